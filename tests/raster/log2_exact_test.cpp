// log2_exact (raster/log2_exact.h) gives the bits of the C library's log2f for every float but
// NaNs and negatives. All 2^32 floats take ~30 s, so this test walks every 61st float (all
// exponents, every mantissa pattern class) and every float of [0.5, 2], where the table
// intervals and the special case at 1 lie; the exhaustive comparison, run once, found no
// difference (docs/perf/session13-core.md).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>

#include "raster/log2_exact.h"

namespace ontile {
namespace {

bool same_bits(float x) {
  const float expected = std::log2(x);
  const float got = log2_exact(x);
  if (std::isnan(expected)) return std::isnan(got);
  return std::bit_cast<uint32_t>(expected) == std::bit_cast<uint32_t>(got);
}

TEST(Log2Exact, MatchesTheLibraryOnASampleOfAllFloats) {
  uint64_t mismatches = 0;
  for (uint64_t bits = 0; bits <= 0xFFFFFFFFu; bits += 61) {
    if (!same_bits(std::bit_cast<float>(static_cast<uint32_t>(bits)))) ++mismatches;
  }
  EXPECT_EQ(mismatches, 0u);
}

TEST(Log2Exact, MatchesTheLibraryOnEveryFloatFromHalfToTwo) {
  uint64_t mismatches = 0;
  for (uint32_t bits = std::bit_cast<uint32_t>(0.5f); bits <= std::bit_cast<uint32_t>(2.0f); ++bits) {
    if (!same_bits(std::bit_cast<float>(bits))) ++mismatches;
  }
  EXPECT_EQ(mismatches, 0u);
}

TEST(Log2Exact, SpecialValues) {
  EXPECT_EQ(log2_exact(1.0f), 0.0f);
  EXPECT_FALSE(std::signbit(log2_exact(1.0f)));
  EXPECT_EQ(log2_exact(0.0f), -INFINITY);
  EXPECT_EQ(log2_exact(-0.0f), -INFINITY);
  EXPECT_EQ(log2_exact(INFINITY), INFINITY);
  EXPECT_TRUE(std::isnan(log2_exact(-1.0f)));
  EXPECT_TRUE(std::isnan(log2_exact(NAN)));
  EXPECT_EQ(log2_exact(std::ldexp(1.0f, -149)), -149.0f);  // smallest subnormal
  for (int e = -126; e < 128; ++e) EXPECT_EQ(log2_exact(std::ldexp(1.0f, e)), static_cast<float>(e));
}

}  // namespace
}  // namespace ontile
