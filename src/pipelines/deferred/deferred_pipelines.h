// The deferred pipelines and their forward baseline (docs/deferred.md):
//  deferred-classic  a G-buffer render pass storing every target and depth, then a lighting
//                    pass that samples them as textures and stores the light target;
//  deferred-subpass  one render pass: G-buffer subpass, lighting subpass reading input
//                    attachments, G-buffer and depth transient; an optional tonemap subpass
//                    keeps the HDR light accumulation on tile too;
//  forward           Forward+ shading with the same lights and BRDF, optionally with MSAA
//                    resolved on tile or by a separate resolve pass.
// Options (--set, and --gbuffer/--lights on the CLI): gbuffer=unity|vulkan-samples|
// vulkan-samples-large|bjorge, lights=N (generated point lights), tonemap=auto|on|off; subpass only:
// transient=on|off, gbuffer_store=dont-care|store (store needs transient=off), technique=subpasses|
// render-passes (Vulkan-Samples' two render passes: the G-buffer stored, then loaded as input
// attachments); forward only: msaa=1|2|4|8, resolve=on-tile|separate.
#pragma once
#include "pipelines/kit/pipeline.h"

namespace ontile {

class DeferredPipeline final : public Pipeline {
 public:
  explicit DeferredPipeline(bool subpasses) : subpasses_(subpasses) {}
  std::string name() const override { return subpasses_ ? "deferred-subpass" : "deferred-classic"; }
  std::string description() const override {
    return subpasses_ ? "deferred in one render pass: G-buffer and lighting subpasses, G-buffer on tile"
                      : "deferred in two render passes: G-buffer stored, lighting samples it as textures";
  }
  FrameOutputs render(RenderContext& context, const FrameInputs& inputs) override;

 private:
  bool subpasses_;
};

class ForwardPipeline final : public Pipeline {
 public:
  std::string name() const override { return "forward"; }
  std::string description() const override {
    return "Forward+ PBR shading with the deferred pipelines' lights (baseline; MSAA option)";
  }
  FrameOutputs render(RenderContext& context, const FrameInputs& inputs) override;
};

}  // namespace ontile
