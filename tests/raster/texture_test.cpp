// Tests for Texture2D: mip chain sizes and box filtering (linear space, odd sizes), exact
// nearest/bilinear sampling, wrap modes, LOD selection from quad derivatives, non-finite uv,
// and repeated fetches traced as separate sample instructions.
#include "raster/texture.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "raster/cell_raster.h"
#include "raster/pixel_format.h"
#include "raster/texel_trace.h"
#include "util/error.h"

namespace ontile {
namespace {

// width x height Float32 texture whose texel (x, y) is (x, y, x + 10 y, 1).
std::shared_ptr<const Texture2D> coordinate_texture(int width, int height) {
  std::vector<float> rgba;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      rgba.insert(rgba.end(), {float(x), float(y), float(x + 10 * y), 1.0f});
    }
  }
  return Texture2D::from_rgba32f(width, height, std::move(rgba), "coords");
}

// 8-bit texture with pseudo-random texels, so that every level holds different values.
std::shared_ptr<const Texture2D> noise_texture(int width, int height, bool srgb) {
  std::vector<uint8_t> rgba(size_t(width) * height * 4);
  uint32_t state = 7u;
  for (uint8_t& b : rgba) {
    state = state * 1664525u + 1013904223u;
    b = static_cast<uint8_t>(state >> 24);
  }
  return Texture2D::from_rgba8(width, height, std::move(rgba), srgb, "noise");
}

SamplerDesc sampler_of(FilterMode filter, MipmapMode mip, WrapMode wrap = WrapMode::Repeat) {
  SamplerDesc s;
  s.mag_filter = s.min_filter = filter;
  s.mipmap_mode = mip;
  s.wrap_u = s.wrap_v = wrap;
  return s;
}

// A quad at uv0 whose uv moves by (step_x_texels, 0) per pixel in x and (0, step_y_texels) per
// pixel in y, in level-0 texels.
void make_quad(const Texture2D& t, glm::vec2 uv0, float step_x_texels, float step_y_texels,
               glm::vec2 uv[4]) {
  const glm::vec2 dx(step_x_texels / t.width(), 0.0f), dy(0.0f, step_y_texels / t.height());
  uv[0] = uv0;
  uv[1] = uv0 + dx;
  uv[2] = uv0 + dy;
  uv[3] = uv0 + dx + dy;
}

TEST(Texture2D, MipChainSizes) {
  const auto t = noise_texture(256, 256, false);
  ASSERT_EQ(t->level_count(), 9);
  for (int level = 0; level < 9; ++level) {
    EXPECT_EQ(t->width(level), 256 >> level);
    EXPECT_EQ(t->height(level), 256 >> level);
  }
  const auto odd = coordinate_texture(5, 3);
  ASSERT_EQ(odd->level_count(), 3);
  EXPECT_EQ(odd->width(1), 2);
  EXPECT_EQ(odd->height(1), 1);
  EXPECT_EQ(odd->width(2), 1);
  EXPECT_EQ(odd->height(2), 1);
  EXPECT_EQ(noise_texture(1, 1, false)->level_count(), 1);
  EXPECT_EQ(noise_texture(8, 1, false)->level_count(), 4);
  EXPECT_EQ(t->bytes_per_texel(), 4);
  EXPECT_EQ(odd->bytes_per_texel(), 16);
  EXPECT_EQ(odd->encoding(), TexelEncoding::Float32);
  EXPECT_EQ(odd->name(), "coords");
}

TEST(Texture2D, BoxFilterOfCheckerIsExactAverage) {
  const auto f = Texture2D::from_rgba32f(2, 2, {0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0});
  EXPECT_EQ(f->fetch(1, 0, 0), glm::vec4(0.5f));
  const auto u = Texture2D::from_rgba8(2, 2,
                                       {0, 0, 0, 0, 200, 200, 200, 200,  //
                                        200, 200, 200, 200, 0, 0, 0, 0},
                                       false);
  EXPECT_EQ(u->fetch(1, 0, 0), glm::vec4(unorm8_decode_table()[100]));
  // 127.5 rounds half up, as float_to_unorm does.
  const auto half = Texture2D::from_rgba8(2, 2,
                                          {0, 0, 0, 0, 255, 255, 255, 255,  //
                                           255, 255, 255, 255, 0, 0, 0, 0},
                                          false);
  EXPECT_EQ(half->fetch(1, 0, 0), glm::vec4(unorm8_decode_table()[128]));
}

