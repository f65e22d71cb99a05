// Renderer features of the `universal` pipeline (URP's ScriptableRendererFeature): user passes
// injected at spaced integer events, what they may ask the pipeline to produce for them, and
// the frame data they are recorded with.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "pipelines/kit/pipeline_api.h"
#include "pipelines/kit/pipeline.h"

namespace ontile {

// URP's RenderPassEvent values: spaced so that a feature can run between two named events
// (e.g. RenderPassEvent::AfterRenderingOpaques + 10). Features run in order of (event,
// insertion order); a feature at an event runs before the pipeline's own work of that event
// when the name says "Before", after it when it says "After".
struct RenderPassEvent {
  enum : int {
    BeforeRendering = 0,
    BeforeRenderingShadows = 50,
    AfterRenderingShadows = 100,
    BeforeRenderingPrePasses = 150,
    AfterRenderingPrePasses = 200,
    BeforeRenderingOpaques = 250,
    AfterRenderingOpaques = 300,
    BeforeRenderingSkybox = 350,
    AfterRenderingSkybox = 400,
    BeforeRenderingTransparents = 450,
    AfterRenderingTransparents = 500,
    BeforeRenderingPostProcessing = 550,
    AfterRenderingPostProcessing = 600,
    AfterRendering = 1000,
  };
};

// Inputs a feature needs the pipeline to render before it (URP's ScriptableRenderPassInput).
struct FeatureInputs {
  bool depth = false;       // the camera depth texture (a depth prepass)
  bool normals = false;     // view-space normals (DepthNormals prepass instead of DepthOnly)
  bool color_copy = false;  // a copy of the camera colour taken after the transparents
};

// What a feature is recorded with. Targets that were not produced this frame are invalid refs.
struct RenderingData {
  const FrameInputs* inputs = nullptr;
  CameraMatrices camera;
  const CullingResults* culling = nullptr;  // the camera's visible renderers
  int width_px = 0, height_px = 0;
  RenderTargetRef camera_color;       // HDR colour (RGBA16F), before post-processing
  RenderTargetRef camera_depth;       // D32F; holds the prepass depth (opaque and alpha-tested
                                      // surfaces) when a prepass ran (FeatureInputs::depth)
  RenderTargetRef camera_normals;     // RGB10A2 view normals (n * 0.5 + 0.5), when requested
  RenderTargetRef camera_color_copy;  // RGBA16F copy after transparents, when produced
  RenderTargetRef final_color;        // RGBA8 sRGB, written by the post-processing pass
  // Temporary render-target ids this feature may use: [first, first + kFeatureTemporaryIds).
  int first_temporary_id = 0;
};

constexpr int kFeatureTemporaryIds = 100;

class RendererFeature {
 public:
  virtual ~RendererFeature() = default;
  virtual std::string name() const = 0;
  virtual int event() const = 0;  // a RenderPassEvent value, or one between two of them
  virtual FeatureInputs required_inputs() const { return {}; }
  // Records the feature's work. It runs with none of the pipeline's render passes open and
  // binds its own targets (set_render_target with Load to draw onto the camera targets, blit,
  // its own passes); a feature at an event inside the forward pass therefore splits that pass
  // in two (colour and depth stored, then loaded again), as a non-merged URP pass does.
  virtual void record(RenderContext& context, const RenderingData& data) = 0;
  // URP's ScriptableRendererFeature.SetActive: an inactive feature records nothing and
  // requests nothing.
  bool active() const { return active_; }
  void set_active(bool active) { active_ = active; }

 private:
  bool active_ = true;
};

// Indices of `features` in run order: by event, then by position in the list (stable).
std::vector<size_t> feature_run_order(const std::vector<std::unique_ptr<RendererFeature>>& features);

}  // namespace ontile
