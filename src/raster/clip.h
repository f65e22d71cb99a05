// Homogeneous clipping (Sutherland-Hodgman in clip space) against the near and far planes, a
// w > 0 plane, and the guard band. Triangles inside the guard band are never clipped in x/y:
// the rasterizer's scissor handles them, as on hardware with a guard band.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/raster_types.h"

namespace ontile {

struct ClipPolygon {
  static constexpr int kMaxVertices = 12;  // 3 + one per clipping plane, with margin
  int count = 0;
  glm::vec4 position[kMaxVertices];
  float varyings[kMaxVertices][kMaxVaryings];
};

enum class ClipOutcome { Inside, Outside, Clipped };

// Guard band in clip-space units for a viewport of the given size: the clip planes
// x <= right * w, x >= -left * w (and the same for y) that keep snapped coordinates within
// +-kGuardBandPx pixels.
struct GuardBand {
  float x_max = 0, x_min = 0, y_max = 0, y_min = 0;  // as multiples of w
  static GuardBand for_viewport(int width_px, int height_px);
};

// Classifies a triangle; when the result is Clipped, `out` holds the clipped convex polygon
// (count >= 3) with interpolated varyings. Positions must be finite (callers drop others).
// Intersections are computed from the inside vertex towards the outside one, so an edge
// shared by two triangles is cut at bit-identical points in both (watertight clipping).
ClipOutcome clip_triangle(const glm::vec4 position[3], const float* const varyings[3],
                          int varying_count, const GuardBand& guard, ClipPolygon& out);

}  // namespace ontile