TEST(Texture2D, SrgbMipsAverageInLinearSpace) {
  // Black/white in sRGB average to linear 0.5, which encodes to sRGB 188 (not 128).
  const auto t = Texture2D::from_rgba8(2, 2,
                                       {0, 0, 0, 0, 255, 255, 255, 255,  //
                                        255, 255, 255, 255, 0, 0, 0, 0},
                                       true);
  const glm::vec4 level1 = t->fetch(1, 0, 0);
  EXPECT_EQ(level1.x, srgb8_decode_table()[188]);
  EXPECT_EQ(level1.z, srgb8_decode_table()[188]);
  EXPECT_EQ(level1.w, unorm8_decode_table()[128]);  // alpha is linear
  EXPECT_EQ(t->fetch(0, 1, 0).x, 1.0f);
  EXPECT_EQ(t->fetch(0, 0, 0).x, 0.0f);
}

TEST(Texture2D, OddSizesFoldTheLastRowAndColumn) {
  // 5x3 -> 2x1: texel 0 covers x 0..1, texel 1 covers x 2..4 (1/3 each); both cover y 0..2.
  const auto t = coordinate_texture(5, 3);
  EXPECT_EQ(t->fetch(1, 0, 0), glm::vec4(0.5f, 1.0f, 10.5f, 1.0f));
  EXPECT_EQ(t->fetch(1, 1, 0), glm::vec4(3.0f, 1.0f, 13.0f, 1.0f));
  EXPECT_EQ(t->fetch(2, 0, 0), glm::vec4(1.75f, 1.0f, 11.75f, 1.0f));
  const auto three =
      Texture2D::from_rgba8(3, 1, {0, 0, 0, 0, 3, 30, 90, 255, 6, 60, 180, 255}, false);
  ASSERT_EQ(three->level_count(), 2);
  const auto& unorm = unorm8_decode_table();
  EXPECT_EQ(three->fetch(1, 0, 0), glm::vec4(unorm[3], unorm[30], unorm[90], unorm[170]));
}

TEST(Texture2D, TexelCentresReturnTexelsExactly) {
  for (const auto& t : {noise_texture(8, 4, true), coordinate_texture(8, 4)}) {
    for (FilterMode filter : {FilterMode::Nearest, FilterMode::Linear}) {
      const SamplerDesc s = sampler_of(filter, MipmapMode::None);
      for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 8; ++x) {
          const glm::vec2 uv((x + 0.5f) / 8.0f, (y + 0.5f) / 4.0f);
          EXPECT_EQ(t->sample_lod(s, uv, 0.0f), t->fetch(0, x, y)) << x << "," << y;
        }
      }
    }
  }
}

TEST(Texture2D, BilinearHalfwayIsExactMean) {
  const auto t = noise_texture(8, 4, false);
  const SamplerDesc s = sampler_of(FilterMode::Linear, MipmapMode::None);
  for (int x = 0; x < 7; ++x) {
    const glm::vec2 uv((x + 1.0f) / 8.0f, 2.5f / 4.0f);
    EXPECT_EQ(t->sample_lod(s, uv, 0.0f), (t->fetch(0, x, 2) + t->fetch(0, x + 1, 2)) * 0.5f);
  }
  // Quarter of the way: weights 0.75 / 0.25 on the float texture give exact values.
  const auto c = coordinate_texture(8, 4);
  EXPECT_EQ(c->sample_lod(s, {2.75f / 8.0f, 1.5f / 4.0f}, 0.0f).x, 2.25f);
  // Repeat wraps the right neighbour of the last texel to texel 0: mean of x = 7 and x = 0.
  EXPECT_EQ(c->sample_lod(s, {1.0f, 1.5f / 4.0f}, 0.0f).x, 3.5f);
}

