// Row conversions of the packed and 16/24-bit formats (see pixel_packed_simd.h): channels are
// gathered from and scattered to the RGBA rows in chunks, their codes computed on SIMD lanes
// (pixel_packed_simd.cpp, pixel_format_simd.h) and packed into the stored words here, byte by
// byte little-endian as encode_pixel does.
#include <algorithm>
#include <cstring>

#include "raster/packed_bytes.h"
#include "raster/pixel_format_simd.h"
#include "raster/pixel_packed_simd.h"

namespace ontile {
namespace {

constexpr int kChunkPixels = 64;

using namespace packed_bytes;

// Per-thread scratch of one chunk's channels and codes. Thread-local rather than on the stack:
// zeroed once (stack arrays would be zeroed per chunk, or GCC warns that the kernels may read
// them uninitialised, which it cannot see they do not).
struct ChunkBuffers {
  float values[4 * kChunkPixels];
  uint32_t codes[4 * kChunkPixels];
};

ChunkBuffers& chunk_buffers() {
  static thread_local ChunkBuffers buffers{};
  return buffers;
}

void fill(float* values, int count, float value) { std::fill_n(values, count, value); }

// Channels `first`..`first + channels - 1` of each pixel, pixel after pixel.
void gather_channels(const glm::vec4* src, int pixels, int first, int channels, float* out) {
  for (int p = 0; p < pixels; ++p) {
    for (int c = 0; c < channels; ++c) out[p * channels + c] = src[p][first + c];
  }
}

void encode_chunk(PixelFormat format, const glm::vec4* src, int pixels, uint8_t* dst) {
  ChunkBuffers& buffers = chunk_buffers();
  float* const values = buffers.values;
  uint32_t* const codes = buffers.codes;
  switch (format) {
    case PixelFormat::RG11B10_FLOAT:
      gather_channels(src, pixels, 0, 1, values);
      gather_channels(src, pixels, 1, 1, values + kChunkPixels);
      gather_channels(src, pixels, 2, 1, values + 2 * kChunkPixels);
      encode_unsigned_small_float_simd(values, pixels, 6, codes);
      encode_unsigned_small_float_simd(values + kChunkPixels, pixels, 6, codes + kChunkPixels);
      encode_unsigned_small_float_simd(values + 2 * kChunkPixels, pixels, 5, codes + 2 * kChunkPixels);
      for (int p = 0; p < pixels; ++p) {
        store_u32(dst + 4 * p, codes[p] | (codes[kChunkPixels + p] << 11) |
                                   (codes[2 * kChunkPixels + p] << 22));
      }
      return;
    case PixelFormat::RG16_FLOAT:
      gather_channels(src, pixels, 0, 2, values);
      encode_half_simd(values, 2 * pixels, dst);
      return;
    case PixelFormat::D16_UNORM:
    case PixelFormat::RG16_UNORM: {
      const int channels = format == PixelFormat::D16_UNORM ? 1 : 2;
      gather_channels(src, pixels, 0, channels, values);
      encode_unorm_codes_simd(values, channels * pixels, 16, codes);
      for (int i = 0; i < channels * pixels; ++i) store_u16(dst + 2 * i, codes[i]);
      return;
    }
    case PixelFormat::D24S8:
      gather_channels(src, pixels, 0, 1, values);
      gather_channels(src, pixels, 1, 1, values + kChunkPixels);
      encode_unorm_codes_simd(values, pixels, 24, codes);
      encode_stencil_simd(values + kChunkPixels, pixels, codes + kChunkPixels);
      for (int p = 0; p < pixels; ++p) store_u32(dst + 4 * p, codes[p] | (codes[kChunkPixels + p] << 24));
      return;
    default:
      return;
  }
}

void decode_chunk(PixelFormat format, const uint8_t* src, int pixels, glm::vec4* dst) {
  ChunkBuffers& buffers = chunk_buffers();
  float* const values = buffers.values;
  uint32_t* const codes = buffers.codes;
  switch (format) {
    case PixelFormat::RG11B10_FLOAT:
      for (int p = 0; p < pixels; ++p) {
        const uint32_t word = load_u32(src + 4 * p);
        codes[p] = word & 0x7FFu;
        codes[kChunkPixels + p] = (word >> 11) & 0x7FFu;
        codes[2 * kChunkPixels + p] = word >> 22;
      }
      decode_unsigned_small_float_simd(codes, pixels, 6, values);
      decode_unsigned_small_float_simd(codes + kChunkPixels, pixels, 6, values + kChunkPixels);
      decode_unsigned_small_float_simd(codes + 2 * kChunkPixels, pixels, 5, values + 2 * kChunkPixels);
      for (int p = 0; p < pixels; ++p) {
        dst[p] = {values[p], values[kChunkPixels + p], values[2 * kChunkPixels + p], 1.0f};
      }
      return;
    case PixelFormat::RG16_FLOAT:
      decode_half_simd(src, 2 * pixels, values);
      for (int p = 0; p < pixels; ++p) dst[p] = {values[2 * p], values[2 * p + 1], 0.0f, 1.0f};
      return;
    case PixelFormat::D16_UNORM:
    case PixelFormat::RG16_UNORM: {
      const int channels = format == PixelFormat::D16_UNORM ? 1 : 2;
      for (int i = 0; i < channels * pixels; ++i) codes[i] = load_u16(src + 2 * i);
      decode_unorm_codes_simd(codes, channels * pixels, 16, values);
      for (int p = 0; p < pixels; ++p) {
        dst[p] = channels == 1 ? glm::vec4(values[p], 0.0f, 0.0f, 1.0f)
                               : glm::vec4(values[2 * p], values[2 * p + 1], 0.0f, 1.0f);
      }
      return;
    }
    case PixelFormat::D24S8:
      for (int p = 0; p < pixels; ++p) codes[p] = load_u32(src + 4 * p) & 0xFFFFFFu;
      decode_unorm_codes_simd(codes, pixels, 24, values);
      for (int p = 0; p < pixels; ++p) {
        dst[p] = {values[p], static_cast<float>(load_u32(src + 4 * p) >> 24), 0.0f, 1.0f};
      }
      return;
    default:
      return;
  }
}

bool has_packed_rows(PixelFormat format) {
  switch (format) {
    case PixelFormat::RG11B10_FLOAT:
    case PixelFormat::RG16_FLOAT:
    case PixelFormat::D24S8:
    case PixelFormat::D16_UNORM:
    case PixelFormat::RG16_UNORM:
      return true;
    default:
      return false;
  }
}

}  // namespace

bool quantize_packed_pixels(PixelFormat format, float* r, float* g, float* b, float* a, int count) {
  switch (format) {
    case PixelFormat::RG11B10_FLOAT:
      quantize_unsigned_small_float_simd(r, count, 6);
      quantize_unsigned_small_float_simd(g, count, 6);
      quantize_unsigned_small_float_simd(b, count, 5);
      fill(a, count, 1.0f);
      return true;
    case PixelFormat::RG16_FLOAT:
      quantize_half_simd(r, count);
      quantize_half_simd(g, count);
      break;
    case PixelFormat::RG16_UNORM:
      quantize_unorm_simd(r, count, 16);
      quantize_unorm_simd(g, count, 16);
      break;
    case PixelFormat::R32_FLOAT:
    case PixelFormat::D32_FLOAT:
      fill(g, count, 0.0f);
      break;
    case PixelFormat::D16_UNORM:
      quantize_unorm_simd(r, count, 16);
      fill(g, count, 0.0f);
      break;
    case PixelFormat::D24S8:
      quantize_unorm_simd(r, count, 24);
      quantize_stencil_simd(g, count);
      break;
    default:
      return false;
  }
  // Every format above but RG11B10F: no blue channel, alpha 1 (Vulkan "Format Conversion").
  fill(b, count, 0.0f);
  fill(a, count, 1.0f);
  return true;
}

bool encode_packed_pixels(PixelFormat format, const glm::vec4* src, int count, uint8_t* dst) {
  if (!has_packed_rows(format)) return false;
  const int bytes = bytes_per_pixel(format);
  for (int first = 0; first < count; first += kChunkPixels) {
    encode_chunk(format, src + first, std::min(kChunkPixels, count - first), dst + bytes * first);
  }
  return true;
}

bool decode_packed_pixels(PixelFormat format, const uint8_t* src, int count, glm::vec4* dst) {
  if (!has_packed_rows(format)) return false;
  const int bytes = bytes_per_pixel(format);
  for (int first = 0; first < count; first += kChunkPixels) {
    decode_chunk(format, src + bytes * first, std::min(kChunkPixels, count - first), dst + first);
  }
  return true;
}

}  // namespace ontile
