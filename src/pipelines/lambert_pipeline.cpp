// The `lambert` forward pipeline (see lambert_pipeline.h).
#include "pipelines/lambert_pipeline.h"

#include <algorithm>
#include <memory>

#include "context/camera_matrices.h"
#include "shaders_cpp/lambert_shader.h"
#include "shaders_cpp/mesh_vertex_shader.h"

namespace ontile {

FrameOutputs LambertPipeline::render(RenderContext& context, const FrameInputs& in) {
  const Scene& scene = *in.scene;
  const CameraMatrices cam = camera_matrices(in.camera, double(in.width_px) / in.height_px);
  const DirectionalLighting lighting = main_directional_light(scene);
  static const Material kDefaultMaterial;

  struct Item {
    DrawCall draw;
    bool blended = false;
    double view_depth = 0.0;  // for back-to-front sorting of blended draws
  };
  std::vector<std::unique_ptr<VertexShader>> vertex_shaders;
  std::vector<std::unique_ptr<FragmentShader>> fragment_shaders;
  std::vector<Item> items;
  uint32_t primitive_id_base = 0;
  for (const MeshInstance& instance : scene.instances) {
    for (const MeshPrimitive& prim : scene.meshes[instance.mesh].primitives) {
      const Material& material = prim.material >= 0 ? scene.materials[prim.material] : kDefaultMaterial;
      auto vs = std::make_unique<MeshVertexShader>(prim, glm::dmat4(instance.world), cam.view_projection);
      auto fs = std::make_unique<LambertShader>(material, lighting);
      Item item;
      item.draw.vertex_shader = vs.get();
      item.draw.fragment_shader = fs.get();
      item.draw.vertex_count = static_cast<uint32_t>(prim.positions.size());
      item.draw.indices = prim.indices.data();
      item.draw.index_count = static_cast<uint32_t>(prim.indices.size());
      item.draw.raster.cull = material.double_sided ? CullMode::None : CullMode::Back;
      item.draw.primitive_id_base = primitive_id_base;
      item.draw.input_vertex_bytes = vs->input_vertex_bytes();
      item.blended = material.alpha_mode == AlphaMode::Blend;
      if (item.blended) {
        item.draw.blend.mode = BlendMode::Alpha;
        item.draw.raster.depth_write = false;
        const glm::dvec4 c = cam.view * glm::dvec4(glm::dvec3(instance.world_bounds.center()), 1.0);
        item.view_depth = -c.z;
      }
      primitive_id_base += prim.triangle_count();
      vertex_shaders.push_back(std::move(vs));
      fragment_shaders.push_back(std::move(fs));
      items.push_back(item);
    }
  }
  // Opaque in scene order, then blended back to front (stable, so ties keep scene order).
  std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
    if (a.blended != b.blended) return !a.blended;
    return a.blended && a.view_depth > b.view_depth;
  });

  Surface* color = context.create_surface("color", PixelFormat::RGBA8_SRGB, in.width_px, in.height_px);
  std::vector<AttachmentDesc> attachments(2);
  attachments[0] = {"color", PixelFormat::RGBA8_SRGB, LoadAction::Clear, StoreAction::Store,
                    glm::vec4(0.05f, 0.05f, 0.08f, 1.0f), color, nullptr};
  attachments[1] = {"depth", PixelFormat::D32_FLOAT, LoadAction::Clear, StoreAction::DontCare,
                    glm::vec4(1.0f), nullptr, nullptr};
  context.begin_render_pass("forward", in.width_px, in.height_px, 1, attachments, 1);
  context.begin_subpass({0});
  for (const Item& item : items) context.draw(item.draw);
  context.end_subpass();
  context.end_render_pass();

  FrameOutputs out;
  out.report = context.submit();
  out.color = color;
  return out;
}

}  // namespace ontile
