// Normal storage: the RG16_UNORM pixel format (exact Vulkan UNORM conversions), the octahedral
// map (exact on the axes, a float round trip), and the angular error of each stored encoding
// over 200k directions against its analytic bound.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <numbers>

#include "analysis/sweep_metrics.h"
#include "raster/pixel_format.h"
#include "shaders_cpp/normal_encoding.h"

namespace ontile {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

// Fibonacci sphere: n nearly uniform unit directions covering both hemispheres.
std::vector<glm::vec3> sphere_directions(int n) {
  std::vector<glm::vec3> dirs;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (i + 0.5) * 2.0 / n;
    const double r = std::sqrt(1.0 - z * z);
    dirs.push_back(glm::normalize(glm::vec3(glm::dvec3(r * std::cos(golden * i), r * std::sin(golden * i), z))));
  }
  return dirs;
}

TEST(Rg16Unorm, TableEntryAndExactConversions) {
  EXPECT_EQ(bytes_per_pixel(PixelFormat::RG16_UNORM), 4);
  EXPECT_EQ(channel_count(PixelFormat::RG16_UNORM), 2);
  EXPECT_FALSE(is_depth_format(PixelFormat::RG16_UNORM));
  EXPECT_STREQ(format_name(PixelFormat::RG16_UNORM), "rg16");
  EXPECT_EQ(parse_pixel_format("rg16"), PixelFormat::RG16_UNORM);

  // 0.5 * 65535 = 32767.5 rounds away from zero to 32768 (0x8000); little-endian R then G.
  uint8_t bytes[4];
  encode_pixel(PixelFormat::RG16_UNORM, glm::vec4(0.5f, 1.0f, 0.7f, 0.2f), bytes);
  EXPECT_EQ(bytes[0], 0x00);
  EXPECT_EQ(bytes[1], 0x80);
  EXPECT_EQ(bytes[2], 0xFF);
  EXPECT_EQ(bytes[3], 0xFF);
  const glm::vec4 decoded = decode_pixel(PixelFormat::RG16_UNORM, bytes);
  EXPECT_EQ(decoded, glm::vec4(32768.0f / 65535.0f, 1.0f, 0.0f, 1.0f));

  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (glm::vec4 v : {glm::vec4(-0.3f, 1.7f, 0, 0), glm::vec4(nan, 0.25f, 0, 0), glm::vec4(1e-6f, 0.999999f, 0, 0),
                      glm::vec4(0.123456f, 0.654321f, 9, 9)}) {
    encode_pixel(PixelFormat::RG16_UNORM, v, bytes);
    const glm::vec4 round_trip = decode_pixel(PixelFormat::RG16_UNORM, bytes);
    const glm::vec4 quantized = quantize_pixel(PixelFormat::RG16_UNORM, v);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(std::bit_cast<uint32_t>(quantized[c]), std::bit_cast<uint32_t>(round_trip[c]));
  }
  EXPECT_EQ(quantize_pixel(PixelFormat::RG16_UNORM, glm::vec4(-0.3f, 1.7f, 0, 0)), glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
  EXPECT_EQ(quantize_pixel(PixelFormat::RG16_UNORM, glm::vec4(nan, 0.0f, 0, 0)).x, 0.0f);
  // Every code round trips.
  for (uint32_t code = 0; code <= 0xFFFF; ++code) {
    const float f = unorm_to_float(code, 16);
    ASSERT_EQ(float_to_unorm(quantize_pixel(PixelFormat::RG16_UNORM, glm::vec4(f, f, 0, 0)).y, 16), code);
  }
}

TEST(Octahedral, AxesMapExactly) {
  const std::pair<glm::vec3, glm::vec2> cases[] = {
      {{0, 0, 1}, {0, 0}},  {{1, 0, 0}, {1, 0}},   {{-1, 0, 0}, {-1, 0}},
      {{0, 1, 0}, {0, 1}},  {{0, -1, 0}, {0, -1}}, {{0, 0, -1}, {1, 1}}};
  for (const auto& [n, e] : cases) {
    EXPECT_EQ(octahedral_encode(n), e) << n.x << " " << n.y << " " << n.z;
    EXPECT_EQ(octahedral_decode(e), n) << e.x << " " << e.y;
  }
  EXPECT_EQ(octahedral_encode(glm::vec3(0.0f)), glm::vec2(0.0f));
}

TEST(Octahedral, FloatRoundTripAndEveryEncodingWithinItsBound) {
  const std::vector<glm::vec3> dirs = sphere_directions(200000);
  double max_float = 0.0;
  double max_deg[3] = {0, 0, 0}, sum_deg[3] = {0, 0, 0};
  for (const glm::vec3& n : dirs) {
    const glm::vec2 e = octahedral_encode(n);
    ASSERT_LE(std::max(std::abs(e.x), std::abs(e.y)), 1.0f);  // inside the square; z < 0 outside the diamond
    max_float = std::max(max_float, angle_between_deg(octahedral_decode(e), n));
    for (NormalStorage s : all_normal_storages()) {
      const glm::vec4 stored = quantize_pixel(normal_storage_format(s), encode_normal(s, n));
      const double deg = angle_between_deg(decode_normal(s, stored), n);
      const int k = static_cast<int>(s);
      max_deg[k] = std::max(max_deg[k], deg);
      sum_deg[k] += deg;
    }
  }
  EXPECT_LT(max_float, 1e-4);  // float rounding only
  // Bounds from the half step h of each encoding (decoded vector error, then the angle):
  // RGB10A2: h = 1/1023 per component of n, |dn| <= sqrt(3) h.
  // RGBA16F: relative rounding 2^-11 per component, |dn| <= 2^-11.
  // oct RG16: h = 1/65535 per component of the octahedral point, the unnormalised decoded
  //   vector moves by at most sqrt(6) h and has length >= 1/sqrt(3): angle <= sqrt(18) h.
  const double bound_deg[3] = {std::sqrt(3.0) / 1023.0 * kRadToDeg, std::ldexp(1.0, -11) * kRadToDeg,
                               std::sqrt(18.0) / 65535.0 * kRadToDeg};
  for (NormalStorage s : all_normal_storages()) {
    const int k = static_cast<int>(s);
    EXPECT_LE(max_deg[k], bound_deg[k]) << normal_storage_name(s);
    EXPECT_GT(max_deg[k], 0.25 * bound_deg[k]) << normal_storage_name(s) << ": the bound is not loose";
    std::printf("%-9s max %.6f deg (bound %.6f), mean %.6f deg\n", normal_storage_name(s), max_deg[k], bound_deg[k],
                sum_deg[k] / dirs.size());
  }
  // 32 bits of octahedral RG16 beat 64 bits of RGBA16F and 32 bits of RGB10A2.
  EXPECT_LT(max_deg[2], max_deg[1]);
  EXPECT_LT(max_deg[1], max_deg[0]);
}

TEST(NormalStorage, NamesParseAndClearedPixelsDecodeToZero) {
  for (NormalStorage s : all_normal_storages()) EXPECT_EQ(parse_normal_storage(normal_storage_name(s)), s);
  EXPECT_FALSE(parse_normal_storage("oct").has_value());
  EXPECT_EQ(normal_storage_format(NormalStorage::OctRg16), PixelFormat::RG16_UNORM);
  EXPECT_EQ(decode_normal(NormalStorage::Rgb10a2, glm::vec4(0.0f)), glm::vec3(0.0f));
  EXPECT_EQ(decode_normal(NormalStorage::Rgba16f, glm::vec4(0.0f)), glm::vec3(0.0f));
}

}  // namespace
}  // namespace ontile
