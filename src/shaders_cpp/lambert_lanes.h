// The Lambert functor's lighting over a fragment batch on SIMD lanes (Highway, runtime
// dispatch): the scalar per-fragment formula's IEEE operations in its order, so every target
// gives the same bits.
#pragma once
#include "raster/shader_interface.h"

namespace ontile {

// What every fragment of a batch shares: the light, the facing sign (+1 front, -1 back) and
// the untextured factors (used where the per-fragment rows below are null).
struct LambertLaneConstants {
  float to_light[3];
  float ambient[3];
  float radiance[3];
  float facing;
  float base_color[4];
  float emission[3];
};

// For f < count (a multiple of 16): n = normalize(nx, ny, nz) (or (0, 0, 1) for a zero
// normal) times facing, n_dot_l = max(dot(n, to_light), 0), and
//   rgb[f] = albedo * (ambient + radiance * n_dot_l) + emissive,  a[f] = albedo alpha,
// with albedo = base_color[c] x albedo[c][f] (texels) when albedo is non-null, else
// base_color[c]; emissive = emission[c] x emissive[c][f] likewise.
void lambert_light_batch(const float* nx, const float* ny, const float* nz,
                         const LambertLaneConstants& k, const float (*albedo)[kBatchFragments],
                         const float (*emissive)[kBatchFragments], float (*out)[kBatchFragments],
                         int count);

}  // namespace ontile
