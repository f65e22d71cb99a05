// 8-bit UNORM quantisation and encoding on 32-bit integer lanes (pixel_format_simd.cpp) give
// the bits of the scalar float_to_unorm / unorm_to_float: every float from 2^-10 to 1 (all
// 10 binades where the integer arithmetic decides the code) on the best target, and on every
// target the values around each code's rounding threshold, every exponent and the special
// values (NaN, infinities, zeros, subnormals, negatives).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "raster/cell_raster.h"
#include "raster/pixel_format.h"
#include "raster/pixel_format_simd.h"

namespace ontile {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

// Compares both kernels with the scalar conversions on `values`; returns the first mismatch.
std::string first_mismatch(const std::vector<float>& values) {
  std::vector<float> quantized = values;
  std::vector<uint8_t> codes(values.size());
  quantize_unorm_simd(quantized.data(), static_cast<int>(quantized.size()), 8);
  encode_unorm8_simd(values.data(), static_cast<int>(values.size()), codes.data());
  for (size_t i = 0; i < values.size(); ++i) {
    const uint32_t code = float_to_unorm(values[i], 8);
    const float expected = unorm_to_float(code, 8);
    if (std::bit_cast<uint32_t>(quantized[i]) != std::bit_cast<uint32_t>(expected) ||
        codes[i] != code) {
      return "value bits " + std::to_string(std::bit_cast<uint32_t>(values[i])) + ": quantised " +
             std::to_string(quantized[i]) + " (expected " + std::to_string(expected) +
             "), code " + std::to_string(codes[i]) + " (expected " + std::to_string(code) + ")";
    }
  }
  return "";
}

std::vector<float> edge_values() {
  std::vector<float> v = {0.0f, -0.0f, 1.0f, -1.0f, std::nextafter(1.0f, 0.0f), 2.0f,
                          std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::quiet_NaN(),
                          -std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::denorm_min(),
                          std::numeric_limits<float>::min(), 0x1p-9f, 0x1p-10f,
                          std::nextafter(0x1p-9f, 0.0f), std::nextafter(0x1p-9f, 1.0f)};
  // Around each code's threshold (c - 1/2) / 255 and each code's value c / 255.
  for (int c = 0; c <= 256; ++c) {
    for (const double centre : {(c - 0.5) / 255.0, c / 255.0}) {
      float f = static_cast<float>(centre);
      for (int step = 0; step < 4; ++step) f = std::nextafter(f, -1.0f);
      for (int step = 0; step < 9; ++step, f = std::nextafter(f, 2.0f)) v.push_back(f);
    }
  }
  // Every exponent, random significands and signs.
  std::mt19937 rng(255);
  for (uint32_t exponent = 0; exponent < 256; ++exponent) {
    for (int i = 0; i < 16; ++i) {
      const uint32_t bits = (exponent << 23) | (rng() & 0x7FFFFFu) | ((i & 1u) << 31);
      v.push_back(std::bit_cast<float>(bits));
    }
  }
  while (v.size() % 64 != 5) v.push_back(0.5f);  // a tail for the scalar remainder as well
  return v;
}

TEST(Unorm8Lanes, EveryFloatFromTwoToTheMinusTenToOneMatchesTheScalarConversion) {
  const uint32_t first = std::bit_cast<uint32_t>(0x1p-10f);
  const uint32_t end = std::bit_cast<uint32_t>(1.0f) + 1;
  std::vector<float> chunk;
  for (uint32_t bits = first; bits < end;) {
    chunk.clear();
    for (; bits < end && chunk.size() < (1u << 20); ++bits) chunk.push_back(std::bit_cast<float>(bits));
    const std::string mismatch = first_mismatch(chunk);
    ASSERT_EQ(mismatch, "");
  }
}

TEST(Unorm8Lanes, EdgeValuesMatchOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  const std::vector<float> values = edge_values();
  for (const std::string& target : simd_targets()) {
    force_simd_target(target);
    EXPECT_EQ(first_mismatch(values), "") << target;
  }
}

}  // namespace
}  // namespace ontile
