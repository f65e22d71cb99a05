// The lighting kernels on SIMD lanes (lighting_lanes.cpp, gbuffer_decode_lanes.cpp) against the
// scalar functions they replace, bit for bit on every SIMD target: the Schlick power against
// std::pow over a sweep of floats, the G-buffer decode and world-position reconstruction against
// decode_gbuffer and ViewReconstruction, and the batch framebuffer fetch against load().
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "raster/cell_raster.h"
#include "shaders_cpp/deferred/gbuffer_decode_lanes.h"
#include "shaders_cpp/lighting/schlick_power.h"

namespace ontile {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Every 61st float of [0, 1] (17.6 M values: among them some thousands where glibc's powf is
// not correctly rounded), both signs of the edges, subnormals, the underflow boundary of x^5
// (about 2^-25.2), values above 1 up to overflow, infinities and NaN.
std::vector<float> power_inputs() {
  std::vector<float> x;
  const uint32_t one = 0x3F800000u;
  for (uint32_t bits = 0; bits <= one; bits += 61) {
    float v;
    std::memcpy(&v, &bits, sizeof v);
    x.push_back(v);
  }
  for (float v = 0x1p-27f; v < 0x1p-24f; v = std::nextafter(v * 1.001f, 1.0f)) x.push_back(v);
  for (float v = 1.0f; v < 1e9f; v = v * 1.37f) x.push_back(v);
  const float specials[] = {0.0f, -0.0f, 1.0f, -1.0f, 0x1p-149f, 0x1p-126f, -0x1p-26f, -0.5f, -1e-3f, 1e-40f,
                            std::numeric_limits<float>::max(), std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()};
  for (const float v : specials) x.push_back(v);
  while (x.size() % 64 != 3) x.push_back(0.25f);  // a tail the vectors do not cover
  return x;
}

TEST(LightingLanes, SchlickPowerIsPowfOnEveryTarget) {
  const std::vector<float> x = power_inputs();
  std::vector<float> expected(x.size());
  for (size_t i = 0; i < x.size(); ++i) expected[i] = std::pow(x[i], 5.0f);
  for (size_t i = 0; i < x.size(); ++i) {
    ASSERT_TRUE(same_bits(schlick_power(x[i]), expected[i])) << "x = " << x[i];
  }
  const AutomaticTargetOnExit restore;
  std::vector<float> out(x.size());
  for (const std::string& target : simd_targets()) {
    SCOPED_TRACE(target);
    force_simd_target(target);
    schlick_power_lanes(x.data(), static_cast<int>(x.size()), out.data());
    for (size_t i = 0; i < x.size(); ++i) ASSERT_TRUE(same_bits(out[i], expected[i])) << "x = " << x[i];
  }
}

// Random G-buffer values (unsigned-normalised or signed normals, a zero normal, depths from 0 to
// just below 1) for fragments [0, count), of which some are lit.
GBufferLanes random_gbuffer(std::mt19937& rng, bool signed_normal, int count) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  GBufferLanes in;
  for (int f = 0; f < kBatchFragments; ++f) {
    in.x_px[f] = static_cast<int32_t>(unit(rng) * 1919.0f);
    in.y_px[f] = static_cast<int32_t>(unit(rng) * 1079.0f);
    in.depth[f] = f % 9 == 0 ? 0.0f : std::nextafter(1.0f, 0.0f) * unit(rng);
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 4; ++c) in.targets[k][c][f] = signed_normal ? 2.0f * unit(rng) - 1.0f : unit(rng);
    }
    if (f % 13 == 5) {
      for (int k = 0; k < 3; ++k) {
        for (int c = 0; c < 3; ++c) in.targets[k][c][f] = signed_normal ? 0.0f : 0.5f;  // zero normal
      }
    }
    if (f < count && f % 7 != 3) in.lit |= uint64_t{1} << f;
  }
  return in;
}

