// Homogeneous triangle clipping (see clip.h). Plane distances are d(v) >= 0 inside.
#include "raster/clip.h"

#include <algorithm>

namespace ontile {
using namespace clip_plane;
namespace {

inline float plane_distance(int plane, const glm::vec4& v, const GuardBand& g) {
  switch (plane) {
    case kNear: return v.z;                    // Vulkan/D3D: z >= 0
    case kFar: return v.w - v.z;               // z <= w
    case kPositiveW: return v.w - kClipMinW;
    case kGuardRight: return g.x_max * v.w - v.x;
    case kGuardLeft: return v.x - g.x_min * v.w;
    case kGuardBottom: return v.y - g.y_min * v.w;  // +Y is up in clip space
    case kGuardTop: return g.y_max * v.w - v.y;
    case kViewRight: return v.w - v.x;
    case kViewLeft: return v.x + v.w;
    case kViewBottom: return v.y + v.w;
    case kViewTop: return v.w - v.y;
    default: return 0.0f;
  }
}

void clip_against_plane(int plane, int varying_count, const GuardBand& g, ClipPolygon& poly,
                        ClipPolygon& scratch) {
  scratch.count = 0;
  float dist[ClipPolygon::kMaxVertices];
  for (int i = 0; i < poly.count; ++i) dist[i] = plane_distance(plane, poly.position[i], g);
  auto emit_copy = [&](int i) {
    const int k = scratch.count++;
    scratch.position[k] = poly.position[i];
    std::copy_n(poly.varyings[i], varying_count, scratch.varyings[k]);
  };
  // In double: with vertices ~1e6 screen widths apart, a float lerp moves the clipped edge by
  // up to 0.18 px (tests/stability/clipping_stress_test.cpp measures it against the exact line).
  auto emit_intersection = [&](int inside, int outside) {
    const double t = double(dist[inside]) / (double(dist[inside]) - double(dist[outside]));
    const int k = scratch.count++;
    const glm::dvec4 pi(poly.position[inside]), po(poly.position[outside]);
    scratch.position[k] = glm::vec4(pi + t * (po - pi));
    for (int a = 0; a < varying_count; ++a) {
      const double vi = poly.varyings[inside][a];
      scratch.varyings[k][a] = static_cast<float>(vi + t * (double(poly.varyings[outside][a]) - vi));
    }
  };
  for (int i = 0; i < poly.count; ++i) {
    const int j = (i + 1) % poly.count;
    const bool in_i = dist[i] >= 0.0f;
    const bool in_j = dist[j] >= 0.0f;
    if (in_i) emit_copy(i);
    if (in_i && !in_j) emit_intersection(i, j);
    if (!in_i && in_j) emit_intersection(j, i);
  }
  poly.count = scratch.count;
  for (int i = 0; i < scratch.count; ++i) {
    poly.position[i] = scratch.position[i];
    std::copy_n(scratch.varyings[i], varying_count, poly.varyings[i]);
  }
}

}  // namespace

// Straight-line form of plane_distance() < 0 for every plane: it runs for every vertex, so it
// avoids the per-plane switch.
unsigned clip_outcode(const glm::vec4& v, const GuardBand& g) {
  auto out = [](float d, int plane) { return d >= 0.0f ? 0u : 1u << plane; };
  return out(v.z, kNear) | out(v.w - v.z, kFar) | out(v.w - kClipMinW, kPositiveW) |
         out(g.x_max * v.w - v.x, kGuardRight) | out(v.x - g.x_min * v.w, kGuardLeft) |
         out(v.y - g.y_min * v.w, kGuardBottom) | out(g.y_max * v.w - v.y, kGuardTop) |
         out(v.w - v.x, kViewRight) | out(v.x + v.w, kViewLeft) | out(v.y + v.w, kViewBottom) |
         out(v.w - v.y, kViewTop);
}

GuardBand GuardBand::for_viewport(int width_px, int height_px) {
  // A little inside the fixed-point limit so that rounding never leaves it.
  const double limit_px = kGuardBandPx - 64;
  GuardBand g;
  g.x_max = static_cast<float>(2.0 * limit_px / width_px - 1.0);
  g.x_min = static_cast<float>(-2.0 * limit_px / width_px - 1.0);
  // Screen y = (1 - y/w) * H / 2, so y/w = 1 - 2 * y_screen / H.
  g.y_max = static_cast<float>(1.0 + 2.0 * limit_px / height_px);
  g.y_min = static_cast<float>(1.0 - 2.0 * limit_px / height_px);
  return g;
}

ClipOutcome clip_triangle(const glm::vec4 position[3], const float* const varyings[3],
                          int varying_count, const GuardBand& guard, ClipPolygon& out) {
  const unsigned c0 = clip_outcode(position[0], guard);
  const unsigned c1 = clip_outcode(position[1], guard);
  const unsigned c2 = clip_outcode(position[2], guard);
  if (c0 & c1 & c2) return ClipOutcome::Outside;  // all on the wrong side of one plane
  const unsigned needed = (c0 | c1 | c2) & kClippingPlaneMask;
  if (needed == 0) return ClipOutcome::Inside;
  return clip_against_planes(position, varyings, varying_count, guard, needed, out);
}

ClipOutcome clip_against_planes(const glm::vec4 position[3], const float* const varyings[3],
                                int varying_count, const GuardBand& guard, unsigned planes,
                                ClipPolygon& out) {
  out.count = 3;
  for (int i = 0; i < 3; ++i) {
    out.position[i] = position[i];
    std::copy_n(varyings[i], varying_count, out.varyings[i]);
  }
  ClipPolygon scratch;
  for (int p = 0; p < kViewRight; ++p) {
    if (!(planes & (1u << p))) continue;
    clip_against_plane(p, varying_count, guard, out, scratch);
    if (out.count < 3) return ClipOutcome::Outside;
  }
  return ClipOutcome::Clipped;
}

}  // namespace ontile
