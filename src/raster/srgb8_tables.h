// The exact 8-bit sRGB encode/decode tables shared by the scalar conversions (pixel_format.cpp)
// and their SIMD row versions (pixel_format_simd.cpp), so both give the same codes.
#pragma once
#include <array>
#include <cstdint>

namespace ontile {

// Encoding rounds the exact OETF to the nearest code: the code of x is the number of
// thresholds <= x. bucket_start[] gives that count at the start of each bucket of
// 2^-kSrgb8BucketMantissaBits of an octave in [2^-13, 1); below 2^-13 every input encodes to 0
// (thresholds[0] ~ 1.5e-4 > 2^-13). Buckets are narrower than the spacing of thresholds, so a
// scan from bucket_start takes at most one step.
constexpr int kSrgb8BucketMantissaBits = 7;
constexpr uint32_t kSrgb8BucketLowestBits = 0x39000000u;  // 2^-13
constexpr int kSrgb8BucketCount = 13 << kSrgb8BucketMantissaBits;

struct Srgb8Tables {
  std::array<float, 256> decode;      // code -> linear, the exact EOTF rounded to float
  std::array<float, 256> thresholds;  // [255] = +Inf: never reached, keeps the compare in range
  std::array<int32_t, kSrgb8BucketCount> bucket_start;  // int32 so SIMD lanes can gather it
  Srgb8Tables();
};

const Srgb8Tables& srgb8_tables();

}  // namespace ontile
