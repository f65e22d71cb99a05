// The universal forward renderer (see universal_pipeline.h). Frame order, with features merged
// in at their events (key 2 x event; the pipeline's steps sit at odd keys between them):
//   MainLightShadow      D32F shadow map (Clear, Store): ShadowCaster pass of the light's casters
//   DepthPrepass         D32F depth (Clear, Store): DepthOnly pass of the visible opaques, or
//   DepthNormalPrepass   + RGB10A2 view normals (Clear, Store) when a feature asks for normals
//   ForwardRendering     RGBA16F colour (Clear, Store) + depth (Load): opaques, skybox,
//                        transparents (split into resumed passes around features inside it)
//   blit CopyColor       RGBA16F temporary copy of the colour
//   blit PostProcessing  tonemap into the RGBA8 sRGB final target
#include "pipelines/universal/universal_pipeline.h"

#include <algorithm>
#include <cmath>

#include "pipelines/kit/pipeline_api.h"
#include "pipelines/universal/screen_space_outline_feature.h"
#include "pipelines/universal/universal_lit_shader.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr int kColorCopyId = 0;
constexpr int kFirstFeatureTemporaryId = 1000;
const glm::vec4 kBlack(0.0f, 0.0f, 0.0f, 1.0f);

// Keys of the pipeline's own steps: a feature at event e (key 2e) runs before the step when
// e <= the step's "Before" event and after it otherwise.
constexpr int kShadowsKey = 2 * RenderPassEvent::BeforeRenderingShadows + 1;
constexpr int kPrepassKey = 2 * RenderPassEvent::BeforeRenderingPrePasses + 1;
constexpr int kOpaquesKey = 2 * RenderPassEvent::BeforeRenderingOpaques + 1;
constexpr int kSkyboxKey = 2 * RenderPassEvent::BeforeRenderingSkybox + 1;
constexpr int kTransparentsKey = 2 * RenderPassEvent::BeforeRenderingTransparents + 1;
// The forward pass ends, and the colour is copied, just before AfterRenderingTransparents.
constexpr int kEndForwardKey = 2 * RenderPassEvent::AfterRenderingTransparents - 1;
constexpr int kPostProcessingKey = 2 * RenderPassEvent::BeforeRenderingPostProcessing + 1;

bool on_off_option(const PipelineOptions& options, const std::string& key, bool fallback) {
  const std::string value = options.take(key, fallback ? "on" : "off");
  if (value == "on") return true;
  if (value == "off") return false;
  throw Error("pipeline option " + key + "='" + value + "': expected on or off");
}

// A number in [lowest, highest]; with `integer`, a whole one.
double number_option(const PipelineOptions& options, const std::string& key, double fallback,
                     double lowest, double highest, bool integer = false) {
  const std::string value = options.take(key, "");
  if (value.empty()) return fallback;
  size_t used = 0;
  double number = 0.0;
  try {
    number = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size() || !(number >= lowest && number <= highest) ||
      (integer && number != std::floor(number))) {
    throw Error("pipeline option " + key + "='" + value + "': expected " + (integer ? "an integer" : "a number") +
                " in [" + std::to_string(lowest) + ", " + std::to_string(highest) + "]");
  }
  return number;
}

// One frame as a render graph: the pipeline's render passes (shadows, prepass, the forward
// parts) are graph passes; the colour copy, the tonemap blit and the renderer features record
// their own passes into the context, as external graph passes declaring what they touch.
class FrameRecorder {
 public:
  FrameRecorder(RenderContext& ctx, const FrameInputs& in, const UniversalSettings& settings)
      : ctx_(ctx), in_(in), settings_(settings), kit_(ctx, in) {}

