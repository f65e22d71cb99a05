// The batched functors' per-fragment helpers on SIMD lanes against the scalar code they stand
// for, bit for bit on every SIMD target: batch_unit_normals against toon_unit_normal, and the cel
// shader's lit/shadow mix against cel_shadow_factor and glm::mix, and the gradient sky against
// its per-fragment formula.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "raster/cell_raster.h"
#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/gradient_sky_lanes.h"
#include "shaders_cpp/toon/cel_shader.h"
#include "shaders_cpp/toon/toon_outputs.h"

namespace ontile {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

uint32_t bits(float v) { return std::bit_cast<uint32_t>(v); }

// Normals a rasteriser can hand over: ordinary, tiny (denormal squares), huge (overflowing
// squares), zero, and NaN/Inf components.
float awkward_component(std::mt19937& rng, int f) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  std::uniform_real_distribution<float> u(-1.5f, 1.5f);
  switch (f % 11) {
    case 3: return u(rng) * 1e-22f;
    case 5: return u(rng) * 1e25f;
    case 7: return 0.0f;
    case 8: return f % 2 ? -0.0f : 0.0f;
    case 9: return f % 3 ? nan : inf;
    default: return u(rng);
  }
}

TEST(FragmentLanes, UnitNormalsMatchToonUnitNormalOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  std::mt19937 rng(2026);
  for (const std::string& target : simd_targets()) {
    force_simd_target(target);
    for (int round = 0; round < 40; ++round) {
      FragmentBatch batch;
      batch.front_facing = round % 2 == 0;
      for (int c = 0; c < 3; ++c) {
        for (int f = 0; f < kBatchFragments; ++f) batch.varyings[4 + c][f] = awkward_component(rng, f + c * round);
      }
      const int n = 16 * (1 + round % 4);
      alignas(64) BatchVec3 normal;
      batch_unit_normals(batch, 4, n, normal);
      for (int f = 0; f < n; ++f) {
        const glm::vec3 in(batch.varyings[4][f], batch.varyings[5][f], batch.varyings[6][f]);
        // NaN results included: the back-face sign is a negation, also for a NaN.
        const glm::vec3 expected = toon_unit_normal(in, batch.front_facing);
        for (int c = 0; c < 3; ++c) {
          ASSERT_EQ(bits(normal[c][f]), bits(expected[c])) << target << " fragment " << f << " component " << c;
        }
      }
    }
  }
}

TEST(FragmentLanes, CelMixMatchesTheScalarBandsOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> colour(0.0f, 1.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  struct Bands {
    int steps;
    float step_size;
  };
  const Bands bands[] = {{1, 1.0f}, {3, 1.0f / 3.0f}, {6, 1.0f / 6.0f}, {3, 0.1f}, {7, 0.03f}};
  for (const std::string& target : simd_targets()) {
    force_simd_target(target);
    for (const Bands& b : bands) {
      const glm::vec3 to_light = glm::normalize(glm::vec3(colour(rng) - 0.5f, 1.0f, colour(rng) - 0.5f));
      alignas(64) BatchVec3 normal;
      alignas(64) BatchVec4 lit, shadow, mixed;
      for (int f = 0; f < kBatchFragments; ++f) {
        // Normals all around the sphere, a few exactly on the terminator, and NaN.
        const glm::vec3 n = f % 13 == 0 ? glm::vec3(to_light.z, 0.0f, -to_light.x)
                            : f % 17 == 0 ? glm::vec3(nan, 0.0f, 0.0f)
                                          : glm::vec3(colour(rng) * 2 - 1, colour(rng) * 2 - 1, colour(rng) * 2 - 1);
        for (int c = 0; c < 3; ++c) normal[c][f] = n[c];
        for (int c = 0; c < 4; ++c) {
          lit[c][f] = colour(rng);
          shadow[c][f] = colour(rng);
        }
      }
      cel_mix_batch(normal, to_light, b.steps, b.step_size, lit, shadow, kBatchFragments, mixed);
      for (int f = 0; f < kBatchFragments; ++f) {
        const float n_dot_l = (normal[0][f] * to_light.x + normal[1][f] * to_light.y) + normal[2][f] * to_light.z;
        const float t = cel_shadow_factor(n_dot_l, b.steps, b.step_size);
        for (int c = 0; c < 4; ++c) {
          const float expected = lit[c][f] * (1.0f - t) + shadow[c][f] * t;
          ASSERT_EQ(bits(mixed[c][f]), bits(expected)) << target << " steps " << b.steps << " fragment " << f;
        }
      }
    }
  }
}

// GradientSkyShader's formula for one fragment, as it was written before it moved onto lanes.
glm::vec4 sky_of_direction(glm::vec3 d, const SkyColours& sky) {
  const float len = std::sqrt((d.x * d.x + d.y * d.y) + d.z * d.z);
  const bool has_length = len > 0.0f;
  const float up = has_length ? d.y / len : 0.0f;
  const float above = std::sqrt(up);
  const float below_t = -up * 4.0f;
  const float below = below_t < 1.0f ? below_t : 1.0f;
  glm::vec4 colour(1.0f);
  for (int c = 0; c < 3; ++c) {
    const float above_c = sky.horizon[c] * (1.0f - above) + sky.zenith[c] * above;
    const float below_c = sky.horizon[c] * (1.0f - below) + sky.ground[c] * below;
    colour[c] = up >= 0.0f ? above_c : below_c;
  }
  return colour;
}

TEST(FragmentLanes, GradientSkyMatchesThePerFragmentFormulaOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  std::mt19937 rng(5);
  const SkyColours sky{{0.2f, 0.35f, 0.8f}, {0.7f, 0.75f, 0.8f}, {0.3f, 0.25f, 0.2f}};
  for (const std::string& target : simd_targets()) {
    force_simd_target(target);
    for (int round = 0; round < 20; ++round) {
      alignas(64) float dx[kBatchFragments], dy[kBatchFragments], dz[kBatchFragments];
      for (int f = 0; f < kBatchFragments; ++f) {
        dx[f] = awkward_component(rng, f + round);
        dy[f] = f % 5 == 0 ? -awkward_component(rng, f) : awkward_component(rng, f + 2 * round);
        dz[f] = awkward_component(rng, f + 3 * round);
      }
      alignas(64) float colour[4][kBatchFragments];
      gradient_sky_batch(dx, dy, dz, kBatchFragments, sky, colour);
      for (int f = 0; f < kBatchFragments; ++f) {
        const glm::vec4 expected = sky_of_direction({dx[f], dy[f], dz[f]}, sky);
        for (int c = 0; c < 4; ++c) {
          ASSERT_EQ(bits(colour[c][f]), bits(expected[c])) << target << " fragment " << f << " channel " << c;
        }
      }
    }
  }
}

}  // namespace
}  // namespace ontile
