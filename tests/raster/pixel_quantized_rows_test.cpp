// The quantised-value fast paths of the row and batch conversions against the per-pixel
// functions, bit for bit, on every SIMD target: encodes of rows holding every code's decoded
// value of RGBA8 (UNORM, sRGB) and RGB10A2, with one value nudged off its code at each position
// of a vector (the exact path takes over there), and quantisation of values at and one step
// either side of every UNORM threshold of 2, 8 and 10 bits and every sRGB threshold (as values
// and, for RGBA8, as tile memory's packed codes).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "raster/cell_raster.h"
#include "raster/pixel_format.h"
#include "raster/pixel_quantize_simd.h"
#include "raster/srgb8_tables.h"

namespace ontile {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

bool same_bits(const glm::vec4& a, const glm::vec4& b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }

void expect_rows_match(PixelFormat format, const std::vector<glm::vec4>& pixels, const std::string& what) {
  const int count = static_cast<int>(pixels.size());
  std::vector<uint8_t> row(static_cast<size_t>(count) * 4), expected(row.size());
  encode_pixels(format, pixels.data(), count, row.data());
  for (int i = 0; i < count; ++i) encode_pixel(format, pixels[i], expected.data() + 4 * i);
  for (int i = 0; i < count; ++i) {
    ASSERT_EQ(0, std::memcmp(row.data() + 4 * i, expected.data() + 4 * i, 4))
        << format_name(format) << " " << what << ", pixel " << i << ": " << pixels[i].x << " "
        << pixels[i].y << " " << pixels[i].z << " " << pixels[i].w;
  }
}

// Every code of each channel, decoded (R, G, B and A run through the codes at different
// offsets), in a row of `count` pixels (not a multiple of any vector width).
std::vector<glm::vec4> decoded_codes(PixelFormat format, int rgb_codes, int alpha_codes, int count) {
  std::vector<glm::vec4> pixels(count);
  for (int i = 0; i < count; ++i) {
    uint8_t bytes[4];
    if (format == PixelFormat::RGB10A2_UNORM) {
      const uint32_t word = static_cast<uint32_t>(i % rgb_codes) |
                            (static_cast<uint32_t>((i + 7) % rgb_codes) << 10) |
                            (static_cast<uint32_t>((i * 3 + 1) % rgb_codes) << 20) |
                            (static_cast<uint32_t>(i % alpha_codes) << 30);
      for (int k = 0; k < 4; ++k) bytes[k] = static_cast<uint8_t>(word >> (8 * k));
    } else {
      bytes[0] = static_cast<uint8_t>(i % rgb_codes);
      bytes[1] = static_cast<uint8_t>((i + 7) % rgb_codes);
      bytes[2] = static_cast<uint8_t>((i * 3 + 1) % rgb_codes);
      bytes[3] = static_cast<uint8_t>((i * 5 + 2) % alpha_codes);
    }
    pixels[i] = decode_pixel(format, bytes);
  }
  return pixels;
}

TEST(PixelRows, QuantizedRowsEncodeEveryCodeOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  struct Case {
    PixelFormat format;
    int rgb_codes, alpha_codes;
  };
  const Case cases[] = {{PixelFormat::RGBA8_SRGB, 256, 256},
                        {PixelFormat::RGBA8_UNORM, 256, 256},
                        {PixelFormat::RGB10A2_UNORM, 1024, 4}};
  for (const std::string& target : simd_targets()) {
    SCOPED_TRACE(target);
    force_simd_target(target);
    for (const Case& c : cases) {
      const std::vector<glm::vec4> pixels = decoded_codes(c.format, c.rgb_codes, c.alpha_codes, 2053);
      expect_rows_match(c.format, pixels, "every code");
      // -0 for +0, then one value off its code (a step up, a step down, NaN, -Inf) at each
      // channel of the first 20 pixels: the vector holding it, and what follows, go exactly.
      std::vector<glm::vec4> zeros = pixels;
      for (glm::vec4& p : zeros) {
        for (int ch = 0; ch < 4; ++ch) {
          if (p[ch] == 0.0f) p[ch] = -0.0f;
        }
      }
      expect_rows_match(c.format, zeros, "negative zeros");
      const float nudges[] = {1.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(),
                              -std::numeric_limits<float>::infinity()};
      for (int i = 0; i < 80; ++i) {
        std::vector<glm::vec4> row(pixels.begin(), pixels.begin() + 67);
        float& v = row[i / 4][i % 4];
        const float nudge = nudges[i % 4];
        v = std::isnan(nudge) || std::isinf(nudge) ? nudge : std::nextafter(v, nudge);
        expect_rows_match(c.format, row, "nudged value " + std::to_string(i));
      }
    }
  }
}

// Values at, and one float either side of, every threshold where a code starts.
std::vector<float> around_thresholds() {
  std::vector<float> values = {0.0f, -0.0f, 1.0f, -1.0f, 2.0f,
                               std::numeric_limits<float>::quiet_NaN(),
                               -std::numeric_limits<float>::quiet_NaN(),
                               std::numeric_limits<float>::infinity(),
                               -std::numeric_limits<float>::infinity(),
                               std::numeric_limits<float>::denorm_min(), 1e-30f};
  const auto around = [&](float x) {
    values.push_back(std::nextafter(x, -1.0f));
    values.push_back(x);
    values.push_back(std::nextafter(x, 2.0f));
  };
  for (const int bits : {2, 8, 10}) {
    const UnormThresholds& t = unorm_thresholds(bits);
    for (int k = 1; k < (1 << bits); ++k) around(t.at[k]);
  }
  const Srgb8Tables& srgb = srgb8_tables();
  for (int c = 0; c < 255; ++c) around(srgb.thresholds[c]);
  for (int b = 0; b < kSrgb8BucketCount; b += 5) {  // bucket edges
    around(std::bit_cast<float>(kSrgb8BucketLowestBits + (uint32_t(b) << (23 - kSrgb8BucketMantissaBits))));
  }
  return values;
}

TEST(PixelRows, QuantizeMatchesAtEveryThresholdOnEveryTarget) {
  const std::vector<float> values = around_thresholds();
  const int count = static_cast<int>(values.size());
  const AutomaticTargetOnExit restore;
  for (const std::string& target : simd_targets()) {
    SCOPED_TRACE(target);
    force_simd_target(target);
    for (const PixelFormat format :
         {PixelFormat::RGBA8_SRGB, PixelFormat::RGBA8_UNORM, PixelFormat::RGB10A2_UNORM}) {
      // Each channel gets the values at a different rotation.
      std::vector<float> ch[4];
      for (int c = 0; c < 4; ++c) {
        ch[c].resize(count);
        for (int i = 0; i < count; ++i) ch[c][i] = values[(i + 13 * c) % count];
      }
      std::vector<float> q[4] = {ch[0], ch[1], ch[2], ch[3]};
      quantize_pixels(format, q[0].data(), q[1].data(), q[2].data(), q[3].data(), count);
      for (int i = 0; i < count; ++i) {
        const glm::vec4 in(ch[0][i], ch[1][i], ch[2][i], ch[3][i]);
        ASSERT_TRUE(same_bits(quantize_pixel(format, in), glm::vec4(q[0][i], q[1][i], q[2][i], q[3][i])))
            << format_name(format) << " value " << i << ": " << in.x << " " << in.y << " " << in.z
            << " " << in.w;
      }
    }
  }
}

// The codes kernel of tile memory's code planes (TileMemory::holds_codes): encode_pixel's four
// bytes for the same values, every decoded code included (they give their own codes back).
TEST(PixelRows, Rgba8CodesMatchEncodeAtEveryThresholdOnEveryTarget) {
  std::vector<float> values = around_thresholds();
  for (int c = 0; c < 256; ++c) {
    values.push_back(srgb8_decode_table()[c]);
    values.push_back(unorm8_decode_table()[c]);
  }
  const int count = static_cast<int>(values.size());
  const AutomaticTargetOnExit restore;
  for (const std::string& target : simd_targets()) {
    SCOPED_TRACE(target);
    force_simd_target(target);
    for (const PixelFormat format : {PixelFormat::RGBA8_SRGB, PixelFormat::RGBA8_UNORM}) {
      std::vector<float> ch[4];
      for (int c = 0; c < 4; ++c) {
        ch[c].resize(count);
        for (int i = 0; i < count; ++i) ch[c][i] = values[(i + 13 * c) % count];
      }
      std::vector<uint32_t> codes(count);
      quantize_rgba8_codes_simd(ch[0].data(), ch[1].data(), ch[2].data(), ch[3].data(), count,
                                format == PixelFormat::RGBA8_SRGB, codes.data());
      for (int i = 0; i < count; ++i) {
        const glm::vec4 in(ch[0][i], ch[1][i], ch[2][i], ch[3][i]);
        uint8_t expected[4];
        encode_pixel(format, in, expected);
        ASSERT_EQ(0, std::memcmp(&codes[i], expected, 4))
            << format_name(format) << " value " << i << ": " << in.x << " " << in.y << " " << in.z
            << " " << in.w;
      }
    }
  }
}

// The codes of decoded codes (BatchOutput::output0_codes_of) by the cheaper kernel: each code.
TEST(PixelRows, Rgba8CodesOfDecodedCodesOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  for (const std::string& target : simd_targets()) {
    SCOPED_TRACE(target);
    force_simd_target(target);
    for (const PixelFormat format : {PixelFormat::RGBA8_SRGB, PixelFormat::RGBA8_UNORM}) {
      const std::vector<glm::vec4> pixels = decoded_codes(format, 256, 256, 1031);
      const int count = static_cast<int>(pixels.size());
      std::vector<float> ch[4];
      for (int c = 0; c < 4; ++c) {
        for (const glm::vec4& p : pixels) ch[c].push_back(p[c]);
      }
      std::vector<uint32_t> codes(count);
      rgba8_codes_of_decoded_simd(ch[0].data(), ch[1].data(), ch[2].data(), ch[3].data(), count,
                                  format == PixelFormat::RGBA8_SRGB, codes.data());
      for (int i = 0; i < count; ++i) {
        uint8_t expected[4];
        encode_pixel(format, pixels[i], expected);
        ASSERT_EQ(0, std::memcmp(&codes[i], expected, 4)) << format_name(format) << " pixel " << i;
      }
    }
  }
}

// The tables the fast paths rest on: each threshold is the first float reaching its code.
TEST(PixelRows, UnormThresholdsAreWhereCodesStart) {
  for (const int bits : {2, 8, 10}) {
    const UnormThresholds& t = unorm_thresholds(bits);
    for (uint32_t k = 1; k < (1u << bits); ++k) {
      EXPECT_EQ(k, float_to_unorm(t.at[k], bits)) << bits << " bits, code " << k;
      EXPECT_EQ(k - 1, float_to_unorm(std::nextafter(t.at[k], 0.0f), bits)) << bits << " bits, code " << k;
    }
  }
}

}  // namespace
}  // namespace ontile