TEST(Texture2D, WrapModesWithNearest) {
  const auto t = coordinate_texture(4, 4);
  struct Case {
    WrapMode mode;
    float u;
    float expected_x;
  };
  const Case cases[] = {
      {WrapMode::Repeat, -0.25f, 3},        {WrapMode::Repeat, 1.25f, 1},
      {WrapMode::Repeat, -1.9f, 0},         {WrapMode::ClampToEdge, -0.25f, 0},
      {WrapMode::ClampToEdge, 1.25f, 3},    {WrapMode::MirroredRepeat, -0.25f, 0},
      {WrapMode::MirroredRepeat, 1.25f, 2},  // x = 5 is the first texel of the mirrored copy
      {WrapMode::MirroredRepeat, -0.3f, 1}, {WrapMode::MirroredRepeat, 1.8f, 0},
      {WrapMode::MirroredRepeat, 2.1f, 0},
  };
  for (const Case& c : cases) {
    const SamplerDesc s = sampler_of(FilterMode::Nearest, MipmapMode::None, c.mode);
    const glm::vec4 along_u = t->sample_lod(s, {c.u, 0.6f}, 0.0f);
    EXPECT_EQ(along_u.x, c.expected_x) << "u " << c.u << " mode " << int(c.mode);
    EXPECT_EQ(along_u.y, 2.0f);
    const glm::vec4 along_v = t->sample_lod(s, {0.6f, c.u}, 0.0f);
    EXPECT_EQ(along_v.y, c.expected_x) << "v " << c.u << " mode " << int(c.mode);
  }
  // Clamp with bilinear at the edge returns the edge texel exactly.
  const SamplerDesc clamp = sampler_of(FilterMode::Linear, MipmapMode::None, WrapMode::ClampToEdge);
  EXPECT_EQ(t->sample_lod(clamp, {0.0f, 0.0f}, 0.0f), t->fetch(0, 0, 0));
  EXPECT_EQ(t->sample_lod(clamp, {1.0f, 1.0f}, 0.0f), t->fetch(0, 3, 3));
}

TEST(Texture2D, QuadLodSelectsTheExpectedLevel) {
  const auto t = noise_texture(16, 16, false);
  // Level 2 is 4x4; these uvs are its texel centres (3, 1) and neighbours one pixel away.
  const glm::vec2 uv0(3.5f / 4.0f, 1.5f / 4.0f);
  glm::vec2 uv[4];
  glm::vec4 out[4];
  make_quad(*t, uv0, 4.0f, 4.0f, uv);  // 4 texels per pixel: lambda = 2
  SamplerDesc s = sampler_of(FilterMode::Nearest, MipmapMode::Nearest);
  t->sample_quad(s, uv, out);
  ASSERT_NE(t->fetch(2, 3, 1), t->fetch(1, 7, 3));
  ASSERT_NE(t->fetch(2, 3, 1), t->fetch(3, 1, 0));
  EXPECT_EQ(out[0], t->fetch(2, 3, 1));
  EXPECT_EQ(out[1], t->fetch(2, 0, 1));  // u = 4.5 / 4 repeats to texel 0
  EXPECT_EQ(out[2], t->fetch(2, 3, 2));
  EXPECT_EQ(out[3], t->fetch(2, 0, 2));
  // Anisotropic footprint: rho is the larger axis (4 texels), still level 2.
  make_quad(*t, uv0, 4.0f, 1.0f, uv);
  t->sample_quad(s, uv, out);
  EXPECT_EQ(out[0], t->fetch(2, 3, 1));
  // Nearest mip at lambda 1.5 rounds down (ceil(lambda + 0.5) - 1 = 1), at 1.75 up to 2.
  make_quad(*t, uv0, 2.0f, 2.0f, uv);  // lambda = 1
  s.lod_bias = 0.5f;
  t->sample_quad(s, uv, out);
  EXPECT_EQ(out[0], t->fetch(1, 7, 3));
  s.lod_bias = 0.75f;
  t->sample_quad(s, uv, out);
  EXPECT_EQ(out[0], t->fetch(2, 3, 1));
  // MipmapMode::None always uses level 0, even when minifying.
  s = sampler_of(FilterMode::Nearest, MipmapMode::None);
  make_quad(*t, uv0, 4.0f, 4.0f, uv);
  t->sample_quad(s, uv, out);
  EXPECT_EQ(out[0], t->fetch(0, 14, 6));
  // Beyond the last level lambda clamps to it: the 1x1 level.
  s = sampler_of(FilterMode::Nearest, MipmapMode::Linear);
  make_quad(*t, uv0, 1000.0f, 1000.0f, uv);
  t->sample_quad(s, uv, out);
  for (int lane = 0; lane < 4; ++lane) EXPECT_EQ(out[lane], t->fetch(4, 0, 0));
}

