// The universal pipeline's batched functor code against the scalar code it replaced, bit for
// bit: the shadow PCF of a whole batch and its texel trace (main_light_visibility per kept
// fragment, quad by quad), the tone curves on lanes, and the Lit lighting lanes against the
// per-fragment Blinn-Phong with point, spot and directional lights, on every SIMD target.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "pipelines/universal/main_light_shadows_batch.h"
#include "pipelines/universal/universal_lit_functors.h"
#include "pipelines/universal/universal_lit_lighting.h"
#include "raster/cell_raster.h"
#include "raster/texel_trace.h"
#include "shaders_cpp/tone_curves.h"
#include "shaders_cpp/tone_curves_batch.h"

namespace ontile {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

uint32_t bits(float v) { return std::bit_cast<uint32_t>(v); }

glm::vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<float> g(0.0f, 1.0f);
  return glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
}

TEST(UniversalShadowBatch, MatchesScalarVisibilityAndTraceOnEveryTarget) {
  std::mt19937 rng(77);
  constexpr int kW = 37, kH = 23;
  std::vector<uint8_t> depth(static_cast<size_t>(kW) * kH * 4);
  for (size_t i = 0; i < depth.size(); i += 4) {
    const float d = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
    std::memcpy(&depth[i], &d, 4);
  }
  const auto map = Texture2D::view_of_surface(kW, kH, PixelFormat::D32_FLOAT, depth.data(), "shadow");
  ShadowLookup s;
  s.set_map(map.get());
  // World [-5, 5]^3 onto about [-0.05, 1.05]^3, with some shear so every row of the matrix counts.
  s.world_to_shadow = glm::mat4(glm::vec4(0.11f, 0.01f, 0.02f, 0.0f), glm::vec4(0.015f, 0.105f, -0.01f, 0.0f),
                                glm::vec4(-0.01f, 0.02f, 0.1f, 0.0f), glm::vec4(0.5f, 0.49f, 0.51f, 1.0f));
  s.depth_bias_world = 0.03f;
  s.normal_bias_world = 0.05f;
  s.strength = 0.85f;
  ASSERT_TRUE(shadow_batch_supported(s));
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  int inside = 0, outside = 0;
  for (int round = 0; round < 120; ++round) {
    force_simd_target(targets[round % targets.size()]);
    const glm::vec3 to_light = random_unit(rng);
    alignas(64) float x[kBatchFragments], y[kBatchFragments], z[kBatchFragments];
    alignas(64) float normal[3][kBatchFragments];
    std::uniform_real_distribution<float> coordinate(-5.5f, 5.5f);
    for (int f = 0; f < kBatchFragments; ++f) {
      x[f] = coordinate(rng);
      y[f] = coordinate(rng);
      z[f] = coordinate(rng);
      if (rng() % 29 == 0) x[f] = nan;
      const glm::vec3 n = rng() % 31 == 0 ? glm::vec3(0.0f) : random_unit(rng);
      for (int c = 0; c < 3; ++c) normal[c][f] = n[c];
    }
    // Kept lanes per quad, as the functor's lit mask (some quads keep none).
    uint64_t kept = 0;
    for (int f = 0; f < kBatchFragments; ++f) kept |= static_cast<uint64_t>(rng() % 4 != 0) << f;
    std::vector<uint64_t> expected_trace{3}, trace{3};  // a granule before: merges count too
    float expected[kBatchFragments];
    {
      const TexelTraceScope scope(&expected_trace);
      for (int f = 0; f < kBatchFragments; ++f) {
        if (!((kept >> f) & 1u)) continue;
        expected[f] = main_light_visibility(s, {x[f], y[f], z[f]}, {normal[0][f], normal[1][f], normal[2][f]}, to_light);
      }
    }
    ShadowBatch batch;
    {
      const TexelTraceScope scope(&trace);
      main_light_visibility_batch(s, x, y, z, normal, to_light, kBatchFragments, batch);
      EXPECT_EQ(trace.size(), 1u);  // the lookups themselves trace nothing
      for (int q = 0; q < kBatchQuads; ++q) {
        trace_shadow_quad(s, batch, q, static_cast<unsigned>(kept >> (q * kQuadLanes)) & 0xFu);
      }
    }
    ASSERT_EQ(trace, expected_trace) << "round " << round << " on " << targets[round % targets.size()];
    for (int f = 0; f < kBatchFragments; ++f) {
      if (!((kept >> f) & 1u)) continue;
      ASSERT_EQ(bits(batch.visibility[f]), bits(expected[f])) << "round " << round << " fragment " << f;
      ((batch.inside >> f) & 1u ? inside : outside) += 1;
    }
  }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 100);
}