  FrameOutputs record(const std::vector<std::unique_ptr<RendererFeature>>& features,
                      const std::vector<bool>& enabled) {
    const Scene& scene = kit_.scene();
    const int w = in_.width_px, h = in_.height_px;
    lit_ = make_universal_lit_shader();
    blit_shader_ = make_universal_blit_shader();
    kit_.cull([&](const Material& m) { return make_universal_lit_material(*lit_, m); });

    // Features in run order, merged with the pipeline's steps by key (features even, steps odd).
    std::vector<std::pair<int, int>> work;  // (key, feature index or -1 - step key)
    FeatureInputs inputs;
    for (size_t i : feature_run_order(features)) {
      if (!enabled[i]) continue;
      const FeatureInputs r = features[i]->required_inputs();
      inputs.depth |= r.depth;
      inputs.normals |= r.normals;
      inputs.color_copy |= r.color_copy;
      work.emplace_back(2 * features[i]->event(), static_cast<int>(i));
      // A feature between the first forward draw and the end of the forward pass splits it.
      split_forward_ |= 2 * features[i]->event() > kOpaquesKey && 2 * features[i]->event() < kEndForwardKey;
    }
    for (int key : {kShadowsKey, kPrepassKey, kOpaquesKey, kSkyboxKey, kTransparentsKey, kEndForwardKey,
                    kPostProcessingKey}) {
      work.emplace_back(key, -1 - key);
    }
    std::stable_sort(work.begin(), work.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    normals_prepass_ = inputs.normals;
    prepass_ = settings_.depth_prepass || inputs.depth || inputs.normals;
    copy_color_ = settings_.copy_color || inputs.color_copy;

    // Attachment names as the passes name them; surfaces named as URP names its textures.
    color_ = graph_.create({"color", PixelFormat::RGBA16_FLOAT, w, h, 1, kBlack, "_CameraColorAttachment"});
    depth_ = graph_.create({"depth", PixelFormat::D32_FLOAT, w, h, 1, glm::vec4(1.0f), "_CameraDepthAttachment"});
    // Cleared to a normal facing the camera, (0, 0, 1) encoded as n * 0.5 + 0.5.
    if (normals_prepass_) {
      normals_ = graph_.create({"normals", PixelFormat::RGB10A2_UNORM, w, h, 1, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f),
                                "_CameraNormalsTexture"});
    }
    final_ = graph_.create({"final", PixelFormat::RGBA8_SRGB, w, h});
    data_.inputs = &in_;
    data_.camera = kit_.matrices();
    data_.culling = &kit_.culling();
    data_.width_px = w;
    data_.height_px = h;

    lights_ = universal_lights(scene);
    CommandBuffer globals("universal globals");
    set_light_globals(globals, lights_);
    globals.set_global_float("_AdditionalLightsPerObject", static_cast<float>(settings_.max_lights_per_object - 1));
    ctx_.execute_command_buffer(globals);

    for (const auto& [key, what] : work) {
      if (what >= 0) {
        run_feature(*features[what], what);
      } else {
        run_step(-1 - what);
      }
    }
    graph_.mark_output(final_);
    graph_.execute(ctx_);
    if (data_.camera_color_copy.valid()) ctx_.release_temporary_rt(kColorCopyId);
    return kit_.submit(graph_.surface(final_));
  }

 private:
  // The camera targets as features see them, once the graph has backed them with surfaces.
  void bind_camera_targets() {
    data_.camera_color = RenderTargetRef::of(graph_.surface(color_));
    data_.camera_depth = RenderTargetRef::of(graph_.surface(depth_));
    if (normals_.valid()) data_.camera_normals = RenderTargetRef::of(graph_.surface(normals_));
    data_.final_color = RenderTargetRef::of(graph_.surface(final_));
  }

  // A feature may read and draw onto the camera targets (and read the normals it asked for).
  void run_feature(RendererFeature& feature, int index) {
    if (forward_open_) close_forward();
    GraphPassBuilder pass = graph_.add_external_pass(feature.name(), [this, &feature, index](RenderContext& ctx) {
      bind_camera_targets();
      data_.first_temporary_id = kFirstFeatureTemporaryId + index * kFeatureTemporaryIds;
      feature.record(ctx, data_);
    });
    pass.write_color(color_, LoadAction::Load, StoreAction::Store).write_depth(depth_, LoadAction::Load, StoreAction::Store);
    if (normals_.valid()) pass.read_texture(normals_);
  }

  void run_step(int key) {
    switch (key) {
      case kShadowsKey: return shadows();
      case kPrepassKey: return prepass();
      case kOpaquesKey:
        return forward_step([this](GraphPassRecorder& r) {
          r.draw_renderers(kit_.culling(), {{universal_light_mode::kForward}, SortingCriteria::CommonOpaque},
                           {RenderQueueRange::opaque()});
        });
      case kSkyboxKey:
        return forward_step([this](GraphPassRecorder& r) { r.draw_skybox(kit_.matrices()); });
      case kTransparentsKey:
        return forward_step([this](GraphPassRecorder& r) {
          r.draw_renderers(kit_.culling(), {{universal_light_mode::kForward}, SortingCriteria::CommonTransparent},
                           {RenderQueueRange::transparent()});
        });
      case kEndForwardKey: return end_forward();
      case kPostProcessingKey: return post_processing();
      default: throw Error("universal pipeline: unknown step " + std::to_string(key));
    }
  }

