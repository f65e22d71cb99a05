// AOV pass (arbitrary output variables) of the rasterizer: one render pass through the context
// API that writes depth, primitive id and/or world normal of the opaque-queue geometry into
// RGBA32F targets, with the lambert pipeline's materials deciding culling and alpha test.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pipelines/kit/render_frame.h"

namespace ontile {

enum class AovKind {
  Depth,        // R = QuadFragment::depth (the value the depth test uses), clear 1
  PrimitiveId,  // R = QuadFragment::primitive_id as float (exact below 2^24), clear -1
  Normal,       // RGB = unit interpolated shading normal, flipped on back faces, clear 0
};

// "depth", "primitive_id", "normal".
const char* aov_name(AovKind kind);
std::optional<AovKind> parse_aov_kind(std::string_view name);
// EXR channels of an AOV: {"Z"}, {"primid"}, {"N.x", "N.y", "N.z"} (the reference's names).
std::vector<std::string> aov_channel_names(AovKind kind);
// The AOV's channels of every pixel, interleaved, rows top first (for write_exr_channels). A
// multisampled surface gives each pixel's sample 0: Vulkan's VK_RESOLVE_MODE_SAMPLE_ZERO_BIT,
// the one depth resolve every implementation supports; averaging ids or depths across an edge
// would give values no triangle has.
std::vector<float> aov_channels(const Surface& surface, AovKind kind);

// Records and submits one pass "aov" of width x height with `samples` samples per pixel: one
// RGBA32F target per kind (in order, storing every sample) and a transient D32F depth, drawing
// the opaque render queue with the Lit materials (culling and alpha test as lambert draws them).
// Returns the targets, owned by the context; `report` (optional) receives the traffic report.
std::vector<Surface*> render_aov_pass(RenderContext& context, const FrameInputs& inputs,
                                      const std::vector<AovKind>& kinds, FrameReport* report = nullptr,
                                      int samples = 1);

struct AovFrame {
  std::unique_ptr<RenderContext> context;  // owns the surfaces
  std::vector<Surface*> surfaces;          // one per requested kind, in order
  FrameReport report;
  Camera camera;
};

// render_frame's counterpart for AOVs: same camera selection, size checks and context set-up.
// The geometry is the lambert pipeline's; settings.pipeline must be "lambert" and the only
// option accepted is lambert's msaa=1|2|4|8 (the AOVs then hold sample 0 of each pixel, see
// aov_channels); anything else is an Error.
AovFrame render_aov_frame(const Scene& scene, const RenderSettings& settings,
                          const std::vector<AovKind>& kinds);

}  // namespace ontile
