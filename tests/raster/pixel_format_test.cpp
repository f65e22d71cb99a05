// Tests for pixel formats: sizes and names, exhaustive small-float round trips, known vectors of
// the Vulkan conversion rules, and quantize_pixel == decode_pixel(encode_pixel) bit for bit.
#include "raster/pixel_format.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace ontile {
namespace {

constexpr PixelFormat kAllFormats[] = {
    PixelFormat::RGBA8_UNORM,   PixelFormat::RGBA8_SRGB,   PixelFormat::RGB10A2_UNORM,
    PixelFormat::RG11B10_FLOAT, PixelFormat::RGBA16_FLOAT, PixelFormat::RG16_FLOAT,
    PixelFormat::R32_FLOAT,     PixelFormat::RGBA32_FLOAT, PixelFormat::D32_FLOAT,
    PixelFormat::D24S8,         PixelFormat::D16_UNORM};

uint32_t bits(float f) { return std::bit_cast<uint32_t>(f); }

glm::vec4 round_trip(PixelFormat format, glm::vec4 v) {
  uint8_t bytes[16];
  encode_pixel(format, v, bytes);
  return decode_pixel(format, bytes);
}

TEST(PixelFormat, SizesNamesAndParsing) {
  const int expected_bytes[] = {4, 4, 4, 4, 8, 4, 4, 16, 4, 4, 2};
  const char* expected_names[] = {"rgba8", "rgba8_srgb", "rgb10a2", "rg11b10f", "rgba16f", "rg16f",
                                  "r32f",  "rgba32f",    "d32f",    "d24s8",    "d16"};
  const int expected_channels[] = {4, 4, 4, 3, 4, 2, 1, 4, 1, 2, 1};
  for (int i = 0; i < 11; ++i) {
    const PixelFormat f = kAllFormats[i];
    EXPECT_EQ(bytes_per_pixel(f), expected_bytes[i]);
    EXPECT_EQ(bits_per_pixel(f), expected_bytes[i] * 8);
    EXPECT_STREQ(format_name(f), expected_names[i]);
    EXPECT_EQ(channel_count(f), expected_channels[i]);
    EXPECT_EQ(is_depth_format(f), i >= 8);
    ASSERT_TRUE(parse_pixel_format(expected_names[i]).has_value());
    EXPECT_EQ(*parse_pixel_format(expected_names[i]), f);
  }
  EXPECT_FALSE(parse_pixel_format("rgba9").has_value());
  EXPECT_FALSE(parse_pixel_format("").has_value());
  EXPECT_FALSE(parse_pixel_format("RGBA8").has_value());
}

TEST(PixelFormat, EveryHalfCodeRoundTrips) {
  for (uint32_t code = 0; code <= 0xFFFF; ++code) {
    const float f = half_bits_to_float(static_cast<uint16_t>(code));
    ASSERT_EQ(float_to_half_bits(f), code) << "half code " << code;
  }
}

TEST(PixelFormat, EveryUf11AndUf10CodeRoundTrips) {
  for (uint32_t code = 0; code < 2048; ++code) {
    ASSERT_EQ(float_to_uf11_bits(uf11_bits_to_float(code)), code) << "uf11 code " << code;
  }
  for (uint32_t code = 0; code < 1024; ++code) {
    ASSERT_EQ(float_to_uf10_bits(uf10_bits_to_float(code)), code) << "uf10 code " << code;
  }
  // Through the packed format too: R and G are 11-bit, B is 10-bit.
  for (uint32_t code = 0; code < 2048; ++code) {
    const uint32_t packed = code | ((2047 - code) << 11) | ((code & 0x3FF) << 22);
    uint8_t in[4], out[4];
    std::memcpy(in, &packed, 4);
    encode_pixel(PixelFormat::RG11B10_FLOAT, decode_pixel(PixelFormat::RG11B10_FLOAT, in), out);
    ASSERT_EQ(std::memcmp(in, out, 4), 0) << "packed code " << packed;
  }
}

TEST(PixelFormat, HalfKnownVectors) {
  EXPECT_EQ(float_to_half_bits(1.0f), 0x3C00);
  EXPECT_EQ(float_to_half_bits(-2.0f), 0xC000);
  EXPECT_EQ(float_to_half_bits(65504.0f), 0x7BFF);
  EXPECT_EQ(half_bits_to_float(0x7BFF), 65504.0f);
  EXPECT_EQ(float_to_half_bits(65519.99f), 0x7BFF);  // below the halfway point to 65536
  EXPECT_EQ(float_to_half_bits(65520.0f), 0x7C00);   // tie rounds to even: Inf
  EXPECT_EQ(float_to_half_bits(70000.0f), 0x7C00);
  EXPECT_EQ(float_to_half_bits(-70000.0f), 0xFC00);
  EXPECT_EQ(float_to_half_bits(std::ldexp(1.0f, -24)), 0x0001);  // smallest subnormal
  EXPECT_EQ(half_bits_to_float(0x0001), std::ldexp(1.0f, -24));
  EXPECT_EQ(float_to_half_bits(std::ldexp(1.0f, -25)), 0x0000);  // tie to even: 0
  EXPECT_EQ(float_to_half_bits(std::ldexp(1.5f, -25)), 0x0001);
  EXPECT_EQ(float_to_half_bits(std::ldexp(3.0f, -25)), 0x0002);  // 1.5 ulp tie -> even 2
  EXPECT_EQ(float_to_half_bits(std::ldexp(1.0f, -14)), 0x0400);  // smallest normal
  EXPECT_EQ(float_to_half_bits(1e-8f), 0x0000);
  EXPECT_EQ(float_to_half_bits(-0.0f), 0x8000);
  EXPECT_EQ(float_to_half_bits(1.0f + std::ldexp(1.0f, -11)), 0x3C00);  // tie -> even
  EXPECT_EQ(float_to_half_bits(1.0f + std::ldexp(3.0f, -11)), 0x3C02);  // tie -> even
  EXPECT_EQ(float_to_half_bits(std::numeric_limits<float>::infinity()), 0x7C00);
  const uint16_t nan_code = float_to_half_bits(std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(nan_code & 0x7C00, 0x7C00);
  EXPECT_NE(nan_code & 0x03FF, 0);
  // A NaN whose payload sits only below the kept bits must stay NaN, not become Inf.
  EXPECT_EQ(float_to_half_bits(std::bit_cast<float>(0x7F800001u)), 0x7E00);
}

TEST(PixelFormat, Uf11Uf10KnownVectors) {
  EXPECT_EQ(float_to_uf11_bits(1.0f), 15u << 6);
  EXPECT_EQ(float_to_uf10_bits(1.0f), 15u << 5);
  EXPECT_EQ(uf11_bits_to_float(0x7BF), 65024.0f);  // largest finite
  EXPECT_EQ(uf10_bits_to_float(0x3DF), 64512.0f);
  EXPECT_EQ(float_to_uf11_bits(70000.0f), 0x7BFu);  // finite overflow -> largest finite
  EXPECT_EQ(float_to_uf10_bits(1e30f), 0x3DFu);
  EXPECT_EQ(float_to_uf11_bits(std::numeric_limits<float>::infinity()), 0x7C0u);
  EXPECT_EQ(float_to_uf11_bits(-std::numeric_limits<float>::infinity()), 0u);
  EXPECT_EQ(float_to_uf11_bits(-1.0f), 0u);
  EXPECT_EQ(float_to_uf10_bits(-0.0f), 0u);
  EXPECT_EQ(float_to_uf11_bits(std::ldexp(1.0f, -20)), 1u);  // smallest subnormal
  EXPECT_EQ(float_to_uf10_bits(std::ldexp(1.0f, -19)), 1u);
  EXPECT_EQ(float_to_uf11_bits(std::ldexp(1.0f, -21)), 0u);              // tie -> even
  EXPECT_EQ(float_to_uf11_bits(1.0f + std::ldexp(1.0f, -7)), 15u << 6);  // tie -> even
  EXPECT_EQ(float_to_uf11_bits(1.0f + std::ldexp(3.0f, -7)), (15u << 6) | 2u);
  const uint32_t nan11 = float_to_uf11_bits(-std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(nan11 & 0x7C0u, 0x7C0u);  // negative NaN becomes positive NaN
  EXPECT_NE(nan11 & 0x3Fu, 0u);
}

TEST(PixelFormat, UnormAndSrgbKnownVectors) {
  uint8_t b[16];
  encode_pixel(PixelFormat::RGBA8_UNORM, {0.5f, 1.0f, -3.0f, std::nanf("")}, b);
  EXPECT_EQ(b[0], 128);  // 127.5 rounds half up
  EXPECT_EQ(b[1], 255);
  EXPECT_EQ(b[2], 0);
  EXPECT_EQ(b[3], 0);  // NaN -> 0
  EXPECT_EQ(float_to_unorm(126.5f / 255.0f, 8), 127u);
  EXPECT_EQ(unorm_to_float(128, 8), 128.0f / 255.0f);
  // sRGB: 0.5 linear encodes to 0.7354 * 255 = 187.52 -> 188; 0.0031308 is the linear knee.
  EXPECT_EQ(linear_to_srgb8(0.5f), 188);
  EXPECT_EQ(linear_to_srgb8(0.0f), 0);
  EXPECT_EQ(linear_to_srgb8(1.0f), 255);
  EXPECT_EQ(linear_to_srgb8(2.0f), 255);
  EXPECT_EQ(linear_to_srgb8(std::nanf("")), 0);
  EXPECT_EQ(linear_to_srgb8(0.0031308f), 10);  // 0.0031308 * 12.92 * 255 = 10.31
  EXPECT_EQ(srgb8_decode_table()[255], 1.0f);
  EXPECT_EQ(srgb8_decode_table()[10], static_cast<float>(10.0 / 255.0 / 12.92));
  EXPECT_EQ(srgb8_decode_table()[128],
            static_cast<float>(std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4)));
  for (int c = 0; c < 256; ++c) {
    ASSERT_EQ(linear_to_srgb8(srgb8_decode_table()[c]), c);
    ASSERT_EQ(float_to_unorm(unorm8_decode_table()[c], 8), static_cast<uint32_t>(c));
  }
  encode_pixel(PixelFormat::RGBA8_SRGB, {0.5f, 0.5f, 0.5f, 0.5f}, b);
  EXPECT_EQ(b[0], 188);
  EXPECT_EQ(b[3], 128);  // alpha stays linear
}

TEST(PixelFormat, SrgbEncodeMatchesTheExactOetf) {
  // Every 64th float in [0, 1]: the code is round-half-up of 255 * OETF(x), evaluated in double.
  for (uint32_t u = 0; u <= 0x3F800000u; u += 64) {
    const float x = std::bit_cast<float>(u);
    const double encoded =
        x <= 0.0031308 ? x * 12.92 : 1.055 * std::pow(double(x), 1 / 2.4) - 0.055;
    ASSERT_EQ(linear_to_srgb8(x), static_cast<int>(std::floor(encoded * 255.0 + 0.5))) << x;
  }
}

TEST(PixelFormat, PackedLayouts) {
  uint8_t b[16];
  encode_pixel(PixelFormat::RGB10A2_UNORM, {1.0f, 0.0f, 1.0f, 1.0f / 3.0f}, b);
  uint32_t p;
  std::memcpy(&p, b, 4);
  EXPECT_EQ(p, 0x3FFu | (0x3FFu << 20) | (1u << 30));  // R bits 0-9, B 20-29, A 30-31
  encode_pixel(PixelFormat::RG11B10_FLOAT, {1.0f, 2.0f, 0.5f, 0.0f}, b);
  std::memcpy(&p, b, 4);
  EXPECT_EQ(p, (15u << 6) | ((16u << 6) << 11) | ((14u << 5) << 22));
  EXPECT_EQ(decode_pixel(PixelFormat::RG11B10_FLOAT, b), glm::vec4(1.0f, 2.0f, 0.5f, 1.0f));
  encode_pixel(PixelFormat::D24S8, {1.0f, 7.4f, 0.0f, 0.0f}, b);
  std::memcpy(&p, b, 4);
  EXPECT_EQ(p, 0xFFFFFFu | (7u << 24));
  EXPECT_EQ(decode_pixel(PixelFormat::D24S8, b), glm::vec4(1.0f, 7.0f, 0.0f, 1.0f));
  encode_pixel(PixelFormat::D16_UNORM, {0.5f, 0.0f, 0.0f, 0.0f}, b);
  EXPECT_EQ(b[0] | (b[1] << 8), 32768);
  encode_pixel(PixelFormat::RG16_FLOAT, {1.0f, -2.0f, 5.0f, 5.0f}, b);
  EXPECT_EQ(b[0] | (b[1] << 8), 0x3C00);
  EXPECT_EQ(b[2] | (b[3] << 8), 0xC000);
  // Missing channels decode as G = B = 0, A = 1.
  EXPECT_EQ(decode_pixel(PixelFormat::RG16_FLOAT, b), glm::vec4(1.0f, -2.0f, 0.0f, 1.0f));
  encode_pixel(PixelFormat::R32_FLOAT, {0.25f, 9.0f, 9.0f, 9.0f}, b);
  EXPECT_EQ(decode_pixel(PixelFormat::R32_FLOAT, b), glm::vec4(0.25f, 0.0f, 0.0f, 1.0f));
}

TEST(PixelFormat, EveryD24AndD16CodeRoundTrips) {
  for (uint32_t code = 0; code < (1u << 24); ++code) {
    if (float_to_unorm(unorm_to_float(code, 24), 24) != code) FAIL() << "d24 code " << code;
  }
  for (uint32_t code = 0; code < (1u << 16); ++code) {
    ASSERT_EQ(float_to_unorm(unorm_to_float(code, 16), 16), code);
  }
  for (uint32_t code = 0; code < (1u << 10); ++code) {
    ASSERT_EQ(float_to_unorm(unorm_to_float(code, 10), 10), code);
  }
}

// Inputs covering every rounding regime of every format, plus a deterministic pseudo-random
// sweep over many exponents.
std::vector<float> quantize_inputs() {
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> v = {0.0f,
                          -0.0f,
                          1e-8f,
                          -1e-8f,
                          0.5f,
                          1.0f,
                          1.5f,
                          -1.0f,
                          70000.0f,
                          -70000.0f,
                          65504.0f,
                          65520.0f,
                          65024.0f,
                          65535.0f,
                          1e30f,
                          -1e30f,
                          inf,
                          -inf,
                          std::numeric_limits<float>::quiet_NaN(),
                          std::bit_cast<float>(0xFFC00001u),
                          std::bit_cast<float>(0x7F800001u),
                          std::numeric_limits<float>::denorm_min(),
                          0.0031308f,
                          254.6f,
                          255.5f,
                          0.99999994f,
                          1.0000001f,
                          127.5f / 255.0f,
                          0.5f / 1023.0f};
  uint32_t state = 12345u;
  for (int i = 0; i < 200000; ++i) {
    state = state * 1664525u + 1013904223u;  // LCG: fixed sequence, platform independent
    const uint32_t r = state;
    // Exponents -40 .. +23 around 1, random mantissa and sign.
    const uint32_t exponent = 127u - 40u + ((r >> 23) % 64u);
    v.push_back(std::bit_cast<float>((r & 0x807FFFFFu) | (exponent << 23)));
  }
  return v;
}

TEST(PixelFormat, QuantizeEqualsDecodeOfEncodeBitForBit) {
  const std::vector<float> inputs = quantize_inputs();
  for (PixelFormat f : kAllFormats) {
    for (size_t i = 0; i < inputs.size(); ++i) {
      const glm::vec4 v(inputs[i], inputs[(i + 1) % inputs.size()], inputs[(i + 7) % inputs.size()],
                        inputs[(i + 13) % inputs.size()]);
      const glm::vec4 q = quantize_pixel(f, v);
      const glm::vec4 d = round_trip(f, v);
      for (int c = 0; c < 4; ++c) {
        ASSERT_EQ(bits(q[c]), bits(d[c]))
            << format_name(f) << " input " << v[c] << " channel " << c;
      }
    }
  }
}

TEST(PixelFormat, QuantizedValuesAreStable) {
  // Quantizing twice changes nothing: tile memory written back unchanged keeps its value.
  const std::vector<float> inputs = quantize_inputs();
  for (PixelFormat f : kAllFormats) {
    for (float x : inputs) {
      const glm::vec4 once = quantize_pixel(f, glm::vec4(x, x, x, x));
      const glm::vec4 twice = quantize_pixel(f, once);
      for (int c = 0; c < 4; ++c)
        ASSERT_EQ(bits(once[c]), bits(twice[c])) << format_name(f) << " " << x;
    }
  }
  EXPECT_EQ(quantize_pixel(PixelFormat::RGBA16_FLOAT, glm::vec4(70000.0f)).x,
            std::numeric_limits<float>::infinity());
  EXPECT_EQ(quantize_pixel(PixelFormat::RG11B10_FLOAT, glm::vec4(70000.0f)).x, 65024.0f);
  EXPECT_EQ(quantize_pixel(PixelFormat::RG11B10_FLOAT, glm::vec4(-5.0f)).z, 0.0f);
  EXPECT_EQ(quantize_pixel(PixelFormat::RGBA8_UNORM, glm::vec4(0.5f)).x, 128.0f / 255.0f);
  EXPECT_TRUE(std::isnan(quantize_pixel(PixelFormat::RGBA16_FLOAT, glm::vec4(std::nanf(""))).x));
  EXPECT_EQ(quantize_pixel(PixelFormat::D16_UNORM, glm::vec4(std::nanf(""))).x, 0.0f);
}

}  // namespace
}  // namespace ontile
