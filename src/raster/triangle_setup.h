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

// clip_positions must have w > 0 and lie inside the guard band (see clip.h). Vertices snap to
// the nearest multiple of 2^-subpixel_bits px (kMinSubpixelBits..kSubpixelBits; D3D11 uses 8,
// Vulkan allows any precision >= 4); x_fp/y_fp stay in 1/256 px units either way, so coverage,
// the fill rule and sample positions are evaluated exactly at every precision.
SetupResult setup_triangle(const glm::vec4 clip_positions[3], int viewport_width_px,
                           int viewport_height_px, CullMode cull, FrontFace front_face,
                           TriangleSetup& out, int subpixel_bits = kSubpixelBits);

}  // namespace ontile