TEST(Texture2D, TrilinearBlendsNeighbouringLevels) {
  const auto t = noise_texture(16, 16, true);
  const glm::vec2 uv0(3.5f / 4.0f, 1.5f / 4.0f);  // texel centre on levels 0, 1 and 2
  glm::vec2 uv[4];
  glm::vec4 out[4];
  make_quad(*t, uv0, 2.0f, 2.0f, uv);  // lambda = 1, +0.5 bias = 1.5
  SamplerDesc s = sampler_of(FilterMode::Nearest, MipmapMode::Linear);
  s.lod_bias = 0.5f;
  t->sample_quad(s, uv, out);
  EXPECT_EQ(out[0], t->fetch(1, 7, 3) * 0.5f + t->fetch(2, 3, 1) * 0.5f);
  // Explicit LOD takes the same path: sample_lod(lod) adds the same bias.
  EXPECT_EQ(t->sample_lod(s, uv0, 1.0f), out[0]);
  s.lod_bias = 0.25f;  // lambda = 1.25: weights 0.75 / 0.25
  t->sample_quad(s, uv, out);
  EXPECT_EQ(out[0], t->fetch(1, 7, 3) * 0.75f + t->fetch(2, 3, 1) * 0.25f);
  // Magnification (lambda < 0) uses the mag filter on level 0.
  s = sampler_of(FilterMode::Linear, MipmapMode::Linear);
  s.mag_filter = FilterMode::Nearest;
  make_quad(*t, {5.25f / 16.0f, 9.75f / 16.0f}, 0.5f, 0.5f, uv);
  t->sample_quad(s, uv, out);
  EXPECT_EQ(out[0], t->fetch(0, 5, 9));
  // A degenerate quad (all lanes equal) has rho = 0: magnification, no NaN.
  for (glm::vec2& lane_uv : uv) lane_uv = {5.25f / 16.0f, 9.75f / 16.0f};
  t->sample_quad(s, uv, out);
  EXPECT_EQ(out[3], t->fetch(0, 5, 9));
}

TEST(Texture2D, NonFiniteAndHugeUvAreSafe) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const auto t = noise_texture(16, 8, true);
  const float bad[] = {nan, inf, -inf, 1e30f, -3e38f, 16777216.0f, -16777217.0f, 8388607.5f};
  for (WrapMode wrap : {WrapMode::Repeat, WrapMode::ClampToEdge, WrapMode::MirroredRepeat}) {
    for (FilterMode filter : {FilterMode::Nearest, FilterMode::Linear}) {
      for (MipmapMode mip : {MipmapMode::None, MipmapMode::Nearest, MipmapMode::Linear}) {
        const SamplerDesc s = sampler_of(filter, mip, wrap);
        for (float a : bad) {
          const glm::vec2 uv[4] = {{a, 0.3f}, {0.2f, a}, {a, a}, {0.5f, 0.5f}};
          glm::vec4 out[4];
          t->sample_quad(s, uv, out);
          for (const glm::vec4& v : out) {
            for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(v[c])) << a;
          }
          const glm::vec4 single = t->sample_lod(s, {a, a}, nan);
          for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(single[c])) << a;
        }
        // Non-finite uv is treated as 0.
        EXPECT_EQ(t->sample_lod(s, {nan, inf}, 0.0f), t->sample_lod(s, {0.0f, 0.0f}, 0.0f));
      }
    }
  }
  // Every float >= 2^24 is an even integer: Repeat maps it like u = 0.
  const SamplerDesc repeat = sampler_of(FilterMode::Nearest, MipmapMode::None);
  EXPECT_EQ(t->sample_lod(repeat, {1e30f, 0.0f}, 0.0f), t->fetch(0, 0, 0));
  EXPECT_EQ(t->sample_lod(repeat, {-16777218.0f, 0.0f}, 0.0f), t->fetch(0, 0, 0));
}