TEST(UniversalShadowBatch, OnlyFloatMapsRunOnLanes) {
  std::vector<uint8_t> rgba(16 * 4, 0);
  const auto bytes = Texture2D::view_of_surface(4, 4, PixelFormat::RGBA8_UNORM, rgba.data(), "rgba8");
  ShadowLookup s;
  EXPECT_FALSE(shadow_batch_supported(s));
  s.set_map(bytes.get());
  EXPECT_FALSE(shadow_batch_supported(s));
  const auto floats = Texture2D::from_rgba32f(4, 4, std::vector<float>(64, 0.5f), "float");
  s.set_map(floats.get());
  EXPECT_TRUE(shadow_batch_supported(s));
}

TEST(UniversalToneCurves, BatchesMatchScalarCurvesOnEveryTarget) {
  std::mt19937 rng(5);
  const float inf = std::numeric_limits<float>::infinity();
  const float odd[] = {0.0f, -0.0f, -1.0f, 1e-30f, 65504.0f, 3e38f, inf, -inf, std::nanf(""), 0.18f};
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  for (int round = 0; round < 60; ++round) {
    force_simd_target(targets[round % targets.size()]);
    const float exposure = round % 3 == 0 ? 1.0f : std::uniform_real_distribution<float>(0.1f, 4.0f)(rng);
    alignas(64) float aces[4][kBatchFragments], reinhard[4][kBatchFragments];
    std::uniform_real_distribution<float> hdr(-0.5f, 20.0f);
    for (int c = 0; c < 4; ++c) {
      for (int f = 0; f < kBatchFragments; ++f) {
        aces[c][f] = rng() % 11 == 0 ? odd[rng() % 10] : hdr(rng);
        reinhard[c][f] = aces[c][f];
      }
    }
    const auto input = [&](int f) { return glm::vec3(aces[0][f], aces[1][f], aces[2][f]) * exposure; };
    glm::vec3 expected_aces[kBatchFragments], expected_reinhard[kBatchFragments];
    for (int f = 0; f < kBatchFragments; ++f) {
      expected_aces[f] = tonemap_aces_fitted(input(f));
      expected_reinhard[f] = tonemap_reinhard(input(f));
    }
    tonemap_aces_fitted_batch(aces, exposure, kBatchFragments);
    tonemap_reinhard_batch(reinhard, exposure, kBatchFragments);
    for (int f = 0; f < kBatchFragments; ++f) {
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(bits(aces[c][f]), bits(expected_aces[f][c])) << "round " << round << " fragment " << f;
        ASSERT_EQ(bits(reinhard[c][f]), bits(expected_reinhard[f][c])) << "round " << round << " fragment " << f;
      }
      ASSERT_EQ(aces[3][f], 1.0f);
      ASSERT_EQ(reinhard[3][f], 1.0f);
    }
  }
}