TEST(LightingLanes, GBufferDecodeMatchesDecodeGBufferOnEveryTarget) {
  ViewReconstruction view;
  const glm::dmat4 projection = glm::perspective(0.9, 16.0 / 9.0, 0.05, 300.0);
  const glm::dmat4 look = glm::lookAt(glm::dvec3(3.0, 2.0, 7.0), glm::dvec3(0.0, 0.5, 0.0), glm::dvec3(0.0, 1.0, 0.0));
  view.inverse_view_projection = glm::inverse(projection * look);
  view.camera_position = glm::dvec3(3.0, 2.0, 7.0);
  view.width_px = 1920;
  view.height_px = 1080;
  const AutomaticTargetOnExit restore;
  for (const std::string& target : simd_targets()) {
    SCOPED_TRACE(target);
    force_simd_target(target);
    std::mt19937 rng(77);
    for (const std::string& name : gbuffer_layout_names()) {
      SCOPED_TRACE(name);
      const GBufferLayout layout = gbuffer_layout(name);
      for (const int count : {4, 20, 64}) {
        const GBufferLanes in = random_gbuffer(rng, gbuffer_detail::is_float_format(layout.normal_format), count);
        BrdfBatch brdf;
        alignas(64) BatchVec3 normal, world, to_view;
        decode_gbuffer_lanes(layout, view, in, count, brdf, normal, world, to_view);
        for (int f = 0; f < count; ++f) {
          const bool lit = (in.lit >> f) & 1u;
          glm::vec4 targets[3];
          for (int k = 0; k < 3; ++k) {
            targets[k] = {in.targets[k][0][f], in.targets[k][1][f], in.targets[k][2][f], in.targets[k][3][f]};
          }
          const DecodedGBuffer g = decode_gbuffer(layout, targets);
          const glm::dvec3 w = view.world_position(in.x_px[f], in.y_px[f], in.depth[f]);
          const glm::vec3 expected_world = lit ? glm::vec3(w) : glm::vec3(0.0f);
          const glm::vec3 expected_to_view = lit ? view.to_view(w) : glm::vec3(0.0f);
          for (int c = 0; c < 3; ++c) {
            ASSERT_TRUE(same_bits(brdf.diffuse_color[c][f], lit ? g.brdf.diffuse_color[c] : 0.0f)) << f;
            ASSERT_TRUE(same_bits(brdf.f0[c][f], lit ? g.brdf.f0[c] : 0.0f)) << f;
            ASSERT_TRUE(same_bits(normal[c][f], lit ? g.normal[c] : 0.0f)) << f;
            ASSERT_TRUE(same_bits(world[c][f], expected_world[c])) << f;
            ASSERT_TRUE(same_bits(to_view[c][f], expected_to_view[c])) << f;
          }
          ASSERT_TRUE(same_bits(brdf.roughness[f], lit ? g.brdf.roughness : 0.0f)) << f;
        }
      }
    }
  }
}

// A fetch whose value names its pixel, sample and slot, read only through load().
class PixelNamingFetch final : public FramebufferFetch {
 public:
  glm::vec4 load(int input_slot, int x_px, int y_px, int sample) const override {
    return {static_cast<float>(x_px), static_cast<float>(y_px), static_cast<float>(sample),
            static_cast<float>(input_slot)};
  }
};

TEST(LightingLanes, BatchFetchReadsEveryLaneOfEveryQuad) {
  FragmentBatch batch;
  PixelNamingFetch fetch;
  batch.fetch = &fetch;
  batch.quad_count = 3;
  const int32_t xs[3] = {4, 10, 4}, ys[3] = {6, 6, 8};
  for (int q = 0; q < 3; ++q) {
    batch.quad_x_px[q] = xs[q];
    batch.quad_y_px[q] = ys[q];
  }
  batch.sample = 2;
  alignas(64) float channel[4][kBatchFragments];
  float* const out[4] = {channel[0], channel[1], channel[2], channel[3]};
  batch.inputs(1, out);
  for (int f = 0; f < batch.fragment_count(); ++f) {
    const glm::vec4 expected = batch.input(1, f);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(channel[c][f], expected[c]) << f << " " << c;
  }
  EXPECT_EQ(channel[0][5], 11.0f);  // quad 1, lane 1: (x + 1, y)
  EXPECT_EQ(channel[1][11], 9.0f);  // quad 2, lane 3: (x + 1, y + 1)
}

}  // namespace
}  // namespace ontile
