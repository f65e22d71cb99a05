// Scene to renderers (see scene_renderers.h).
#include "context/scene_renderers.h"

namespace ontile {

SceneRenderers make_scene_renderers(
    const Scene& scene,
    const std::function<std::unique_ptr<RenderMaterial>(const Material&)>& make_material) {
  SceneRenderers out;
  for (const Material& m : scene.materials) out.materials.push_back(make_material(m));
  static const Material kDefault;
  out.materials.push_back(make_material(kDefault));
  const RenderMaterial* default_material = out.materials.back().get();

  uint32_t primitive_id = 0;
  for (const MeshInstance& instance : scene.instances) {
    for (const MeshPrimitive& prim : scene.meshes[instance.mesh].primitives) {
      Renderer r;
      r.mesh = &prim;
      r.world = instance.world;
      // World bounds of this primitive: its object bounds' corners transformed. Bounds are
      // float and computed with the float-rounded matrix as before (the universal pipeline's
      // shadow fit reads them, so their bits are part of its images); culling allows for
      // their rounding (culling.cpp).
      const glm::mat4 world_float(instance.world);
      for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? prim.bounds.max.x : prim.bounds.min.x,
                          (corner & 2) ? prim.bounds.max.y : prim.bounds.min.y,
                          (corner & 4) ? prim.bounds.max.z : prim.bounds.min.z);
        if (!prim.bounds.empty()) r.world_bounds.extend(glm::vec3(world_float * glm::vec4(p, 1.0f)));
      }
      r.material = prim.material >= 0 ? out.materials[prim.material].get() : default_material;
      r.primitive_id_base = primitive_id;
      primitive_id += prim.triangle_count();
      out.renderers.push_back(r);
    }
  }
  return out;
}

}  // namespace ontile
