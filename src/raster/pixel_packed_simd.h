// SIMD conversions between flat runs of channel values and their stored codes for the packed and
// 16/24-bit formats (RG11B10F's unsigned 11/10-bit floats, 16- and 24-bit UNORM, the D24S8
// stencil byte), used by the row functions of pixel_format.h. Each gives, value by value, the
// bits of the scalar conversion in pixel_format.cpp on every SIMD target.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/pixel_format.h"

namespace ontile {

// Unsigned small floats with 5 exponent bits and `mantissa_bits` (6: uf11, 5: uf10) mantissa
// bits: codes[i] = float_to_uf11_bits / float_to_uf10_bits(values[i]), values[i] = the decoded
// code, and the two in place (quantize).
void encode_unsigned_small_float_simd(const float* values, int count, int mantissa_bits,
                                      uint32_t* codes);
void decode_unsigned_small_float_simd(const uint32_t* codes, int count, int mantissa_bits,
                                      float* values);
void quantize_unsigned_small_float_simd(float* values, int count, int mantissa_bits);
// codes[i] = float_to_unorm(values[i], bits); values[i] = unorm_to_float(codes[i], bits).
void encode_unorm_codes_simd(const float* values, int count, int bits, uint32_t* codes);
void decode_unorm_codes_simd(const uint32_t* codes, int count, int bits, float* values);
// The D24S8 stencil byte of a value (nearest, clamped to 0..255, NaN -> 0), and the value it
// decodes to, in place.
void encode_stencil_simd(const float* values, int count, uint32_t* codes);
void quantize_stencil_simd(float* values, int count);

// quantize_pixels / encode_pixels / decode_pixels (pixel_format.h) for RG11B10F, RG16F, R32F,
// D32F (quantize only), D24S8, D16 and RG16 through the conversions above (pixel_rows_packed.cpp);
// false, doing nothing, for any other format.
bool quantize_packed_pixels(PixelFormat format, float* r, float* g, float* b, float* a, int count);
bool encode_packed_pixels(PixelFormat format, const glm::vec4* src, int count, uint8_t* dst);
bool decode_packed_pixels(PixelFormat format, const uint8_t* src, int count, glm::vec4* dst);

}  // namespace ontile
