// Vertex snapping without libm: round_half_away_from_zero must return exactly what std::llround
// returns (ties, neighbours of ties, large and tiny values), and snap_vertex must give the bits
// the llround formula setup used before.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "raster/triangle_setup.h"

namespace ontile {
namespace {

double from_bits(uint64_t bits) {
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

// Counts mismatches so that a failure reports one example instead of millions of lines.
struct Checker {
  uint64_t checked = 0, mismatches = 0;
  double first_bad = 0.0;
  void check(double x) {
    ++checked;
    if (round_half_away_from_zero(x) != std::llround(x)) {
      if (mismatches++ == 0) first_bad = x;
    }
  }
  void check_both_signs(double x) {
    check(x);
    check(-x);
  }
};

TEST(SnapRounding, TiesAndTheirNeighboursMatchLlround) {
  Checker c;
  const double inf = std::numeric_limits<double>::infinity();
  // Every tie k + 0.5 of the guard band's subpixel range (|x| < 2^23).
  for (int64_t k = 0; k < (int64_t{1} << 23); ++k) {
    const double tie = static_cast<double>(k) + 0.5;
    c.check_both_signs(tie);
    c.check_both_signs(std::nextafter(tie, inf));
    c.check_both_signs(std::nextafter(tie, 0.0));
    c.check_both_signs(static_cast<double>(k));
    c.check_both_signs(std::nextafter(static_cast<double>(k), inf));
  }
  // The largest double below 0.5: adding 0.5 to it would round up to 1 (the classic bug).
  c.check_both_signs(std::nextafter(0.5, 0.0));
  EXPECT_EQ(c.mismatches, 0u) << "first mismatch at " << c.first_bad << " of " << c.checked;
  EXPECT_EQ(round_half_away_from_zero(std::nextafter(0.5, 0.0)), 0);
  EXPECT_EQ(round_half_away_from_zero(0.5), 1);
  EXPECT_EQ(round_half_away_from_zero(-0.5), -1);
  EXPECT_EQ(round_half_away_from_zero(-2.5), -3);
}

TEST(SnapRounding, EveryFloatOfTheFractionalBinadesMatchesLlround) {
  // Exhaustive over all doubles converted from floats in [2^-3, 2^3), both signs: the binades
  // where the fraction decides the result and ties are dense.
  Checker c;
  for (int exponent = -3; exponent < 3; ++exponent) {
    const float low = std::ldexp(1.0f, exponent);
    for (uint32_t m = 0; m < (1u << 23); ++m) {
      uint32_t bits;
      std::memcpy(&bits, &low, sizeof bits);
      bits += m;
      float f;
      std::memcpy(&f, &bits, sizeof f);
      c.check_both_signs(static_cast<double>(f));
    }
  }
  EXPECT_EQ(c.mismatches, 0u) << "first mismatch at " << c.first_bad << " of " << c.checked;
}

TEST(SnapRounding, RandomDoublesUpTo2To62MatchLlround) {
  Checker c;
  std::mt19937_64 rng(20240611);
  // Random bit patterns with biased exponents 0 (subnormals) .. 1023 + 61 (|x| < 2^62).
  std::uniform_int_distribution<uint64_t> exponent(0, 1023 + 61);
  std::uniform_int_distribution<uint64_t> mantissa(0, (uint64_t{1} << 52) - 1);
  for (int i = 0; i < 20'000'000; ++i) {
    const uint64_t bits = (exponent(rng) << 52) | mantissa(rng);
    c.check_both_signs(from_bits(bits));
  }
  // Around 2^52 (where doubles become integers) and 2^53, 2^62.
  for (int e : {51, 52, 53, 62}) {
    double x = std::ldexp(1.0, e);
    for (int i = 0; i < 1000; ++i) x = std::nextafter(x, 0.0);
    for (int i = 0; i < 2000; ++i, x = std::nextafter(x, 1e300)) c.check_both_signs(x);
  }
  c.check_both_signs(0.0);
  c.check_both_signs(std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(c.mismatches, 0u) << "first mismatch at " << c.first_bad << " of " << c.checked;
}

// The formula setup_triangle used before snap_vertex existed, with libm's llround.
SnappedVertex snap_with_llround(const glm::vec4& clip, int width, int height, int bits) {
  const double snap_scale = static_cast<double>(int64_t{1} << bits);
  const int64_t grid_step = kSubpixelScale >> bits;
  const double inv_w = 1.0 / static_cast<double>(clip.w);
  const double sx = (clip.x * inv_w * 0.5 + 0.5) * width;
  const double sy = (0.5 - clip.y * inv_w * 0.5) * height;
  SnappedVertex v;
  v.x_fp = static_cast<int32_t>(std::llround(sx * snap_scale) * grid_step);
  v.y_fp = static_cast<int32_t>(std::llround(sy * snap_scale) * grid_step);
  v.depth = static_cast<float>(clip.z * inv_w);
  v.inv_w = static_cast<float>(inv_w);
  return v;
}

TEST(SnapRounding, SnapVertexMatchesTheLlroundFormula) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> ndc(-30.0f, 30.0f);  // inside the 32768 px guard band
  std::uniform_real_distribution<float> w(0.01f, 1000.0f);
  std::uniform_int_distribution<int> tie(0, (1 << 18) - 1);
  uint64_t mismatches = 0;
  for (int i = 0; i < 2'000'000; ++i) {
    const float wi = w(rng);
    glm::vec4 clip(ndc(rng) * wi, ndc(rng) * wi, 0.5f * wi, wi);
    if (i % 4 == 0) {
      // Exactly halfway between two subpixels of a 1024-wide viewport (sx * 256 = k + 0.5):
      // sx = 512 * x_ndc + 512 = (2k + 1) / 512, all exact in float.
      clip = glm::vec4(static_cast<float>(2 * tie(rng) + 1) / 262144.0f - 1.0f, 0.25f, 0.5f,
                       1.0f);
    }
    for (int bits : {kMinSubpixelBits, kSubpixelBits}) {
      const SnappedVertex a = snap_vertex(clip, 1024, 768, bits);
      const SnappedVertex b = snap_with_llround(clip, 1024, 768, bits);
      mismatches += a.x_fp != b.x_fp || a.y_fp != b.y_fp ||
                    std::memcmp(&a.depth, &b.depth, sizeof a.depth) != 0 ||
                    std::memcmp(&a.inv_w, &b.inv_w, sizeof a.inv_w) != 0;
    }
  }
  EXPECT_EQ(mismatches, 0u);
}

}  // namespace
}  // namespace ontile
