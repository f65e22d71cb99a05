// direct_lighting_lanes (the lit functors' SIMD kernel) against the per-fragment functions, bit
// for bit: the sun's shade_ggx, then each grid-cell light's light_incidence and shade_ggx in
// order, on random and degenerate inputs (zero half vector, back-facing light, surface at the
// light), runs of cells, fragments outside the grid and unlit fragments, on every SIMD target.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "raster/cell_raster.h"
#include "shaders_cpp/lighting/brdf.h"
#include "shaders_cpp/lighting/punctual_light.h"
#include "shaders_cpp/lighting/scene_lighting.h"

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

// Two grid cells: cell 0 lists lights 0, 1, 2 (point, spot, directional), cell 1 only light 1.
SceneLighting random_lighting(std::mt19937& rng, int round) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  SceneLighting lighting;
  lighting.sun_to_light = glm::vec3(0.0f, 0.0f, 1.0f);
  lighting.sun_radiance = glm::vec3(1.5f);
  for (int k = 0; k < 3; ++k) {
    PunctualLight light;
    light.type = static_cast<PunctualLight::Type>((round + k) % 3);
    light.position = glm::vec3(unit(rng), unit(rng), unit(rng)) * 3.0f;
    light.intensity = glm::vec3(2.0f, 1.0f, 0.5f) * (1.0f + 4.0f * (unit(rng) + 1.0f));
    light.range = (round + k) % 4 == 0 ? 0.0f : 2.0f + 3.0f * (unit(rng) + 1.0f);
    light.direction = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(0.0f, -0.5f, 0.0f));
    light.spot_scale = 4.0f;
    light.spot_offset = -2.5f;
    lighting.lights.push_back(light);
  }
  lighting.grid.cells_x = 2;
  lighting.grid.cells_y = 1;
  lighting.grid.cell_begin = {0, 3, 4};
  lighting.grid.light_indices = {0, 1, 2, 1};
  return lighting;
}

TEST(BatchedLighting, DirectLightingLanesMatchThePerFragmentFunctionsOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  for (const std::string& target : simd_targets()) {
    SCOPED_TRACE(target);
    force_simd_target(target);
    std::mt19937 rng(1234);
    for (int round = 0; round < 200; ++round) {
      Lanes l = random_lanes(rng);
      const SceneLighting lighting = random_lighting(rng, round);
      // Degenerate lanes: a surface at a light, and a view opposite the sun (zero half vector).
      batch_set3(l.position, 3, lighting.lights[0].position);
      batch_set3(l.to_view, 5, -lighting.sun_to_light);
      const int count = 4 * (1 + round % 16);
      // Runs of cells as a batch's fragments meet them: cell 0, cell 1, outside the grid (-1).
      alignas(64) int32_t cell[kBatchFragments];
      const int first_run = static_cast<int>(rng() % (count + 1));
      const int second_run = first_run + static_cast<int>(rng() % (count - first_run + 1));
      for (int f = 0; f < count; ++f) cell[f] = f < first_run ? 0 : f < second_run ? 1 : -1;
      const uint64_t all = count == 64 ? ~uint64_t{0} : (uint64_t{1} << count) - 1;
      const uint64_t lit = (uint64_t{rng()} << 32 | rng()) & all;
      alignas(64) BatchVec3 sum;
      for (int c = 0; c < 3; ++c) {
        for (int f = 0; f < kBatchFragments; ++f) sum[c][f] = -7.0f - static_cast<float>(f);  // kept unless lit
      }
      direct_lighting_lanes(lighting, l.brdf, l.n, l.position, l.to_view, cell, count, lit, sum);
      for (int f = 0; f < count; ++f) {
        const glm::vec3 before(-7.0f - static_cast<float>(f));
        if (!((lit >> f) & 1u)) {
          ASSERT_TRUE(same_bits(batch_get3(sum, f), before)) << "round " << round << " fragment " << f;
          continue;
        }
        const BrdfInputs b = l.brdf.at(f);
        const glm::vec3 n = batch_get3(l.n, f), v = batch_get3(l.to_view, f), p = batch_get3(l.position, f);
        glm::vec3 expected = shade_ggx(b, n, v, lighting.sun_to_light, lighting.sun_radiance);
        for (const uint32_t index : lighting.grid.lights_in(cell[f])) {
          glm::vec3 to_light, radiance;
          if (light_incidence(lighting.lights[index], p, to_light, radiance)) {
            expected += shade_ggx(b, n, v, to_light, radiance);
          }
        }
        ASSERT_TRUE(same_bits(batch_get3(sum, f), expected)) << "round " << round << " fragment " << f;
      }
    }
  }
}

}  // namespace
}  // namespace ontile
