// Triangle setup: viewport transform, snapping to 16.8 fixed point, face culling after
// snapping, integer edge functions with the top-left fill rule, and the pixel bounding box.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/raster_types.h"

namespace ontile {

// Edge i is the edge opposite vertex i. E_i(px, py) = a*px + b*py + c in subpixel units is
// positive inside, and E_i / area is vertex i's screen-space barycentric coordinate.
struct EdgeFunction {
  int64_t a = 0, b = 0, c = 0;
  // 0 for top and left edges, -1 otherwise: a sample exactly on the edge is inside only for
  // top-left edges (D3D11 functional spec 3.4.2.1). Inside iff E + bias >= 0.
  int64_t bias = 0;
  int64_t at(int64_t px, int64_t py) const { return a * px + b * py + c; }
};

struct TriangleSetup {
  int32_t x_fp[3] = {}, y_fp[3] = {};  // snapped positions, 1/256 px units, y down
  EdgeFunction edge[3];
  int64_t area2 = 0;                   // twice the area in subpixel^2 units, > 0
  double inv_area2 = 0.0;
  float depth[3] = {};                 // z / w, [0, 1] after clipping
  float inv_w[3] = {};                 // 1 / w, for perspective-correct interpolation
  int min_x = 0, min_y = 0, max_x = -1, max_y = -1;  // covered pixel range, inclusive
  bool front_facing = true;
  // Setup may swap vertices 1 and 2 to make the area positive; vertex_order[i] is the input
  // index that ended up in slot i (used to pick the matching varyings).
  uint8_t vertex_order[3] = {0, 1, 2};
};

enum class SetupResult { Ok, Culled, ZeroArea, OutsideViewport };

// Nearest integer, halfway cases away from zero: exactly std::llround(x) for finite |x| < 2^63,
// without the libm call. The cast truncates toward zero and x - trunc(x) is exact in binary
// floating point (Sterbenz's lemma for |x| >= 1, trivially below), so the tie test is exact.
inline int64_t round_half_away_from_zero(double x) {
  const int64_t truncated = static_cast<int64_t>(x);
  const double fraction = x - static_cast<double>(truncated);
  return truncated + int64_t{fraction >= 0.5} - int64_t{fraction <= -0.5};
}

// One vertex after the viewport transform and snapping, as setup consumes it. No member
// initialisers: binning allocates one per shaded vertex and snap_vertex() writes all fields.
struct SnappedVertex {
  int32_t x_fp, y_fp;  // 1/256 px units, y down
  float depth;         // z / w
  float inv_w;         // 1 / w
};

// Viewport transform and snapping of one clip-space vertex (w > 0, inside the guard band) to
// the nearest multiple of 2^-subpixel_bits px. Binning snaps each shaded vertex once per draw
// with this and sets up every triangle that needs no clipping from the shared results.
inline SnappedVertex snap_vertex(const glm::vec4& clip, int width_px, int height_px,
                                 int subpixel_bits) {
  // Snapping grid: 2^subpixel_bits steps per pixel, each `grid_step` units of 1/256 px.
  const double snap_scale = static_cast<double>(int64_t{1} << subpixel_bits);
  const int64_t grid_step = kSubpixelScale >> subpixel_bits;
  // Viewport transform in double so snapping sees the exact rounding of the divide.
  const double inv_w = 1.0 / static_cast<double>(clip.w);
  const double ndc_x = clip.x * inv_w;
  const double ndc_y = clip.y * inv_w;
  const double sx = (ndc_x * 0.5 + 0.5) * width_px;
  const double sy = (0.5 - ndc_y * 0.5) * height_px;  // +Y up in NDC, rows go down
  // Round to the nearest point of the snapping grid (D3D11 3.2.4.1 snapping); scaling by a
  // power of two is exact, so at 8 bits this is llround(sx * 256).
  SnappedVertex v;
  v.x_fp = static_cast<int32_t>(round_half_away_from_zero(sx * snap_scale) * grid_step);
  v.y_fp = static_cast<int32_t>(round_half_away_from_zero(sy * snap_scale) * grid_step);
  v.depth = static_cast<float>(clip.z * inv_w);
  v.inv_w = static_cast<float>(inv_w);
  return v;
}

// clip_positions must have w > 0 and lie inside the guard band (see clip.h). Vertices snap to
// the nearest multiple of 2^-subpixel_bits px (kMinSubpixelBits..kSubpixelBits; D3D11 uses 8,
// Vulkan allows any precision >= 4); x_fp/y_fp stay in 1/256 px units either way, so coverage,
// the fill rule and sample positions are evaluated exactly at every precision.
SetupResult setup_triangle(const glm::vec4 clip_positions[3], int viewport_width_px,
                           int viewport_height_px, CullMode cull, FrontFace front_face,
                           TriangleSetup& out, int subpixel_bits = kSubpixelBits);
// The same from vertices snap_vertex() already transformed and snapped.
SetupResult setup_snapped_triangle(const SnappedVertex vertex[3], int viewport_width_px,
                                   int viewport_height_px, CullMode cull, FrontFace front_face,
                                   TriangleSetup& out);

}  // namespace ontile
