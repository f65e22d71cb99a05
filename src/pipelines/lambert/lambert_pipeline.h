// `lambert`: the baseline forward pipeline: one render pass, colour (RGBA8 sRGB) and depth
// (D32F by default), opaque and alpha-tested materials first, blended ones back to front,
// Lambert shading. Options (lambert_options.h) add MSAA, D16/D24 depth, reversed Z, a stored
// normal buffer and forced texture filtering.
#pragma once
#include "pipelines/lambert/lambert_options.h"
#include "pipelines/kit/pipeline.h"

namespace ontile {

// What one lambert frame produced; surfaces are owned by the context.
struct LambertFrame {
  Surface* color = nullptr;          // RGBA8 sRGB (resolved when MSAA)
  Surface* normals = nullptr;        // options.normals' format, when requested
  Surface* primitive_ids = nullptr;  // R32F, -1 where nothing opaque, when requested
  FrameReport report;
};

// Records and submits the frame. Throws ontile::Error for invalid options (check_lambert_options).
LambertFrame render_lambert(RenderContext& context, const FrameInputs& inputs, const LambertOptions& options);

class LambertPipeline final : public Pipeline {
 public:
  std::string name() const override { return "lambert"; }
  std::string description() const override {
    return "forward Lambert shading, one pass: colour RGBA8 sRGB + depth D32F (transient), "
           "culled and sorted by draw_renderers; --set msaa, depth, reversed_z, normals, filter";
  }
  FrameOutputs render(RenderContext& context, const FrameInputs& inputs) override;
};

}  // namespace ontile