// The forward functor's per-fragment lighting before it was batched.
glm::vec3 scalar_lighting(const UniversalLitParams& p, glm::vec3 n_f, glm::vec3 position, glm::vec3 base,
                          float visibility) {
  const float shininess = std::exp2(10.0f * p.smoothness + 1.0f);
  const glm::vec3 to_camera = p.camera_position - position;
  const float camera_distance = glm::length(to_camera);
  const glm::vec3 to_view = camera_distance > 0.0f ? to_camera / camera_distance : n_f;
  const glm::vec3 diffuse_color = base * (1.0f - p.metallic);
  const glm::vec3 specular_color = glm::mix(glm::vec3(0.04f), base, p.metallic);
  glm::vec3 rgb = p.ambient * (diffuse_color + specular_color);
  const glm::vec3 main_radiance = p.main_light.radiance * visibility;
  rgb += blinn_phong(diffuse_color, specular_color, shininess, n_f, to_view, p.main_light.to_light, main_radiance);
  for (int i = 0; i < p.additional_light_count; ++i) {
    const AdditionalLight& light = p.additional_lights[i];
    glm::vec3 to_light = -light.direction;
    glm::vec3 radiance = light.intensity;
    if (light.type != AdditionalLight::Type::Directional) {
      const glm::vec3 offset = light.position - position;
      const float distance_squared = glm::dot(offset, offset);
      to_light = distance_squared > 0.0f ? offset / std::sqrt(distance_squared) : n_f;
      radiance *= range_attenuation(distance_squared, light.range) * spot_attenuation(light, -to_light);
    }
    rgb += blinn_phong(diffuse_color, specular_color, shininess, n_f, to_view, to_light, radiance);
  }
  return rgb;
}

TEST(UniversalLitLighting, BatchLanesMatchPerFragmentBlinnPhongOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  const std::vector<std::string> targets = simd_targets();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), coordinate(-4.0f, 4.0f);
  auto batch = std::make_unique<FragmentBatch>();
  batch->quad_count = kBatchQuads;
  const int count = kBatchFragments;
  for (int round = 0; round < 40 * static_cast<int>(targets.size()); ++round) {
    force_simd_target(targets[(round / 20) % targets.size()]);  // blocks: every light count per target
    UniversalLitParams p;
    p.metallic = round % 4 == 0 ? 0.0f : unit(rng);
    p.smoothness = unit(rng);
    p.camera_position = {coordinate(rng), coordinate(rng), coordinate(rng)};
    p.ambient = {unit(rng), unit(rng), unit(rng)};
    p.main_light.to_light = random_unit(rng);
    p.main_light.radiance = {1.0f + unit(rng), 1.0f, unit(rng)};
    AdditionalLight point, ranged, spot, sun;
    point.position = {coordinate(rng), coordinate(rng), coordinate(rng)};
    point.intensity = {3.0f, 2.0f, 1.0f};
    ranged = point;
    ranged.position = {coordinate(rng), coordinate(rng), coordinate(rng)};
    ranged.range = 4.0f;
    spot = ranged;
    spot.type = AdditionalLight::Type::Spot;
    spot.direction = random_unit(rng);
    spot.spot_scale = 3.0f;
    spot.spot_offset = -1.5f;
    sun.type = AdditionalLight::Type::Directional;
    sun.direction = random_unit(rng);
    sun.intensity = {0.5f, 0.4f, 0.3f};
    p.additional_lights = {point, ranged, spot, sun};
    p.additional_light_count = round % 5;
    alignas(64) float normal[3][kBatchFragments], albedo[4][kBatchFragments], visibility[kBatchFragments];
    for (int f = 0; f < count; ++f) {
      const glm::vec3 n = random_unit(rng);
      glm::vec3 position(coordinate(rng), coordinate(rng), coordinate(rng));
      if (f == 5) position = p.camera_position;  // zero distance to the camera
      if (f == 9) position = ranged.position;    // and to a light
      for (int c = 0; c < 3; ++c) {
        normal[c][f] = n[c];
        batch->varyings[MeshVertexShader::kWorldPos + c][f] = position[c];
      }
      for (int c = 0; c < 4; ++c) albedo[c][f] = unit(rng);
      // Albedos at the edges of the zero-radiance shortcut (a negative, a -0 and a huge channel
      // must still take the power), and fully shadowed fragments (radiance 0, power skipped).
      if (f == 13) albedo[1][f] = -albedo[1][f];
      if (f == 17) albedo[0][f] = -0.0f;
      if (f == 21) albedo[2][f] = 3.0e38f;
      visibility[f] = f % 3 == 0 ? 1.0f : f % 3 == 1 && f % 2 == 0 ? 0.0f : unit(rng);
    }
    const uint64_t lit = (uint64_t{rng()} << 32 | rng()) | 0x222u;
    alignas(64) float rgb[3][kBatchFragments];
    const float* shadowed = round % 2 ? visibility : nullptr;  // null: no shadow map (unshadowed)
    universal_lit_lighting(p, *batch, normal, albedo, shadowed, lit, count, rgb);
    for (int f = 0; f < count; ++f) {
      if (!((lit >> f) & 1u)) continue;
      const glm::vec3 expected =
          scalar_lighting(p, {normal[0][f], normal[1][f], normal[2][f]},
                          {batch->varyings[MeshVertexShader::kWorldPos][f], batch->varyings[MeshVertexShader::kWorldPos + 1][f],
                           batch->varyings[MeshVertexShader::kWorldPos + 2][f]},
                          {albedo[0][f], albedo[1][f], albedo[2][f]}, shadowed ? visibility[f] : 1.0f);
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(bits(rgb[c][f]), bits(expected[c])) << "round " << round << " fragment " << f << " channel " << c;
      }
    }
  }
}