  void shadows() {
    Bounds receivers;
    for (uint32_t i : kit_.culling().visible) receivers.extend(kit_.renderers().renderers[i].world_bounds);
    if (!settings_.main_light_shadows || receivers.empty()) return;
    const MainLightShadowSettings& s = settings_.shadows;
    shadow_setup_ =
        fit_main_light_shadow(lights_.main.to_light, receivers, in_.scene->world_bounds, s.map_size_px);
    shadow_map_ = graph_.create({"shadowmap", PixelFormat::D32_FLOAT, s.map_size_px, s.map_size_px, 1,
                                 glm::vec4(1.0f), "_MainLightShadowmapTexture"});
    shadow_casters_ = ctx_.cull(kit_.renderers().renderers, shadow_setup_.light_camera);
    graph_.add_pass("MainLightShadow")
        .write_depth(shadow_map_, LoadAction::Clear, StoreAction::Store)
        .record([this](GraphPassRecorder& r) {
          const MainLightShadowSettings& s = settings_.shadows;
          r.draw_renderers(shadow_casters_, {{universal_light_mode::kShadowCaster}, SortingCriteria::CommonOpaque},
                           {RenderQueueRange::opaque()});
          SamplerDesc texel_fetch;
          texel_fetch.mag_filter = texel_fetch.min_filter = FilterMode::Nearest;
          texel_fetch.mipmap_mode = MipmapMode::None;
          r.set_global_texture("_MainLightShadowmapTexture", r.texture(shadow_map_, texel_fetch));
          r.set_global_matrix("_MainLightWorldToShadow", glm::mat4(shadow_setup_.world_to_shadow));
          // URP's GetShadowBias: biases in texels times the texel size, scaled by the PCF
          // kernel's radius because the biases only hold for a sample within one texel of the
          // projected point (the 3x3 kernel reaches 1.5 texels).
          const float kernel_radius_texels = 1.5f;
          const float texel = shadow_setup_.texel_size_world * kernel_radius_texels;
          r.set_global_vector("_MainLightShadowParams",
                              glm::vec4(s.depth_bias_texels * texel, s.normal_bias_texels * texel, s.strength, 0.0f));
        });
  }

  void prepass() {
    if (!prepass_) return;
    auto draw = [this](const char* light_mode) {
      return [this, light_mode](GraphPassRecorder& r) {
        r.draw_renderers(kit_.culling(), {{light_mode}, SortingCriteria::CommonOpaque}, {RenderQueueRange::opaque()});
      };
    };
    if (normals_prepass_) {
      graph_.add_pass("DepthNormalPrepass")
          .write_color(normals_, LoadAction::Clear, StoreAction::Store)
          .write_depth(depth_, LoadAction::Clear, StoreAction::Store)
          .record(draw(universal_light_mode::kDepthNormals));
    } else {
      graph_.add_pass("DepthPrepass")
          .write_depth(depth_, LoadAction::Clear, StoreAction::Store)
          .record(draw(universal_light_mode::kDepthOnly));
    }
  }

  // The forward pass: colour cleared by its first part, depth loaded from the prepass (or
  // cleared without one); depth is stored only when a resumed part will load it again.
  void forward_step(std::function<void(GraphPassRecorder&)> step) {
    forward_open_ = true;
    forward_steps_.push_back(std::move(step));
  }

  void close_forward() {
    const bool first = forward_parts_ == 0;
    const LoadAction color_load = first ? LoadAction::Clear : LoadAction::Load;
    const LoadAction depth_load = first && !prepass_ ? LoadAction::Clear : LoadAction::Load;
    const StoreAction depth_store = split_forward_ ? StoreAction::Store : StoreAction::DontCare;
    GraphPassBuilder pass = graph_.add_pass(first ? "ForwardRendering" : "ForwardRendering (resumed)");
    pass.write_color(color_, color_load, StoreAction::Store).write_depth(depth_, depth_load, depth_store);
    if (shadow_map_.valid()) pass.read_texture(shadow_map_);
    pass.record([steps = std::move(forward_steps_)](GraphPassRecorder& r) {
      for (const auto& step : steps) step(r);
    });
    forward_steps_.clear();
    forward_open_ = false;
    ++forward_parts_;
  }

