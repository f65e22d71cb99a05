// Interpolation of a whole batch of quads in one call: runs of consecutive quads, each run of
// one triangle (its plane gradients, vertex 1/w and varyings), at pixel centres.
#pragma once
#include <cstdint>

#include "raster/cell_raster.h"

namespace ontile {

// One triangle's quads of a batch: quads first_quad up to the next run's first quad (the last
// run's up to quad_count).
struct InterpolationRun {
  int first_quad;
  float l1_dx, l1_dy, l2_dx, l2_dy, z_dx, z_dy;  // plane gradients per pixel
  float inv_w[3];
  const float* vertex_varyings[3];  // varying_count floats per vertex, setup slot order
};

// The largest batch one call interpolates (the fragments of kBatchQuads quads).
constexpr int kMaxRunFragments = 64;

// interpolate_whole_quads of each run with its triangle's terms, bit for bit, in one call: quad
// q's fragments 4q .. 4q + 3 of depth_out and of each varying k whose bit is set in
// varyings_read (row k of varyings_out, varyings_stride floats apart). 4 * quad_count must not
// exceed kMaxRunFragments; the per-quad arrays must be readable up to quad_count +
// kQuadOriginsPadding entries. A run's last SIMD vector may reach into the next run's quads:
// the next run overwrites them.
void interpolate_quad_runs(const InterpolationRun* runs, int run_count, const QuadOrigins& quads,
                           int quad_count, int varying_count, uint32_t varyings_read,
                           float* depth_out, float* varyings_out, int varyings_stride);

}  // namespace ontile
