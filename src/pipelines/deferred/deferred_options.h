// Parsing of the forward and deferred pipelines' options (see deferred_pipelines.h), with
// errors that name the option and its valid values.
#pragma once
#include "pipelines/kit/pipeline.h"
#include "shaders_cpp/deferred/gbuffer_layout.h"

namespace ontile {

struct DeferredOptions {
  GBufferLayout layout;
  int generated_lights = 0;
  bool tonemap = false;  // auto: on when the light target is HDR (float)
  bool transient = true;         // subpass: G-buffer and depth without memory behind them
  bool store_gbuffer = false;    // subpass: G-buffer and depth stored (needs transient off)
  // subpass: technique=render-passes splits G-buffer and lighting into two render passes that
  // hand the G-buffer over by store and load (Vulkan-Samples' "two render passes").
  bool two_render_passes = false;
  int msaa_samples = 1;
  bool separate_resolve = false;
};

enum class DeferredVariant { Classic, Subpass, Forward };

// Takes every option the variant knows; reject_unknown() is left to the caller.
DeferredOptions parse_deferred_options(const PipelineOptions& options, DeferredVariant variant);

}  // namespace ontile
