// Quantisation of shaded colours to the RGBA8 (UNORM, sRGB) and RGB10A2 formats on SIMD lanes,
// the four channel arrays of a batch in one call (quantize_pixels, pixel_format.h). Each gives,
// value by value, the bits of the scalar quantize_pixel on every SIMD target.
#pragma once
#include <cstdint>
#include <vector>

#include "raster/srgb8_tables.h"

namespace ontile {

// Exact UNORM rounding by comparison: at[k] (k = 1 .. 2^bits - 1) is the smallest float that
// float_to_unorm rounds to k or more, so a value's code is how many of them it reaches. at[0]
// is -Inf and at[2^bits] NaN (never reached), so a candidate code off by at most one is
// corrected by comparing with at[candidate] and at[candidate + 1].
struct UnormThresholds {
  explicit UnormThresholds(int bits);
  int bits;
  std::vector<float> at;
};
const UnormThresholds& unorm_thresholds(int bits);  // bits: 2, 8 or 10

// srgb8_tables.h's bucket starts with one more bucket for every value from 1 up (code 255), and
// its thresholds with NaN after the last code, so that no lane steps past 255.
struct SrgbQuantizeTables {
  alignas(64) int32_t bucket_start[kSrgb8BucketCount + 1];
  alignas(64) float thresholds[256];
  SrgbQuantizeTables();
};
const SrgbQuantizeTables& srgb_quantize_tables();

// r, g, b through linear_to_srgb8 and back, a through 8-bit UNORM (alpha is linear).
void quantize_srgb8_alpha_simd(float* r, float* g, float* b, float* a, int count);
// r, g, b at rgb_bits, a at alpha_bits UNORM, the two packed as rgb_bits | alpha_bits << 8
// (six arguments: all in registers, so callers can tail-call it).
constexpr int kUnormBits8_8 = 8 | 8 << 8;
constexpr int kUnormBits10_2 = 10 | 2 << 8;
void quantize_unorm_rgba_simd(float* r, float* g, float* b, float* a, int count, int bits);
// The 8-bit RGBA codes of r, g, b, a (sRGB or UNORM colour, UNORM alpha) packed per pixel
// as encode_pixel's four bytes read as a little-endian uint32_t (R in the lowest byte).
void quantize_rgba8_codes_simd(const float* r, const float* g, const float* b, const float* a,
                               int count, bool srgb, uint32_t* codes);
// quantize_rgba8_codes_simd where every value is a decoded code of the format (colour and
// alpha): cheaper, and only for such values (BatchOutput::output0_codes_of).
void rgba8_codes_of_decoded_simd(const float* r, const float* g, const float* b, const float* a,
                                 int count, bool srgb, uint32_t* codes);

}  // namespace ontile
