// Coverage: walks the 2x2 quads of a pixel rectangle that a set-up triangle touches and
// reports which samples each quad covers, using incremental integer edge functions.
#pragma once
#include <algorithm>
#include <cstdint>

#include "raster/sample_pattern.h"
#include "raster/shader_interface.h"
#include "raster/triangle_setup.h"

namespace ontile {

// A pixel rectangle [x0, x1) x [y0, y1); x0 and y0 must be even (quad aligned).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Coverage of one quad: bit (lane * kMaxSamples + sample), lanes as in QuadFragment.
using QuadCoverage = uint32_t;
constexpr QuadCoverage lane_coverage(QuadCoverage c, int lane) {
  return (c >> (lane * kMaxSamples)) & 0xFFu;
}

// Calls emit(quad_x, quad_y, coverage) for every quad in `rect` with at least one covered
// sample, in row-major order. Samples outside `rect` (beyond the render target's last
// row/column) are never covered.
template <class Emit>
void rasterize_quads(const TriangleSetup& t, const SamplePattern& pattern, const PixelRect& rect,
                     Emit&& emit) {
  const int x_begin = std::max(rect.x0, t.min_x & ~1);
  const int y_begin = std::max(rect.y0, t.min_y & ~1);
  const int x_end = std::min(rect.x1, t.max_x + 1);
  const int y_end = std::min(rect.y1, t.max_y + 1);
  if (x_begin >= x_end || y_begin >= y_end) return;

  // Edge value of every (lane, sample) position of the quad at (x_begin, y_begin), including
  // the top-left bias, so that a position is inside iff all three values are >= 0.
  const int samples = pattern.count;
  int64_t origin[3][kQuadLanes * kMaxSamples];
  int64_t step_x[3], step_y[3];
  for (int e = 0; e < 3; ++e) {
    const EdgeFunction& f = t.edge[e];
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      const int64_t px = int64_t{x_begin + (lane & 1)} * kSubpixelScale;
      const int64_t py = int64_t{y_begin + (lane >> 1)} * kSubpixelScale;
      for (int s = 0; s < samples; ++s) {
        origin[e][lane * kMaxSamples + s] = f.at(px + pattern.x[s], py + pattern.y[s]) + f.bias;
      }
    }
    step_x[e] = f.a * 2 * kSubpixelScale;  // one quad to the right
    step_y[e] = f.b * 2 * kSubpixelScale;  // one quad down
  }

  int64_t row_offset[3] = {0, 0, 0};
  for (int qy = y_begin; qy < y_end; qy += 2) {
    int64_t offset[3] = {row_offset[0], row_offset[1], row_offset[2]};
    const bool bottom_row_valid = qy + 1 < y_end;
    for (int qx = x_begin; qx < x_end; qx += 2) {
      const bool right_column_valid = qx + 1 < x_end;
      QuadCoverage coverage = 0;
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        if ((lane & 1) && !right_column_valid) continue;
        if ((lane >> 1) && !bottom_row_valid) continue;
        for (int s = 0; s < samples; ++s) {
          const int k = lane * kMaxSamples + s;
          if (origin[0][k] + offset[0] >= 0 && origin[1][k] + offset[1] >= 0 &&
              origin[2][k] + offset[2] >= 0) {
            coverage |= QuadCoverage{1} << k;
          }
        }
      }
      if (coverage) emit(qx, qy, coverage);
      for (int e = 0; e < 3; ++e) offset[e] += step_x[e];
    }
    for (int e = 0; e < 3; ++e) row_offset[e] += step_y[e];
  }
}

// Screen-space barycentrics (lambda_0..2, summing to 1) at a point in subpixel units.
inline void screen_barycentrics(const TriangleSetup& t, int64_t px, int64_t py, double out[3]) {
  out[1] = static_cast<double>(t.edge[1].at(px, py)) * t.inv_area2;
  out[2] = static_cast<double>(t.edge[2].at(px, py)) * t.inv_area2;
  out[0] = 1.0 - out[1] - out[2];
}

// Perspective-correct weights from screen-space barycentrics: lambda_i / w_i, normalised.
inline void perspective_weights(const TriangleSetup& t, const double screen[3], float out[3]) {
  const double q0 = screen[0] * t.inv_w[0];
  const double q1 = screen[1] * t.inv_w[1];
  const double q2 = screen[2] * t.inv_w[2];
  const double inv_sum = 1.0 / (q0 + q1 + q2);
  out[0] = static_cast<float>(q0 * inv_sum);
  out[1] = static_cast<float>(q1 * inv_sum);
  out[2] = static_cast<float>(q2 * inv_sum);
}

// Depth is interpolated linearly in screen space (z/w is affine there) and clamped to the
// [0, 1] depth range, as Vulkan does before the depth test.
inline float interpolate_depth(const TriangleSetup& t, const double screen[3]) {
  const double z = screen[0] * t.depth[0] + screen[1] * t.depth[1] + screen[2] * t.depth[2];
  return static_cast<float>(std::clamp(z, 0.0, 1.0));
}

}  // namespace ontile
