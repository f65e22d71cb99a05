// The batched lighting helpers (SIMD-lane loops over a fragment batch) against their per-fragment
// originals, bit for bit: light_incidence and shade_ggx, summed as direct lighting sums them,
// on random and degenerate inputs (zero half vector, back-facing light, surface at the light),
// on every SIMD target.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "raster/cell_raster.h"
#include "shaders_cpp/lighting/brdf.h"
#include "shaders_cpp/lighting/punctual_light.h"

namespace ontile {
namespace {

bool same_bits(glm::vec3 a, glm::vec3 b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Lanes {
  BrdfBatch brdf;
  alignas(64) BatchVec3 n, to_view, position;
};

// Random surfaces, with a few lanes made degenerate on purpose.
Lanes random_lanes(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), positive(0.0f, 1.0f);
  Lanes l;
  for (int f = 0; f < kBatchFragments; ++f) {
    const glm::vec3 n = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(0.0f, 0.0f, 0.3f));
    const glm::vec3 v = glm::normalize(glm::vec3(unit(rng), unit(rng), positive(rng) + 0.01f));
    batch_set3(l.n, f, n);
    batch_set3(l.to_view, f, v);
    batch_set3(l.position, f, glm::vec3(unit(rng), unit(rng), unit(rng)) * 4.0f);
    const BrdfInputs b = metallic_roughness_brdf(glm::vec3(positive(rng), positive(rng), positive(rng)),
                                                 positive(rng), f % 7 == 0 ? 0.0f : positive(rng));
    for (int c = 0; c < 3; ++c) {
      l.brdf.diffuse_color[c][f] = b.diffuse_color[c];
      l.brdf.f0[c][f] = b.f0[c];
    }
    l.brdf.roughness[f] = b.roughness;
  }
  return l;
}

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

TEST(BatchedLighting, GgxAndLightIncidenceMatchThePerFragmentFunctionsOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  for (const std::string& target : simd_targets()) {
  SCOPED_TRACE(target);
  force_simd_target(target);
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (int round = 0; round < 200; ++round) {
    Lanes l = random_lanes(rng);
    PunctualLight light;
    light.type = static_cast<PunctualLight::Type>(round % 3);
    light.position = glm::vec3(unit(rng), unit(rng), unit(rng)) * 3.0f;
    light.intensity = glm::vec3(2.0f, 1.0f, 0.5f) * (1.0f + 4.0f * (unit(rng) + 1.0f));
    light.range = round % 4 == 0 ? 0.0f : 2.0f + 3.0f * (unit(rng) + 1.0f);
    light.direction = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(0.0f, -0.5f, 0.0f));
    light.spot_scale = 4.0f;
    light.spot_offset = -2.5f;
    // Degenerate lanes: a surface at the light, and a view opposite the sun (zero half vector).
    batch_set3(l.position, 3, light.position);
    const glm::vec3 sun(0.0f, 0.0f, 1.0f);
    batch_set3(l.to_view, 5, -sun);
    const int begin = round % 5, end = kBatchFragments - round % 3;
    alignas(64) int32_t lit[kBatchFragments], reached[kBatchFragments];
    for (int f = 0; f < kBatchFragments; ++f) lit[f] = f % 11 != 0;
    alignas(64) BatchVec3 to_light, radiance, sum = {};
    for (int c = 0; c < 3; ++c) {
      for (int f = 0; f < kBatchFragments; ++f) {
        to_light[c][f] = sun[c];
        radiance[c][f] = 1.5f;
      }
    }
    shade_ggx(l.brdf, l.n, l.to_view, to_light, radiance, lit, begin, end, false, sum);
    light_incidence(light, l.position, lit, begin, end, to_light, radiance, reached);
    alignas(64) BatchVec3 batch_to_light, batch_radiance;
    std::memcpy(batch_to_light, to_light, sizeof to_light);
    std::memcpy(batch_radiance, radiance, sizeof radiance);
    shade_ggx(l.brdf, l.n, l.to_view, to_light, radiance, reached, begin, end, true, sum);
    for (int f = begin; f < end; ++f) {
      if (!lit[f]) continue;
      const BrdfInputs b = l.brdf.at(f);
      const glm::vec3 n = batch_get3(l.n, f), v = batch_get3(l.to_view, f);
      glm::vec3 expected = shade_ggx(b, n, v, sun, glm::vec3(1.5f));
      glm::vec3 expected_to_light, expected_radiance;
      const bool expected_reached =
          light_incidence(light, batch_get3(l.position, f), expected_to_light, expected_radiance);
      ASSERT_EQ(reached[f] != 0, expected_reached) << "round " << round << " fragment " << f;
      if (expected_reached) {
        ASSERT_TRUE(same_bits(batch_get3(batch_to_light, f), expected_to_light)) << round << " " << f;
        ASSERT_TRUE(same_bits(batch_get3(batch_radiance, f), expected_radiance)) << round << " " << f;
        expected += shade_ggx(b, n, v, expected_to_light, expected_radiance);
      }
      ASSERT_TRUE(same_bits(batch_get3(sum, f), expected)) << "round " << round << " fragment " << f;
    }
  }
  }
}

}  // namespace
}  // namespace ontile
