// The `lambert` forward pipeline (see lambert_pipeline.h), written against the SRP-style
// context API: cull, then draw_renderers for opaque and transparent queues in one pass.
#include "pipelines/lambert_pipeline.h"

#include "context/scene_renderers.h"
#include "pipelines/lit_shader.h"

namespace ontile {

FrameOutputs LambertPipeline::render(RenderContext& context, const FrameInputs& in) {
  in.options.reject_unknown(name());
  const Scene& scene = *in.scene;
  const CameraMatrices camera = camera_matrices(in.camera, double(in.width_px) / in.height_px);
  const std::unique_ptr<Shader> lit = make_lit_shader();
  const SceneRenderers scene_renderers = make_scene_renderers(
      scene, [&](const Material& m) { return make_lit_material(*lit, m); });
  const CullingResults culling = context.cull(scene_renderers.renderers, camera);

  set_lighting_globals(context, main_directional_light(scene));
  Surface* color = context.create_surface("color", PixelFormat::RGBA8_SRGB, in.width_px, in.height_px);
  std::vector<AttachmentDesc> attachments(2);
  attachments[0] = {"color", PixelFormat::RGBA8_SRGB, LoadAction::Clear, StoreAction::Store,
                    glm::vec4(0.05f, 0.05f, 0.08f, 1.0f), color, nullptr};
  attachments[1] = {"depth", PixelFormat::D32_FLOAT, LoadAction::Clear, StoreAction::DontCare,
                    glm::vec4(1.0f), nullptr, nullptr};
  context.begin_render_pass("forward", in.width_px, in.height_px, 1, attachments, 1);
  context.begin_subpass({0});
  context.draw_renderers(culling, {{lit::kForwardLit}, SortingCriteria::CommonOpaque},
                         {RenderQueueRange::opaque()});
  context.draw_renderers(culling, {{lit::kForwardLit}, SortingCriteria::CommonTransparent},
                         {RenderQueueRange::transparent()});
  context.end_subpass();
  context.end_render_pass();

  FrameOutputs out;
  out.report = context.submit();
  out.color = color;
  return out;
}

}  // namespace ontile
