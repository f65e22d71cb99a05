// The `lambert` forward pipeline (see lambert_pipeline.h), written against the SRP-style
// context API: cull, then draw_renderers for opaque and transparent queues in one pass.
#include "pipelines/lambert/lambert_pipeline.h"

#include "pipelines/kit/pipeline_api.h"
#include "pipelines/lit/lit_shader.h"

namespace ontile {

LambertFrame render_lambert(RenderContext& context, const FrameInputs& in, const LambertOptions& options) {
  check_lambert_options(options);
  LitShaderOptions lit_options;
  lit_options.depth_compare = options.reversed_z ? CompareOp::GreaterEqual : CompareOp::LessEqual;
  lit_options.filtering = options.filtering;
  lit_options.normal_output = options.normals;
  lit_options.primitive_id_output = options.primitive_id_output;
  const std::unique_ptr<Shader> lit = make_lit_shader(lit_options);
  FrameKit kit(context, in, options.reversed_z);  // after the shader: its materials point to it
  const CullingResults& culling = kit.cull([&](const Material& m) { return make_lit_material(*lit, m); });

  set_lighting_globals(context, main_directional_light(kit.scene()));
  LambertFrame frame;
  frame.color = kit.create_target("color", PixelFormat::RGBA8_SRGB);
  const int samples = options.msaa_samples;
  std::vector<AttachmentDesc> attachments;
  // Multisampled colour lives only in tile memory and is resolved on tile (Vulkan's
  // pResolveAttachments): only the single-sample image reaches external memory.
  AttachmentDesc color = samples == 1 ? Attachment::stored("color", frame.color).clear(lit::kBackgroundColor)
                                      : Attachment::transient("color", PixelFormat::RGBA8_SRGB)
                                            .clear(lit::kBackgroundColor)
                                            .resolve_into(frame.color);
  // The load action under study (Vulkan-Samples render_passes): load reads the whole target,
  // clear and dont_care read nothing.
  color.load = options.color_load;
  attachments.push_back(color);
  // Reversed Z clears to the far value 0 (camera_matrices.h). Stored depth needs a surface.
  const float far_depth = options.reversed_z ? 0.0f : 1.0f;
  attachments.push_back(options.depth_store == StoreAction::Store
                            ? Attachment::stored("depth", kit.create_target("depth", options.depth_format, samples))
                                  .clear_depth(far_depth)
                            : Attachment::transient("depth", options.depth_format).clear_depth(far_depth));
  std::vector<int> opaque_outputs = {0};
  if (options.normals) {
    frame.normals = kit.create_target("normals", normal_storage_format(*options.normals));
    opaque_outputs.push_back(static_cast<int>(attachments.size()));
    attachments.push_back(Attachment::stored("normals", frame.normals).clear(glm::vec4(0.0f)));
  }
  if (options.primitive_id_output) {
    frame.primitive_ids = kit.create_target("primitive ids", PixelFormat::R32_FLOAT);
    opaque_outputs.push_back(static_cast<int>(attachments.size()));
    attachments.push_back(Attachment::stored("primitive ids", frame.primitive_ids).clear(glm::vec4(-1.0f, 0.0f, 0.0f, 1.0f)));
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
  const FrameOutputs out = kit.submit(frame.color);
  frame.report = out.report;
  return frame;
}

FrameOutputs LambertPipeline::render(RenderContext& context, const FrameInputs& in) {
  LambertFrame frame = render_lambert(context, in, read_options(in, name(), parse_lambert_options));
  FrameOutputs out;
  out.report = std::move(frame.report);
  out.color = frame.color;
  return out;
}

namespace {
const PipelineRegistration kLambert("lambert", [] { return std::make_unique<LambertPipeline>(); });
}  // namespace

}  // namespace ontile