// Lights that add +0 to every lit lane (radiance 0: the main light unlit, a point light out of
// range) are skipped per vector, except where adding their term changes the bits: a -0 ambient
// colour (-0 + +0 is +0) and a normal longer than 1 whose power overflows (+0 x inf is NaN).
TEST(UniversalLitLighting, SkippedLightsLeaveTheBitsOfTheTermOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
  auto batch = std::make_unique<FragmentBatch>();
  batch->quad_count = kBatchQuads;
  const int count = kBatchFragments;
  for (const std::string& target : simd_targets()) {
    force_simd_target(target);
    for (int round = 0; round < 2; ++round) {
      UniversalLitParams p;
      p.smoothness = 1.0f;  // shininess 2^11
      p.camera_position = {100.0f, 0.0f, 0.0f};
      p.ambient = {round == 0 ? -0.0f : 0.25f, 0.5f, 0.5f};
      p.main_light.to_light = {1.0f, 0.0f, 0.0f};
      p.main_light.radiance = glm::vec3(0.0f);
      AdditionalLight far;
      far.position = {0.0f, 100.0f, 0.0f};
      far.intensity = {3.0f, 2.0f, 1.0f};
      far.range = 1.0f;
      p.additional_lights[0] = far;
      p.additional_light_count = 1;
      alignas(64) float normal[3][kBatchFragments], albedo[4][kBatchFragments];
      for (int f = 0; f < count; ++f) {
        glm::vec3 n = random_unit(rng);
        if (f == 3) n = {1.3f, 0.0f, 0.0f};  // faces both lights, n_dot_h 1.3: pow overflows
        for (int c = 0; c < 3; ++c) {
          normal[c][f] = n[c];
          batch->varyings[MeshVertexShader::kWorldPos + c][f] = coordinate(rng);
        }
        for (int c = 0; c < 4; ++c) albedo[c][f] = 0.5f;
      }
      const uint64_t lit = ~uint64_t{0};
      alignas(64) float rgb[3][kBatchFragments];
      universal_lit_lighting(p, *batch, normal, albedo, nullptr, lit, count, rgb);
      for (int f = 0; f < count; ++f) {
        const glm::vec3 expected =
            scalar_lighting(p, {normal[0][f], normal[1][f], normal[2][f]},
                            {batch->varyings[MeshVertexShader::kWorldPos][f], batch->varyings[MeshVertexShader::kWorldPos + 1][f],
                             batch->varyings[MeshVertexShader::kWorldPos + 2][f]},
                            {albedo[0][f], albedo[1][f], albedo[2][f]}, 1.0f);
        if (f == 3) ASSERT_TRUE(std::isnan(expected[0])) << target;  // the case the skip must not take
        for (int c = 0; c < 3; ++c) {
          ASSERT_EQ(bits(rgb[c][f]), bits(expected[c])) << target << " round " << round << " fragment " << f << " channel " << c;
        }
      }
    }
  }
}

}  // namespace
}  // namespace ontile
