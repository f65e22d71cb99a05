// `universal`: a general-purpose forward renderer standing in for a one-size-fits-all pipeline
// (Unity URP's forward renderer): main-light shadow map, depth (or depth-normals) prepass,
// forward lit pass with up to 8 lights per object, skybox, transparents, a colour copy,
// renderer features at spaced events, and a tonemapping post pass into RGBA8 sRGB.
#pragma once
#include <memory>
#include <vector>

#include "pipelines/kit/pipeline.h"
#include "pipelines/universal/main_light_shadows.h"
#include "pipelines/universal/post_processing.h"
#include "pipelines/universal/renderer_feature.h"
#include "pipelines/universal/universal_lights.h"

namespace ontile {

struct UniversalSettings {
  bool main_light_shadows = true;  // option shadows=on|off
  MainLightShadowSettings shadows;
  int max_lights_per_object = kMaxLightsPerObject;  // option max_lights=1..8 (main light included)
  bool depth_prepass = true;  // option depth_prepass=on|off (a feature's depth/normals request forces it)
  bool copy_color = true;     // option copy_color=on|off (a feature's request forces it)
  Tonemapper tonemapper = Tonemapper::AcesFitted;  // option tonemap=aces|reinhard
  float exposure = 1.0f;                           // option exposure=<float > 0>
};

class UniversalPipeline final : public Pipeline {
 public:
  explicit UniversalPipeline(UniversalSettings settings = {});
  ~UniversalPipeline() override;
  std::string name() const override { return "universal"; }
  std::string description() const override;
  // Features run in order of (event, order added). The pipeline owns them.
  RendererFeature& add_feature(std::unique_ptr<RendererFeature> feature);
  const std::vector<std::unique_ptr<RendererFeature>>& features() const { return features_; }
  UniversalSettings& settings() { return settings_; }
  // Options (see UniversalSettings) override the settings for this frame; outline=on|off sets
  // whether the ScreenSpaceOutline feature runs. Unknown options and bad values throw Error.
  FrameOutputs render(RenderContext& context, const FrameInputs& inputs) override;

 private:
  UniversalSettings settings_;
  std::vector<std::unique_ptr<RendererFeature>> features_;
};

// The registered `universal` pipeline: default settings plus the ScreenSpaceOutline feature.
std::unique_ptr<UniversalPipeline> make_universal_pipeline();

}  // namespace ontile