TEST(Texture2D, RejectsBadSizes) {
  EXPECT_THROW(Texture2D::from_rgba8(2, 2, std::vector<uint8_t>(15), false, "t"), Error);
  EXPECT_THROW(Texture2D::from_rgba8(0, 2, {}, false, "t"), Error);
  EXPECT_THROW(Texture2D::from_rgba32f(1, 1, std::vector<float>(3), "t"), Error);
  try {
    Texture2D::from_rgba8(2, 2, std::vector<uint8_t>(15), false, "albedo.png");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("albedo.png"), std::string::npos);
  }
}

// sample_quad(..., fetches = 2) stands for two identical sample instructions: the same value and
// the same texel trace as two calls, on the SIMD path (8-bit, linear; every SIMD target) and the
// general paths (Float32, nearest), whatever the granule the trace ended on before.
TEST(Texture2D, RepeatedFetchesTraceLikeSeparateSamples) {
  const auto noise = noise_texture(37, 29, true);
  const auto coords = coordinate_texture(16, 16);
  const std::pair<const Texture2D*, SamplerDesc> cases[] = {
      {noise.get(), sampler_of(FilterMode::Linear, MipmapMode::Linear)},
      {noise.get(), sampler_of(FilterMode::Linear, MipmapMode::None, WrapMode::ClampToEdge)},
      {noise.get(), sampler_of(FilterMode::Nearest, MipmapMode::Nearest)},
      {coords.get(), sampler_of(FilterMode::Linear, MipmapMode::Linear)},
  };
  int quads_with_merged_repeats = 0;
  struct AutomaticTargetOnExit {
    ~AutomaticTargetOnExit() { force_simd_target(""); }
  } restore;
  for (const std::string& target : simd_targets()) {
    SCOPED_TRACE(target);
    force_simd_target(target);
    for (const auto& [texture, sampler] : cases) {
      for (int i = 0; i < 40; ++i) {
        glm::vec2 uv[4];
        make_quad(*texture, {0.013f * i, 0.7f - 0.021f * i}, 0.25f + 0.2f * i, 0.5f + 0.1f * i, uv);
        std::vector<uint64_t> twice, repeated;
        glm::vec4 a[4], b[4], c[4];
        {
          TexelTraceScope scope(&twice);
          record_texel_address(static_cast<uint64_t>(i) << 20);  // a previous granule unrelated to the texture
          texture->sample_quad(sampler, uv, a);
          texture->sample_quad(sampler, uv, b);
        }
        {
          TexelTraceScope scope(&repeated);
          record_texel_address(static_cast<uint64_t>(i) << 20);
          texture->sample_quad(sampler, uv, c, 2);
        }
        EXPECT_EQ(repeated, twice) << texture->name() << " quad " << i;
        for (int lane = 0; lane < 4; ++lane) {
          for (int ch = 0; ch < 4; ++ch) {
            EXPECT_EQ(std::bit_cast<uint32_t>(c[lane][ch]), std::bit_cast<uint32_t>(b[lane][ch]));
            EXPECT_EQ(std::bit_cast<uint32_t>(a[lane][ch]), std::bit_cast<uint32_t>(b[lane][ch]));
          }
        }
        // The previous granule, then a footprint inside one granule that the repeat merges into:
        // the collapse across fetches is exercised.
        quads_with_merged_repeats += twice.size() == 2;
      }
    }
  }
  EXPECT_GT(quads_with_merged_repeats, 0);
}

}  // namespace
}  // namespace ontile