  void end_forward() {
    if (forward_open_) close_forward();
    if (!copy_color_) return;
    copy_material_ = make_copy_material(*blit_shader_, "CopyColor");
    graph_.add_external_pass("CopyColor", [this](RenderContext& ctx) {
      ctx.get_temporary_rt(kColorCopyId, {in_.width_px, in_.height_px, PixelFormat::RGBA16_FLOAT, 1});
      ctx.blit(RenderTargetRef::of(graph_.surface(color_)), RenderTargetRef::temporary(kColorCopyId),
               copy_material_.get(), "Copy");
      data_.camera_color_copy = RenderTargetRef::temporary(kColorCopyId);
      SamplerDesc texel_exact;
      texel_exact.mag_filter = texel_exact.min_filter = FilterMode::Nearest;
      texel_exact.mipmap_mode = MipmapMode::None;
      texel_exact.wrap_u = texel_exact.wrap_v = WrapMode::ClampToEdge;
      ctx.set_global_texture("_CameraColorCopyTexture", {nullptr, data_.camera_color_copy, texel_exact});
    }).read_texture(color_);
  }

  void post_processing() {
    tonemap_material_ = make_tonemap_material(*blit_shader_, settings_.tonemapper, settings_.exposure);
    graph_.add_external_pass("PostProcessing", [this](RenderContext& ctx) {
      ctx.blit(RenderTargetRef::of(graph_.surface(color_)), RenderTargetRef::of(graph_.surface(final_)),
               tonemap_material_.get(), "Tonemap");
    }).read_texture(color_).write_color(final_, LoadAction::DontCare, StoreAction::Store);
  }

  RenderContext& ctx_;
  const FrameInputs& in_;
  const UniversalSettings& settings_;
  UniversalLights lights_;
  std::unique_ptr<Shader> lit_, blit_shader_;
  std::unique_ptr<RenderMaterial> copy_material_, tonemap_material_;
  FrameKit kit_;  // camera, renderers and culling of the frame
  CullingResults shadow_casters_;
  MainLightShadowSetup shadow_setup_;
  RenderingData data_;
  RenderGraph graph_;
  GraphResource color_, depth_, normals_, final_, shadow_map_;
  std::vector<std::function<void(GraphPassRecorder&)>> forward_steps_;
  bool prepass_ = false, normals_prepass_ = false, copy_color_ = false, split_forward_ = false;
  bool forward_open_ = false;
  int forward_parts_ = 0;
};

}  // namespace

UniversalPipeline::UniversalPipeline(UniversalSettings settings) : settings_(settings) {}
UniversalPipeline::~UniversalPipeline() = default;

std::string UniversalPipeline::description() const {
  return "URP-style general forward renderer: main-light shadow map (D32F 2048^2, 3x3 PCF), depth "
         "prepass, forward pass RGBA16F with up to 8 lights per object (Lambert + Blinn-Phong), "
         "skybox, transparents, colour copy, renderer features at events (ScreenSpaceOutline: "
         "DepthNormals + Sobel edges), ACES tonemap to RGBA8 sRGB";
}

RendererFeature& UniversalPipeline::add_feature(std::unique_ptr<RendererFeature> feature) {
  if (!feature) throw Error("universal pipeline: add_feature(nullptr)");
  features_.push_back(std::move(feature));
  return *features_.back();
}

FrameOutputs UniversalPipeline::render(RenderContext& context, const FrameInputs& in) {
  UniversalSettings s = settings_;
  s.main_light_shadows = on_off_option(in.options, "shadows", s.main_light_shadows);
  s.depth_prepass = on_off_option(in.options, "depth_prepass", s.depth_prepass);
  s.copy_color = on_off_option(in.options, "copy_color", s.copy_color);
  s.max_lights_per_object = static_cast<int>(
      number_option(in.options, "max_lights", s.max_lights_per_object, 1, kMaxLightsPerObject, true));
  s.exposure = static_cast<float>(number_option(in.options, "exposure", s.exposure, 1e-6, 1e6));
  const std::string tonemap = in.options.take("tonemap", "");
  if (!tonemap.empty()) s.tonemapper = parse_tonemapper(tonemap);
  std::vector<bool> enabled;
  for (const auto& f : features_) enabled.push_back(f->active());
  const std::string outline = in.options.take("outline", "");
  if (!outline.empty()) {
    const bool on = on_off_option(in.options, "outline", true);
    for (size_t i = 0; i < features_.size(); ++i) {
      if (features_[i]->name() == "ScreenSpaceOutline") enabled[i] = on;
    }
  }
  in.options.reject_unknown(name());
  FrameRecorder recorder(context, in, s);
  return recorder.record(features_, enabled);
}

std::unique_ptr<UniversalPipeline> make_universal_pipeline() {
  auto pipeline = std::make_unique<UniversalPipeline>();
  pipeline->add_feature(std::make_unique<ScreenSpaceOutlineFeature>());
  return pipeline;
}

namespace {
const PipelineRegistration kUniversal("universal", [] { return make_universal_pipeline(); });
}  // namespace

}  // namespace ontile
