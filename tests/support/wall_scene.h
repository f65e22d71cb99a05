// A rough metal-and-plastic wall filling the whole view of its camera, so every pixel holds
// geometry: per-pixel traffic formulas hold exactly on it.
#pragma once
#include "scene/scene.h"

namespace ontile::test {

inline Scene wall_scene() {
  Scene scene;
  MeshPrimitive quad;
  quad.positions = {{-100, -100, -5}, {100, -100, -5}, {100, 100, -5}, {-100, 100, -5}};
  quad.normals.assign(4, glm::vec3(0, 0, 1));
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.material = 0;
  for (const glm::vec3& p : quad.positions) quad.bounds.extend(p);
  scene.meshes.push_back({"wall", {quad}});
  Material m;
  m.base_color_factor = glm::vec4(0.7f, 0.6f, 0.5f, 1.0f);
  m.metallic_factor = 0.3f;
  m.roughness_factor = 0.4f;
  scene.materials.push_back(m);
  MeshInstance instance;
  instance.mesh = 0;
  instance.world_bounds = quad.bounds;
  scene.instances.push_back(instance);
  scene.world_bounds = quad.bounds;
  Camera camera;
  camera.znear = 0.1f;
  camera.zfar = 50.0f;
  scene.cameras.push_back(camera);
  return scene;
}

}  // namespace ontile::test
