// Pixel conversions over runs of pixels (see pixel_format.h: quantize_pixels, encode_pixels,
// decode_pixels, encode_pixel_rows): one format dispatch per run, every format on SIMD lanes
// (pixel_format_simd.h, pixel_packed_simd.h, pixel_quantize_simd.h); blocks of RGBA8 and RGB10A2
// rows take the already-quantised fast path (pixel_encode_quantized_simd.h) as far as it goes.
#include <cstring>

#include "raster/pixel_encode_quantized_simd.h"
#include "raster/pixel_format.h"
#include "raster/pixel_format_simd.h"
#include "raster/pixel_packed_simd.h"
#include "raster/pixel_quantize_simd.h"
#include "raster/srgb8_tables.h"

namespace ontile {

namespace {

// The formats without a whole-batch kernel of their own, apart so that quantize_pixels, called
// once per shaded batch and output, stays a branch and a tail call for the hot formats.
[[gnu::noinline]] void quantize_other_pixels(PixelFormat format, float* r, float* g, float* b,
                                             float* a, int count) {
  switch (format) {
    case PixelFormat::RGBA32_FLOAT:
      return;
    case PixelFormat::RGBA16_FLOAT:
      quantize_half_simd(r, count);
      quantize_half_simd(g, count);
      quantize_half_simd(b, count);
      quantize_half_simd(a, count);
      return;
    default:
      if (quantize_packed_pixels(format, r, g, b, a, count)) return;
      for (int i = 0; i < count; ++i) {
        const glm::vec4 q = quantize_pixel(format, {r[i], g[i], b[i], a[i]});
        r[i] = q.x;
        g[i] = q.y;
        b[i] = q.z;
        a[i] = q.w;
      }
  }
}

}  // namespace

void quantize_pixels(PixelFormat format, float* r, float* g, float* b, float* a, int count) {
  switch (format) {
    case PixelFormat::RGBA8_SRGB:
      return quantize_srgb8_alpha_simd(r, g, b, a, count);  // alpha is always linear
    case PixelFormat::RGBA8_UNORM:
      return quantize_unorm_rgba_simd(r, g, b, a, count, kUnormBits8_8);
    case PixelFormat::RGB10A2_UNORM:
      return quantize_unorm_rgba_simd(r, g, b, a, count, kUnormBits10_2);
    default:
      return quantize_other_pixels(format, r, g, b, a, count);
  }
}

void encode_pixels(PixelFormat format, const glm::vec4* src, int count, uint8_t* dst) {
  static_assert(sizeof(glm::vec4) == 4 * sizeof(float), "vec4 rows are flat float arrays");
  const float* values = &src[0].x;
  switch (format) {
    case PixelFormat::RGBA8_UNORM:
      encode_unorm8_simd(values, 4 * count, dst);
      return;
    case PixelFormat::RGBA8_SRGB:
      encode_srgb8_alpha_simd(values, count, dst);  // alpha is always linear
      return;
    case PixelFormat::RGBA32_FLOAT:
      std::memcpy(dst, values, sizeof(glm::vec4) * static_cast<size_t>(count));
      return;
    case PixelFormat::RGB10A2_UNORM:
      encode_rgb10a2_simd(values, count, dst);
      return;
    case PixelFormat::RGBA16_FLOAT:
      encode_half_simd(values, 4 * count, dst);
      return;
    case PixelFormat::R32_FLOAT:
    case PixelFormat::D32_FLOAT:
      for (int i = 0; i < count; ++i) std::memcpy(dst + 4 * i, &src[i].x, 4);
      return;
    default: {
      if (encode_packed_pixels(format, src, count, dst)) return;
      const int bytes = bytes_per_pixel(format);
      for (int i = 0; i < count; ++i) encode_pixel(format, src[i], dst + bytes * i);
    }
  }
}

void encode_pixel_rows(PixelFormat format, const glm::vec4* src, size_t src_row_pixels, int count,
                       int rows, uint8_t* dst, size_t dst_row_bytes) {
  const bool rgba8 = format == PixelFormat::RGBA8_UNORM || format == PixelFormat::RGBA8_SRGB;
  const bool quantized_path = rgba8 || format == PixelFormat::RGB10A2_UNORM;
  int y = 0;
  while (y < rows) {
    if (quantized_path) {
      const float* values = &src[y * src_row_pixels].x;
      uint8_t* out = dst + y * dst_row_bytes;
      y += rgba8 ? encode_quantized_rgba8_rows_simd(values, 4 * src_row_pixels, count, rows - y,
                                                    format == PixelFormat::RGBA8_SRGB, out,
                                                    dst_row_bytes)
                 : encode_quantized_rgb10a2_rows_simd(values, 4 * src_row_pixels, count, rows - y,
                                                      out, dst_row_bytes);
      if (y == rows) return;
    }
    // A row the quantised path stopped at (or every row of another format): the general path.
    encode_pixels(format, src + y * src_row_pixels, count, dst + y * dst_row_bytes);
    ++y;
  }
}

void decode_pixels(PixelFormat format, const uint8_t* src, int count, glm::vec4* dst) {
  float* values = &dst[0].x;
  switch (format) {
    case PixelFormat::RGBA8_UNORM:
      decode_table8_simd(src, 4 * count, unorm8_decode_table().data(), values);
      return;
    case PixelFormat::RGBA8_SRGB: {
      decode_table8_simd(src, 4 * count, srgb8_tables().decode.data(), values);
      const std::array<float, 256>& unorm = unorm8_decode_table();
      for (int i = 0; i < count; ++i) dst[i].w = unorm[src[4 * i + 3]];  // alpha is linear
      return;
    }
    case PixelFormat::RGBA32_FLOAT:
      std::memcpy(values, src, sizeof(glm::vec4) * static_cast<size_t>(count));
      return;
    case PixelFormat::RGB10A2_UNORM:
      decode_rgb10a2_simd(src, count, values);
      return;
    case PixelFormat::RGBA16_FLOAT:
      decode_half_simd(src, 4 * count, values);
      return;
    case PixelFormat::R32_FLOAT:
    case PixelFormat::D32_FLOAT:
      for (int i = 0; i < count; ++i) {
        float value;
        std::memcpy(&value, src + 4 * i, 4);
        dst[i] = {value, 0.0f, 0.0f, 1.0f};
      }
      return;
    default: {
      if (decode_packed_pixels(format, src, count, dst)) return;
      const int bytes = bytes_per_pixel(format);
      for (int i = 0; i < count; ++i) dst[i] = decode_pixel(format, src + bytes * i);
    }
  }
}

}  // namespace ontile
