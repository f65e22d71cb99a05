// Test scenes for the reference renderer: an axis-aligned textured quad under an orthographic
// camera whose edges lie a quarter pixel from every pixel centre (no fill-rule ties), and a
// tilted triangle under a perspective camera.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.h"

namespace ontile::test {

// 64x64 target, ymag = 1: world x = pixel x / 32 - 1, world y = 1 - pixel y / 32.
constexpr int kQuadTargetPx = 64;

inline glm::vec3 quad_corner(double x_px, double y_px) {
  return {static_cast<float>(x_px / 32.0 - 1.0), static_cast<float>(1.0 - y_px / 32.0), 0.0f};
}

inline void finish_scene(Scene& scene, MeshPrimitive prim, Material material) {
  for (const glm::vec3& p : prim.positions) prim.bounds.extend(p);
  scene.source_path = "test scene";
  scene.materials.push_back(std::move(material));
  prim.material = 0;
  MeshInstance instance;
  instance.mesh = 0;
  instance.world_bounds = prim.bounds;
  scene.world_bounds = prim.bounds;
  Mesh mesh;
  mesh.primitives.push_back(std::move(prim));
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back(instance);
}

// Quad from pixel (8.25, 8.25) to (40.25, 24.25); its diagonal has slope 1/2 and passes a
// quarter pixel from pixel centres too. Varying normals and a bilinear-magnified texture make
// every pixel's colour different.
inline Scene textured_quad_scene() {
  MeshPrimitive prim;
  prim.positions = {quad_corner(8.25, 8.25), quad_corner(40.25, 8.25), quad_corner(40.25, 24.25),
                    quad_corner(8.25, 24.25)};
  prim.normals = {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(0.5f, 0, 1)),
                  glm::normalize(glm::vec3(0, 0.5f, 1)), glm::normalize(glm::vec3(-0.3f, -0.3f, 1))};
  prim.uv0 = {{0.0f, 0.0f}, {1.5f, 0.0f}, {1.5f, 0.5f}, {0.0f, 0.5f}};
  prim.indices = {0, 3, 2, 0, 2, 1};  // counter-clockwise with +Y up: front faces
  std::vector<uint8_t> texels(16 * 16 * 4);
  for (int i = 0; i < 16 * 16; ++i) {
    texels[4 * i + 0] = static_cast<uint8_t>((i * 37) % 256);
    texels[4 * i + 1] = static_cast<uint8_t>((i * 91 + 40) % 256);
    texels[4 * i + 2] = static_cast<uint8_t>((i * 13 + 200) % 256);
    texels[4 * i + 3] = 255;
  }
  Material material;
  material.base_color_factor = {0.9f, 0.8f, 0.7f, 1.0f};
  material.base_color_texture.texture = Texture2D::from_rgba8(16, 16, texels, true, "test texels");
  Scene scene;
  finish_scene(scene, std::move(prim), std::move(material));
  Camera camera;
  camera.type = Camera::Type::Orthographic;
  camera.xmag = camera.ymag = 1.0f;
  camera.znear = 0.1f;
  camera.zfar = 10.0f;
  camera.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 5.0f));
  scene.cameras.push_back(camera);
  return scene;
}

// One triangle tilted away from a perspective camera, untextured, smooth normals.
inline Scene tilted_triangle_scene() {
  MeshPrimitive prim;
  prim.positions = {{-1.3f, -0.8f, 0.4f}, {1.1f, -0.6f, -0.9f}, {0.2f, 1.0f, -2.5f}};
  prim.normals = {glm::normalize(glm::vec3(0.2f, 0.1f, 1.0f)), glm::normalize(glm::vec3(-0.4f, 0.3f, 1.0f)),
                  glm::normalize(glm::vec3(0.1f, -0.5f, 1.0f))};
  prim.uv0 = {{0, 0}, {1, 0}, {0, 1}};
  prim.indices = {0, 1, 2};
  Material material;
  material.base_color_factor = {0.6f, 0.9f, 0.4f, 1.0f};
  material.double_sided = true;
  Scene scene;
  finish_scene(scene, std::move(prim), std::move(material));
  Camera camera;
  camera.yfov_rad = 0.9f;
  camera.znear = 0.2f;
  camera.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 0.05f, 3.0f));
  scene.cameras.push_back(camera);
  return scene;
}

}  // namespace ontile::test
