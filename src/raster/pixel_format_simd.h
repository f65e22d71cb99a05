// SIMD conversions of flat runs of channel values for the hot pixel formats (8-bit UNORM and
// sRGB, n-bit UNORM, RGB10A2, binary16), used by the row and batch functions of pixel_format.h. Each gives, value
// by value, the bits of the scalar conversion in pixel_format.cpp on every SIMD target.
#pragma once
#include <cstdint>

namespace ontile {

// values[i] = unorm_to_float(float_to_unorm(values[i], bits), bits), bits in 1..24.
void quantize_unorm_simd(float* values, int count, int bits);
// dst[i] = float_to_unorm(values[i], 8).
void encode_unorm8_simd(const float* values, int count, uint8_t* dst);
// RGBA8_SRGB pixels (4 floats each): dst[4 p + c] = linear_to_srgb8 for R, G, B and
// float_to_unorm(a, 8) for the linear alpha.
void encode_srgb8_alpha_simd(const float* rgba, int pixels, uint8_t* dst);
// dst[i] = table[src[i]] (a 256-entry decode table).
void decode_table8_simd(const uint8_t* src, int count, const float* table, float* dst);
// binary16: values[i] = quantize_half(values[i]); dst gets float_to_half_bits(values[i]) as 2
// little-endian bytes per value; decode_half_simd is half_bits_to_float of such bytes.
void quantize_half_simd(float* values, int count);
void encode_half_simd(const float* values, int count, uint8_t* dst);
void decode_half_simd(const uint8_t* src, int count, float* values);
// RGB10A2 (Vulkan A2B10G10R10_UNORM_PACK32) pixels from and to RGBA floats: encode_pixel and
// decode_pixel of that format, pixel by pixel.
void encode_rgb10a2_simd(const float* rgba, int pixels, uint8_t* dst);
void decode_rgb10a2_simd(const uint8_t* src, int pixels, float* rgba);

}  // namespace ontile
