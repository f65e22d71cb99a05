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

// Planes, with their distances d(v) >= 0 inside: near z, far w - z, w - kClipMinW, the guard
// band g.x_max * w - x, x - g.x_min * w, y - g.y_min * w, g.y_max * w - y, and the viewport
// w - x, x + w, y + w, w - y (+Y is up in clip space).
namespace clip_plane {
enum : int {
  kNear, kFar, kPositiveW, kGuardRight, kGuardLeft, kGuardBottom, kGuardTop,
  kViewRight, kViewLeft, kViewBottom, kViewTop, kPlaneCount
};
}  // namespace clip_plane
// w must stay positive so that the perspective divide is defined; any tiny positive w left is
// then pushed outside by the guard-band planes.
constexpr float kClipMinW = 1e-20f;
// Planes 0..6 clip; the viewport planes only serve trivial rejection.
constexpr unsigned kClippingPlaneMask = (1u << clip_plane::kViewRight) - 1u;

// Bit p set when the vertex lies outside plane p (NaN counts as outside). A triangle is wholly
// outside when its vertices' outcodes share a bit, and needs no clipping when their union has
// no bit of kClippingPlaneMask. Binning computes it once per vertex (tiler/vertex_kernels.h
// computes the same bits with SIMD).
unsigned clip_outcode(const glm::vec4& position, const GuardBand& guard);

// Classifies a triangle; when the result is Clipped, `out` holds the clipped convex polygon
// (count >= 3) with interpolated varyings. Positions must be finite (callers drop others).
// Intersections are computed from the inside vertex towards the outside one, so an edge
// shared by two triangles is cut at bit-identical points in both (watertight clipping).
ClipOutcome clip_triangle(const glm::vec4 position[3], const float* const varyings[3],
                          int varying_count, const GuardBand& guard, ClipPolygon& out);
// The clipping step alone, for a triangle whose outcodes share no bit and whose union has the
// clipping-plane bits `planes` (non-zero): Clipped with `out` filled, or Outside.
ClipOutcome clip_against_planes(const glm::vec4 position[3], const float* const varyings[3],
                                int varying_count, const GuardBand& guard, unsigned planes,
                                ClipPolygon& out);

}  // namespace ontile
