// The `lambert` forward pipeline (see lambert_pipeline.h), written against the SRP-style
// context API: cull, then draw_renderers for opaque and transparent queues in one pass.
#include "pipelines/lambert_pipeline.h"

#include "context/scene_renderers.h"

namespace ontile {

LambertFrame render_lambert(RenderContext& context, const FrameInputs& in, const LambertOptions& options) {
  check_lambert_options(options);
  const Scene& scene = *in.scene;
  const CameraMatrices camera =
      camera_matrices(in.camera, double(in.width_px) / in.height_px, options.reversed_z);
  LitShaderOptions lit_options;
  lit_options.depth_compare = options.reversed_z ? CompareOp::GreaterEqual : CompareOp::LessEqual;
  lit_options.filtering = options.filtering;
  lit_options.normal_output = options.normals;
  lit_options.primitive_id_output = options.primitive_id_output;
  const std::unique_ptr<Shader> lit = make_lit_shader(lit_options);
  const SceneRenderers scene_renderers = make_scene_renderers(
      scene, [&](const Material& m) { return make_lit_material(*lit, m); });
  const CullingResults culling = context.cull(scene_renderers.renderers, camera);

  set_lighting_globals(context, main_directional_light(scene));
  LambertFrame frame;
  frame.color = context.create_surface("color", PixelFormat::RGBA8_SRGB, in.width_px, in.height_px);
  const int samples = options.msaa_samples;
  std::vector<AttachmentDesc> attachments;
  const glm::vec4 clear_color = lit::kBackgroundColor;
  if (samples == 1) {
    attachments.push_back({"color", PixelFormat::RGBA8_SRGB, LoadAction::Clear, StoreAction::Store,
                           clear_color, frame.color, nullptr});
  } else {
    // Multisampled colour lives only in tile memory and is resolved on tile (Vulkan's
    // pResolveAttachments): only the single-sample image reaches external memory.
    attachments.push_back({"color", PixelFormat::RGBA8_SRGB, LoadAction::Clear, StoreAction::Resolve,
                           clear_color, nullptr, frame.color});
  }
  // Reversed Z clears to the far value 0 (camera_matrices.h).
  attachments.push_back({"depth", options.depth_format, LoadAction::Clear, StoreAction::DontCare,
                         glm::vec4(options.reversed_z ? 0.0f : 1.0f), nullptr, nullptr});
  std::vector<int> opaque_outputs = {0};
  if (options.normals) {
    const PixelFormat format = normal_storage_format(*options.normals);
    frame.normals = context.create_surface("normals", format, in.width_px, in.height_px);
    opaque_outputs.push_back(static_cast<int>(attachments.size()));
    attachments.push_back({"normals", format, LoadAction::Clear, StoreAction::Store, glm::vec4(0.0f),
                           frame.normals, nullptr});
  }
  if (options.primitive_id_output) {
    frame.primitive_ids = context.create_surface("primitive ids", PixelFormat::R32_FLOAT, in.width_px, in.height_px);
    opaque_outputs.push_back(static_cast<int>(attachments.size()));
    attachments.push_back({"primitive ids", PixelFormat::R32_FLOAT, LoadAction::Clear, StoreAction::Store,
                           glm::vec4(-1.0f, 0.0f, 0.0f, 1.0f), frame.primitive_ids, nullptr});
  }
  context.begin_render_pass("forward", in.width_px, in.height_px, samples, attachments, 1);
  context.begin_subpass(opaque_outputs);
  context.draw_renderers(culling, {{lit::kForwardLit}, SortingCriteria::CommonOpaque},
                         {RenderQueueRange::opaque()});
  if (opaque_outputs.size() > 1) {
    // Blended surfaces write no depth, so they own no normal or id: a second subpass that
    // writes only the colour keeps blending away from the extra targets.
    context.end_subpass();
    context.begin_subpass({0});
  }
  context.draw_renderers(culling, {{lit::kForwardLit}, SortingCriteria::CommonTransparent},
                         {RenderQueueRange::transparent()});
  context.end_subpass();
  context.end_render_pass();
  frame.report = context.submit();
  return frame;
}

FrameOutputs LambertPipeline::render(RenderContext& context, const FrameInputs& in) {
  const LambertOptions options = parse_lambert_options(in.options);
  in.options.reject_unknown(name());
  LambertFrame frame = render_lambert(context, in, options);
  FrameOutputs out;
  out.report = std::move(frame.report);
  out.color = frame.color;
  return out;
}

}  // namespace ontile
