// The AOV pass (see aov_pass.h): an "AOV" shader whose pass reuses the Lit ForwardLit factory
// for the vertex functor and for discards (alpha test), and replaces the colour by the AOVs.
#include "aov/aov_pass.h"

#include "pipelines/kit/pipeline_api.h"
#include "pipelines/lambert/lambert_options.h"
#include "pipelines/lit/lit_shader.h"
#include "shaders_cpp/batch_helpers.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr const char* kAovLightMode = "AOV";

glm::vec4 aov_clear_value(AovKind kind) {
  switch (kind) {
    case AovKind::Depth: return glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    case AovKind::PrimitiveId: return glm::vec4(-1.0f, 0.0f, 0.0f, 0.0f);
    case AovKind::Normal: return glm::vec4(0.0f);
  }
  return glm::vec4(0.0f);
}

// Writes the AOVs of each fragment the material's own functor keeps: the wrapped functor runs
// only when it may discard, so its discards (alpha test) remove the same fragments as in lambert.
class AovShader final : public FragmentShader {
 public:
  AovShader(std::unique_ptr<FragmentShader> material_shader, std::vector<AovKind> kinds)
      : material_(std::move(material_shader)), kinds_(std::move(kinds)) {}
  bool may_discard() const override { return material_ && material_->may_discard(); }
  // Outputs per quad (primitive ids per quad); the material's functor, which reads texels,
  // runs only when it may discard, so then it must allow batches across triangles too.
  bool batches_across_triangles() const override {
    return !may_discard() || material_->batches_across_triangles();
  }

  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    if (may_discard()) {
      // The material's colours go to a scratch output; only its discards are kept.
      BatchOutput material_out;
      material_out.discard_mask = 0;
      material_->shade_batch(batch, material_out);
      out.discard_mask = material_out.discard_mask;
    }
    const int count = batch.fragment_count();
    for (size_t k = 0; k < kinds_.size(); ++k) {
      const int target = static_cast<int>(k);
      switch (kinds_[k]) {
        case AovKind::Depth:
          for (int f = 0; f < count; ++f) out.set(target, f, glm::vec4(batch.depth[f], 0.0f, 0.0f, 1.0f));
          break;
        case AovKind::PrimitiveId:
          // Channel by channel, so the loops stay simple stores (the id is per quad).
          for (int q = 0; q < batch.quad_count; ++q) {
            const float id = static_cast<float>(batch.quad_primitive_id[q]);
            for (int lane = 0; lane < kQuadLanes; ++lane) out.color[target][0][q * kQuadLanes + lane] = id;
          }
          for (int c = 1; c < 4; ++c) {
            const float value = c == 3 ? 1.0f : 0.0f;
            for (int f = 0; f < count; ++f) out.color[target][c][f] = value;
          }
          break;
        case AovKind::Normal: {
          // As the Lambert functor shades: normalised, flipped on back faces.
          alignas(64) BatchVec3 normal;
          batch_unit_normals(batch, MeshVertexShader::kNormal, count, normal);
          for (int f = 0; f < count; ++f) out.set(target, f, glm::vec4(batch_get3(normal, f), 1.0f));
          break;
        }
      }
    }
  }

 private:
  std::unique_ptr<FragmentShader> material_;
  std::vector<AovKind> kinds_;
};

}  // namespace

const char* aov_name(AovKind kind) {
  switch (kind) {
    case AovKind::Depth: return "depth";
    case AovKind::PrimitiveId: return "primitive_id";
    case AovKind::Normal: return "normal";
  }
  return "?";
}

std::optional<AovKind> parse_aov_kind(std::string_view name) {
  for (AovKind k : {AovKind::Depth, AovKind::PrimitiveId, AovKind::Normal}) {
    if (name == aov_name(k)) return k;
  }
  return std::nullopt;
}

std::vector<std::string> aov_channel_names(AovKind kind) {
  switch (kind) {
    case AovKind::Depth: return {"Z"};
    case AovKind::PrimitiveId: return {"primid"};
    case AovKind::Normal: return {"N.x", "N.y", "N.z"};
  }
  return {};
}

