// The row and batch conversions (quantize_pixels, encode_pixels, decode_pixels) against the
// per-pixel functions, bit for bit, for every format and on every SIMD target: values around
// every 8-bit UNORM and sRGB rounding boundary, the 16/24-bit UNORM, binary16, 11/10-bit float
// and stencil ties, specials (NaN, +-Inf, -0, subnormals) and
// random values, in runs whose lengths do not divide the vector width.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "raster/cell_raster.h"
#include "raster/pixel_format.h"

namespace ontile {
namespace {

constexpr PixelFormat kAllFormats[] = {
    PixelFormat::RGBA8_UNORM,  PixelFormat::RGBA8_SRGB,   PixelFormat::RGB10A2_UNORM,
    PixelFormat::RG11B10_FLOAT, PixelFormat::RGBA16_FLOAT, PixelFormat::RG16_FLOAT,
    PixelFormat::R32_FLOAT,    PixelFormat::RGBA32_FLOAT, PixelFormat::D32_FLOAT,
    PixelFormat::D24S8,        PixelFormat::D16_UNORM,    PixelFormat::RG16_UNORM};

// Channel values that exercise every rounding boundary of the 8- and 10-bit encodings.
std::vector<float> test_values() {
  std::vector<float> v = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 1e-30f, 1e-40f, -1e-40f,
                          std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity(),
                          std::nextafter(1.0f, 0.0f), std::nextafter(0.0f, 1.0f)};
  for (int c = 0; c < 1024; ++c) {
    for (const double denominator : {255.0, 1023.0}) {
      const float boundary = static_cast<float>((c + 0.5) / denominator);
      float x = boundary;
      for (int k = 0; k < 3; ++k) x = std::nextafter(x, 0.0f);
      for (int k = 0; k < 7; ++k, x = std::nextafter(x, 2.0f)) v.push_back(x);
    }
  }
  // sRGB boundaries: the linear values where the code changes, found by encoding.
  for (float x = 1.0f / 8192; x < 1.0f; x = std::nextafter(x * 1.0005f, 2.0f)) {
    if (linear_to_srgb8(x) != linear_to_srgb8(std::nextafter(x, 0.0f))) {
      float y = x;
      for (int k = 0; k < 2; ++k) y = std::nextafter(y, 0.0f);
      for (int k = 0; k < 5; ++k, y = std::nextafter(y, 2.0f)) v.push_back(y);
    }
  }
  // binary16 rounding: for exponents across the normal and subnormal range, the dropped 13
  // bits just below, at and above the tie, with even and odd kept mantissas, both signs; the
  // overflow threshold; NaNs whose payload lies only in the dropped bits.
  for (uint32_t exponent = 96; exponent <= 143; ++exponent) {
    for (const uint32_t kept : {0u, 1u, 2u, 0x3FEu, 0x3FFu}) {
      for (const uint32_t dropped : {0x0FFFu, 0x1000u, 0x1001u, 0x1FFFu}) {
        for (const uint32_t sign : {0u, 0x80000000u}) {
          v.push_back(std::bit_cast<float>(sign | (exponent << 23) | (kept << 13) | dropped));
        }
      }
    }
  }
  for (const float x : {65504.0f, 65519.99f, 65520.0f, 65536.0f, 5.9604645e-8f, 2.9802322e-8f,
                        8.940697e-8f, 6.1035156e-5f, 6.1035152e-5f}) {
    v.push_back(x);
    v.push_back(-x);
  }
  // Unsigned 11/10-bit floats (RG11B10F) drop 17 and 18 mantissa bits: the same patterns just
  // below, at and above their ties, over their normal and subnormal range.
  for (uint32_t exponent = 100; exponent <= 143; ++exponent) {
    for (const uint32_t kept : {0u, 1u, 0x1Eu, 0x1Fu, 0x3Eu, 0x3Fu}) {
      for (const int drop : {17, 18}) {
        const uint32_t tie = 1u << (drop - 1);
        for (const uint32_t dropped : {tie - 1, tie, tie + 1, 2 * tie - 1}) {
          v.push_back(std::bit_cast<float>((exponent << 23) | (kept << drop) | dropped));
        }
      }
    }
  }
  for (const float x : {65024.0f, 64512.0f, 65535.0f, 1e30f, 3.0e-5f}) v.push_back(x);
  // 16- and 24-bit UNORM ties (D16, RG16, D24S8 depth), and D24S8 stencil values around every
  // rounding tie k + 0.5 and past 255.
  for (int c = 0; c < 65535; c += 97) {
    for (const double denominator : {65535.0, 16777215.0}) {
      const float boundary = static_cast<float>((c + 0.5) / denominator);
      v.push_back(std::nextafter(boundary, 0.0f));
      v.push_back(boundary);
      v.push_back(std::nextafter(boundary, 2.0f));
    }
  }
  for (int k = -1; k <= 256; ++k) {
    const float tie = static_cast<float>(k) + 0.5f;
    v.push_back(std::nextafter(tie, -1000.0f));
    v.push_back(tie);
    v.push_back(std::nextafter(tie, 1000.0f));
    v.push_back(static_cast<float>(k));
  }
  v.push_back(std::bit_cast<float>(0x7F800001u));
  v.push_back(std::bit_cast<float>(0xFFC00001u));
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(-0.1f, 1.1f);
  for (int i = 0; i < 20000; ++i) v.push_back(unit(rng));
  return v;
}

bool same_bits(const glm::vec4& a, const glm::vec4& b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

void check_format(PixelFormat format, const std::vector<float>& values) {
  const int count = static_cast<int>(values.size() / 4) - 3;  // not a multiple of any width
  std::vector<glm::vec4> pixels(count);
  std::memcpy(pixels.data(), values.data(), sizeof(glm::vec4) * count);
  // quantize_pixels (SoA) == quantize_pixel.
  std::vector<float> r(count), g(count), b(count), a(count);
  for (int i = 0; i < count; ++i) {
    r[i] = pixels[i].x, g[i] = pixels[i].y, b[i] = pixels[i].z, a[i] = pixels[i].w;
  }
  quantize_pixels(format, r.data(), g.data(), b.data(), a.data(), count);
  for (int i = 0; i < count; ++i) {
    const glm::vec4 expected = quantize_pixel(format, pixels[i]);
    ASSERT_TRUE(same_bits(expected, glm::vec4(r[i], g[i], b[i], a[i])))
        << format_name(format) << " quantize, value " << i << ": " << pixels[i].x << " "
        << pixels[i].y << " " << pixels[i].z << " " << pixels[i].w;
  }
  // encode_pixels == encode_pixel, and decode_pixels == decode_pixel on the bytes.
  const int bytes = bytes_per_pixel(format);
  std::vector<uint8_t> row(static_cast<size_t>(count) * bytes), expected(row.size());
  encode_pixels(format, pixels.data(), count, row.data());
  for (int i = 0; i < count; ++i) encode_pixel(format, pixels[i], expected.data() + bytes * i);
  for (int i = 0; i < count; ++i) {
    ASSERT_EQ(0, std::memcmp(row.data() + bytes * i, expected.data() + bytes * i, bytes))
        << format_name(format) << " encode, value " << i << ": " << pixels[i].x;
  }
  std::vector<glm::vec4> decoded(count);
  decode_pixels(format, row.data(), count, decoded.data());
  for (int i = 0; i < count; ++i) {
    ASSERT_TRUE(same_bits(decode_pixel(format, row.data() + bytes * i), decoded[i]))
        << format_name(format) << " decode, pixel " << i;
  }
}

TEST(PixelRows, MatchPerPixelConversionsOnEveryTarget) {
  const std::vector<float> values = test_values();
  const AutomaticTargetOnExit restore;
  for (const std::string& target : simd_targets()) {
    SCOPED_TRACE(target);
    force_simd_target(target);
    for (const PixelFormat format : kAllFormats) check_format(format, values);
  }
}

// binary16 rows around every code: each half value, the floats one step either side of it and
// of the midpoint to the next code (ties), both signs, and every code decoded, NaNs included,
// on every target (the x86 targets from AVX2 up convert with F16C, the others with integers).
TEST(PixelRows, HalfFloatRowsMatchAroundEveryCode) {
  std::vector<float> values;
  std::vector<uint8_t> codes;
  for (uint32_t c = 0; c < 0x10000; ++c) {
    codes.push_back(static_cast<uint8_t>(c));
    codes.push_back(static_cast<uint8_t>(c >> 8));
    const float v = half_bits_to_float(static_cast<uint16_t>(c));
    if (std::isnan(v)) continue;
    values.push_back(v);
    values.push_back(std::nextafter(v, -1e30f));
    values.push_back(std::nextafter(v, 1e30f));
    if ((c & 0x7FFF) >= 0x7BFF) continue;  // the largest finite magnitude and Inf: no next code
    const float next = half_bits_to_float(static_cast<uint16_t>(c + 1));
    const float mid = static_cast<float>((static_cast<double>(v) + next) / 2.0);
    for (const float m : {std::nextafter(mid, v), mid, std::nextafter(mid, next)}) values.push_back(m);
  }
  values.push_back(std::numeric_limits<float>::quiet_NaN());  // a NaN in some vectors only
  while (values.size() % 4 != 3) values.push_back(0.5f);      // a run that no width divides
  const int count = static_cast<int>(values.size());
  const int code_count = static_cast<int>(codes.size() / 2);
  const AutomaticTargetOnExit restore;
  for (const std::string& target : simd_targets()) {
    SCOPED_TRACE(target);
    force_simd_target(target);
    std::vector<float> quantized = values;
    std::vector<float> zeros(count, 0.0f);
    std::vector<float> g = zeros, b = zeros, a = zeros;
    quantize_pixels(PixelFormat::RGBA16_FLOAT, quantized.data(), g.data(), b.data(), a.data(), count);
    std::vector<glm::vec4> pixels(count);
    for (int i = 0; i < count; ++i) pixels[i] = glm::vec4(values[i], 0.0f, 0.0f, 0.0f);
    std::vector<uint8_t> row(static_cast<size_t>(count) * 8);
    encode_pixels(PixelFormat::RGBA16_FLOAT, pixels.data(), count, row.data());
    for (int i = 0; i < count; ++i) {
      const uint16_t expected = float_to_half_bits(values[i]);
      const float expected_value = half_bits_to_float(expected);
      ASSERT_EQ(0, std::memcmp(&expected_value, &quantized[i], sizeof(float))) << "value " << values[i];
      ASSERT_EQ(expected, static_cast<uint16_t>(row[8 * i] | (row[8 * i + 1] << 8))) << "value " << values[i];
    }
    // Every code as the R channel of RGBA16F pixels (G, B, A zero).
    std::vector<uint8_t> encoded(static_cast<size_t>(code_count) * 8, 0);
    for (int c = 0; c < code_count; ++c) {
      encoded[8 * c] = codes[2 * c];
      encoded[8 * c + 1] = codes[2 * c + 1];
    }
    std::vector<glm::vec4> decoded(code_count);
    decode_pixels(PixelFormat::RGBA16_FLOAT, encoded.data(), code_count, decoded.data());
    for (int c = 0; c < code_count; ++c) {
      const float expected = half_bits_to_float(static_cast<uint16_t>(c));
      ASSERT_EQ(0, std::memcmp(&expected, &decoded[c].x, sizeof(float))) << "code " << c;
    }
  }
}

// Every byte of every 8-bit channel decodes and re-encodes to itself through the rows.
TEST(PixelRows, EightBitRoundTripIsExact) {
  std::vector<uint8_t> bytes(256 * 4);
  for (int i = 0; i < 256 * 4; ++i) bytes[i] = static_cast<uint8_t>(i / 4);
  for (const PixelFormat format : {PixelFormat::RGBA8_UNORM, PixelFormat::RGBA8_SRGB}) {
    std::vector<glm::vec4> decoded(256);
    decode_pixels(format, bytes.data(), 256, decoded.data());
    std::vector<uint8_t> again(bytes.size());
    encode_pixels(format, decoded.data(), 256, again.data());
    EXPECT_EQ(bytes, again) << format_name(format);
  }
}

}  // namespace
}  // namespace ontile
