// Pixel conversions over runs of pixels (see pixel_format.h: quantize_pixels, encode_pixels,
// decode_pixels): one format dispatch per run, every format on SIMD lanes (pixel_format_simd.h,
// pixel_packed_simd.h).
#include <cstring>

#include "raster/pixel_format.h"
#include "raster/pixel_format_simd.h"
#include "raster/pixel_packed_simd.h"
#include "raster/srgb8_tables.h"

namespace ontile {

void quantize_pixels(PixelFormat format, float* r, float* g, float* b, float* a, int count) {
  switch (format) {
    case PixelFormat::RGBA8_SRGB:
      quantize_srgb8_simd(r, count);
      quantize_srgb8_simd(g, count);
      quantize_srgb8_simd(b, count);
      quantize_unorm_simd(a, count, 8);  // alpha is always linear
      return;
    case PixelFormat::RGBA8_UNORM:
      // Channel arrays one after another (a whole batch's output): one run of 4 * count values.
      if (g == r + count && b == g + count && a == b + count) {
        quantize_unorm_simd(r, 4 * count, 8);
        return;
      }
      [[fallthrough]];
    case PixelFormat::RGB10A2_UNORM: {
      const int bits = format == PixelFormat::RGBA8_UNORM ? 8 : 10;
      quantize_unorm_simd(r, count, bits);
      quantize_unorm_simd(g, count, bits);
      quantize_unorm_simd(b, count, bits);
      quantize_unorm_simd(a, count, format == PixelFormat::RGBA8_UNORM ? 8 : 2);
      return;
    }
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