std::vector<float> aov_channels(const Surface& surface, AovKind kind) {
  const size_t channels = aov_channel_names(kind).size();
  std::vector<float> out;
  out.reserve(size_t(surface.width()) * surface.height() * channels);
  for (int y = 0; y < surface.height(); ++y) {
    for (int x = 0; x < surface.width(); ++x) {
      const glm::vec4 v = surface.read(x, y);
      for (size_t c = 0; c < channels; ++c) out.push_back(v[static_cast<int>(c)]);
    }
  }
  return out;
}

std::vector<Surface*> render_aov_pass(RenderContext& context, const FrameInputs& in,
                                      const std::vector<AovKind>& kinds, FrameReport* report, int samples) {
  if (kinds.empty() || kinds.size() > static_cast<size_t>(kMaxColorTargets)) {
    throw Error("AOV pass: " + std::to_string(kinds.size()) + " AOVs requested (1.." +
                std::to_string(kMaxColorTargets) + ")");
  }
  const std::unique_ptr<Shader> lit = make_lit_shader();
  const ShaderPass* forward = lit->find_light_mode(lit::kForwardLit);
  Shader aov_shader("AOV");
  aov_shader.add_pass({"AOV", kAovLightMode, forward->state,
                       [factory = forward->factory, kinds](const DrawContext& ctx) {
                         DrawFunctors f = factory(ctx);
                         f.fragment = std::make_unique<AovShader>(std::move(f.fragment), kinds);
                         return f;
                       }});
  // Lit materials (keywords, queue, cull, alpha cutoff) bound to the AOV shader.
  FrameKit kit(context, in);
  const CullingResults& culling = kit.cull([&](const Material& m) { return make_lit_material(aov_shader, m); });

  std::vector<Surface*> surfaces;
  std::vector<AttachmentDesc> attachments;
  std::vector<int> outputs;
  for (AovKind kind : kinds) {
    Surface* s = kit.create_target(std::string("aov ") + aov_name(kind), PixelFormat::RGBA32_FLOAT, samples);
    surfaces.push_back(s);
    outputs.push_back(static_cast<int>(attachments.size()));
    attachments.push_back(Attachment::stored(aov_name(kind), s).clear(aov_clear_value(kind)));
  }
  attachments.push_back(Attachment::transient("depth", PixelFormat::D32_FLOAT).clear_depth(1.0f));
  context.begin_render_pass("aov", in.width_px, in.height_px, samples, attachments,
                            static_cast<int>(attachments.size()) - 1);
  context.begin_subpass(outputs);
  // Only the opaque queue: blended surfaces write no depth in lambert, so they own no pixel.
  context.draw_renderers(culling, {{kAovLightMode}, SortingCriteria::CommonOpaque},
                         {RenderQueueRange::opaque()});
  context.end_subpass();
  context.end_render_pass();
  FrameOutputs submitted = kit.submit(surfaces.front());
  if (report) *report = std::move(submitted.report);
  return surfaces;
}

AovFrame render_aov_frame(const Scene& scene, const RenderSettings& settings,
                          const std::vector<AovKind>& kinds) {
  if (settings.pipeline != "lambert") {
    throw Error("--aov: AOVs are rendered with the lambert pipeline's geometry and materials; "
                "pipeline '" + settings.pipeline + "' is not supported");
  }
  const LambertOptions lambert = parse_lambert_options(settings.options);
  settings.options.reject_unknown("lambert");
  if (lambert.depth_format != LambertOptions{}.depth_format || lambert.reversed_z || lambert.normals ||
      lambert.filtering != LambertOptions{}.filtering) {
    throw Error("--aov: of lambert's options only msaa applies to AOVs (they are D32F depth, float normals)");
  }
  const FrameInputs inputs = frame_inputs(scene, settings);
  AovFrame frame;
  frame.camera = inputs.camera;
  frame.context = std::make_unique<RenderContext>(settings.context);
  frame.surfaces = render_aov_pass(*frame.context, inputs, kinds, &frame.report, lambert.msaa_samples);
  return frame;
}

}  // namespace ontile
