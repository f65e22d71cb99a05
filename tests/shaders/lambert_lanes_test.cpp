// The Lambert lighting lanes (lambert_lanes.cpp) against the scalar formula the functor ran
// before, bit for bit on every SIMD target: random normals with zero, NaN, tiny and huge ones,
// both facings, texel rows and constant factors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "raster/cell_raster.h"
#include "shaders_cpp/lambert_lanes.h"

namespace ontile {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The functor's per-fragment loop as it was written (scalar, in source order).
void scalar_light(const float* nx, const float* ny, const float* nz, const LambertLaneConstants& k,
                  const float (*albedo)[kBatchFragments], const float (*emissive)[kBatchFragments],
                  float (*out)[kBatchFragments], int count) {
  for (int f = 0; f < count; ++f) {
    const float len = std::sqrt(nx[f] * nx[f] + ny[f] * ny[f] + nz[f] * nz[f]);
    const bool has_length = len > 0.0f;
    const float divisor = has_length ? len : 1.0f;
    const float qx = nx[f] / divisor, qy = ny[f] / divisor, qz = nz[f] / divisor;
    const float x = (has_length ? qx : 0.0f) * k.facing;
    const float y = (has_length ? qy : 0.0f) * k.facing;
    const float z = (has_length ? qz : 1.0f) * k.facing;
    const float dot = x * k.to_light[0] + y * k.to_light[1] + z * k.to_light[2];
    const float n_dot_l = dot > 0.0f ? dot : 0.0f;
    for (int c = 0; c < 4; ++c) {
      const float a = albedo ? k.base_color[c] * albedo[c][f] : k.base_color[c];
      if (c == 3) {
        out[3][f] = a;
        continue;
      }
      const float e = emissive ? k.emission[c] * emissive[c][f] : k.emission[c];
      out[c][f] = a * (k.ambient[c] + k.radiance[c] * n_dot_l) + e;
    }
  }
}

TEST(LambertLanes, MatchScalarFormulaOnEveryTarget) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), texel(0.0f, 1.0f);
  alignas(64) float nx[kBatchFragments], ny[kBatchFragments], nz[kBatchFragments];
  alignas(64) float albedo[4][kBatchFragments], emissive[3][kBatchFragments];
  for (int f = 0; f < kBatchFragments; ++f) {
    nx[f] = unit(rng);
    ny[f] = unit(rng);
    nz[f] = unit(rng);
    for (auto& row : albedo) row[f] = texel(rng);
    for (auto& row : emissive) row[f] = texel(rng);
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float specials[][3] = {{0, 0, 0}, {-0.0f, 0, 0}, {nan, 0, 1}, {1e-30f, 0, 0}, {1e30f, 1e30f, 0},
                               {0, 0, -1}, {1e-20f, -1e-20f, 1e-20f}};
  for (int i = 0; i < static_cast<int>(std::size(specials)); ++i) {
    nx[i] = specials[i][0];
    ny[i] = specials[i][1];
    nz[i] = specials[i][2];
  }
  LambertLaneConstants k{{-0.4f, 0.8f, 0.45f}, {0.2f, 0.2f, 0.2f}, {1.0f, 0.9f, 0.7f}, 1.0f,
                         {0.9f, 0.6f, 0.3f, 0.75f}, {0.1f, 0.0f, 0.5f}};
  const AutomaticTargetOnExit restore;
  for (const float facing : {1.0f, -1.0f}) {
    k.facing = facing;
    for (const bool rows_albedo : {false, true}) {
      for (const bool rows_emissive : {false, true}) {
        const auto* a = rows_albedo ? albedo : nullptr;
        const auto* e = rows_emissive ? emissive : nullptr;
        alignas(64) float expected[4][kBatchFragments];
        scalar_light(nx, ny, nz, k, a, e, expected, kBatchFragments);
        for (const std::string& target : simd_targets()) {
          SCOPED_TRACE(target);
          force_simd_target(target);
          alignas(64) float out[4][kBatchFragments];
          lambert_light_batch(nx, ny, nz, k, a, e, out, kBatchFragments);
          for (int c = 0; c < 4; ++c) {
            for (int f = 0; f < kBatchFragments; ++f) {
              ASSERT_TRUE(same_bits(out[c][f], expected[c][f]))
                  << "channel " << c << " fragment " << f << " facing " << facing << ": "
                  << out[c][f] << " vs " << expected[c][f];
            }
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace ontile
