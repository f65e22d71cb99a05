// `lambert`: the baseline forward pipeline: one render pass, colour (RGBA8 sRGB) and depth
// (D32F), opaque and alpha-tested materials first, blended ones back to front, Lambert shading.
#pragma once
#include "pipelines/pipeline.h"

namespace ontile {

class LambertPipeline final : public Pipeline {
 public:
  std::string name() const override { return "lambert"; }
  std::string description() const override {
    return "forward Lambert shading, one pass: colour RGBA8 sRGB + depth D32F (transient), "
           "culled and sorted by draw_renderers";
  }
  FrameOutputs render(RenderContext& context, const FrameInputs& inputs) override;
};

}  // namespace ontile
