// sample_batch_nearest (raster/texture_batch_simd.h) against Texture2D::sample_quad quad by quad:
// the same values bit for bit and the same texel trace, for 8-bit, sRGB, float and surface-view
// (RGBA8, D32F, RGBA16F with every binary16 class) textures, uvs at centres, anywhere, on texel edges and non-finite, on every SIMD target.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "raster/cell_raster.h"
#include "raster/pixel_format.h"
#include "raster/texel_trace.h"
#include "raster/texture.h"
#include "raster/texture_batch_simd.h"

namespace ontile {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

SamplerDesc nearest_clamp() {
  SamplerDesc s;
  s.mag_filter = s.min_filter = FilterMode::Nearest;
  s.mipmap_mode = MipmapMode::None;
  s.wrap_u = s.wrap_v = WrapMode::ClampToEdge;
  return s;
}

TEST(TextureBatch, NearestBatchesMatchSampleQuadBitsAndTrace) {
  std::mt19937 rng(4242);
  constexpr int kW = 45, kH = 29;
  std::vector<uint8_t> bytes(static_cast<size_t>(kW) * kH * 4);
  for (auto& b : bytes) b = static_cast<uint8_t>(rng());
  std::vector<float> floats(static_cast<size_t>(kW) * kH * 4);
  for (auto& f : floats) f = std::uniform_real_distribution<float>(-2.0f, 2.0f)(rng);
  std::vector<uint8_t> depth_bytes(static_cast<size_t>(kW) * kH * 4);
  for (size_t i = 0; i < depth_bytes.size(); i += 4) {
    const float d = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
    std::memcpy(&depth_bytes[i], &d, 4);
  }
  // Random binary16 codes: zeros, subnormals, normals, infinities and NaNs of both signs.
  std::vector<uint8_t> half_bytes(static_cast<size_t>(kW) * kH * 8);
  for (auto& b : half_bytes) b = static_cast<uint8_t>(rng());
  const std::shared_ptr<const Texture2D> textures[] = {
      Texture2D::from_rgba8(kW, kH, bytes, false, "unorm8"),
      Texture2D::from_rgba8(kW, kH, bytes, true, "srgb8"),
      Texture2D::from_rgba32f(kW, kH, floats, "float"),
      Texture2D::view_of_surface(kW, kH, PixelFormat::RGBA8_UNORM, bytes.data(), "view8"),
      Texture2D::view_of_surface(kW, kH, PixelFormat::D32_FLOAT, depth_bytes.data(), "depth"),
      Texture2D::view_of_surface(kW, kH, PixelFormat::RGBA16_FLOAT, half_bytes.data(), "half"),
      // A texel size that is no power of two: granules of consecutive texels step unevenly.
      Texture2D::from_surface_texels(kW, kH, floats, 6, "six_bytes"),
  };
  constexpr int kTextures = static_cast<int>(std::size(textures));
  const float inf = std::numeric_limits<float>::infinity();
  const float odd[] = {-0.3f, 1.7f, 0.0f, 1.0f, -0.0f, std::nanf(""), inf, -inf, 3e7f, -1e30f};
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  auto u = std::make_unique<float[]>(kBatchFragments);
  auto v = std::make_unique<float[]>(kBatchFragments);
  int checked = 0;
  for (int round = 0; round < 240; ++round) {
    force_simd_target(targets[round % targets.size()]);
    const Texture2D& texture = *textures[round % kTextures];
    const int quads = 1 + static_cast<int>(rng() % kBatchQuads);
    const int kind = round % 4;  // centres, texel edges, anywhere, odd values
    for (int f = 0; f < kBatchFragments; ++f) {
      const int fc = std::min(f, quads * kQuadLanes - 1);  // padding repeats the last fragment
      std::uniform_real_distribution<float> any(-0.2f, 1.2f);
      const int x = static_cast<int>(rng() % kW), y = static_cast<int>(rng() % kH);
      float uf = (x + 0.5f) / kW, vf = (y + 0.5f) / kH;
      if (kind == 1) uf = static_cast<float>(x) / kW, vf = static_cast<float>(y) / kH;
      if (kind == 2) uf = any(rng), vf = any(rng);
      if (kind == 3 && rng() % 3 == 0) (rng() % 2 ? uf : vf) = odd[rng() % 10];
      if (fc == f) {
        u[f] = uf;
        v[f] = vf;
      } else {
        u[f] = u[fc];
        v[f] = v[fc];
      }
    }
    // A granule before: another one, or the first texel's (then a first read of it is merged).
    const uint64_t before = round % 3 == 0 ? texture.texel_address(0, 0, 0) >> 6 : 7;
    std::vector<uint64_t> expected_trace{before}, trace{before};
    glm::vec4 expected[kBatchFragments];
    {
      const TexelTraceScope scope(&expected_trace);
      for (int q = 0; q < quads; ++q) {
        glm::vec2 uv[kQuadLanes];
        for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = {u[q * 4 + lane], v[q * 4 + lane]};
        texture.sample_quad(nearest_clamp(), uv, &expected[q * 4]);
      }
    }
    alignas(64) float out[4][kBatchFragments];
    {
      const TexelTraceScope scope(&trace);
      ASSERT_TRUE(sample_batch_nearest(texture, nearest_clamp(), u.get(), v.get(),
                                       quads * kQuadLanes, out));
    }
    ASSERT_EQ(trace, expected_trace) << "round " << round;
    for (int f = 0; f < quads * kQuadLanes; ++f) {
      for (int c = 0; c < 4; ++c) {
        ASSERT_EQ(std::bit_cast<uint32_t>(out[c][f]), std::bit_cast<uint32_t>(expected[f][c]))
            << "round " << round << " fragment " << f << " channel " << c;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 240 * 8);
}

// Whole batches of a same-size copy (uv at texel centres, the blit's fragments) keep the trace of
// sample_quad when the granule before is the batch's first, and report the texels' RGBA8 format.
TEST(TextureBatch, CopyBatchesTraceAsSampleQuadAndReportTheirCodes) {
  constexpr int kW = 64, kH = 8;
  std::vector<uint8_t> bytes(static_cast<size_t>(kW) * kH * 4);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<uint8_t>(i * 37);
  const auto unorm = Texture2D::from_rgba8(kW, kH, bytes, false, "unorm8");
  const auto srgb = Texture2D::from_rgba8(kW, kH, bytes, true, "srgb8");
  const auto view = Texture2D::view_of_surface(kW, kH, PixelFormat::RGBA8_SRGB, bytes.data(), "view");
  const auto floats = Texture2D::from_rgba32f(kW, kH, std::vector<float>(kW * kH * 4, 0.5f), "float");
  const std::pair<const Texture2D*, std::optional<PixelFormat>> cases[] = {
      {unorm.get(), PixelFormat::RGBA8_UNORM}, {srgb.get(), PixelFormat::RGBA8_SRGB},
      {view.get(), PixelFormat::RGBA8_SRGB}, {floats.get(), std::nullopt}};
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  for (const std::string& target : targets) {
    force_simd_target(target);
    for (const auto& [texture, format] : cases) {
      // 16 quads of rows 2-3 from x = 16: the whole-tile batch order.
      alignas(64) float u[kBatchFragments], v[kBatchFragments];
      for (int f = 0; f < kBatchFragments; ++f) {
        u[f] = (16.0f + 2.0f * static_cast<float>(f / 4) + static_cast<float>(f & 1) + 0.5f) / kW;
        v[f] = (2.0f + static_cast<float>((f >> 1) & 1) + 0.5f) / kH;
      }
      const uint64_t first = texture->texel_address(0, 16, 2) >> 6;
      std::vector<uint64_t> expected_trace{first}, trace{first};
      glm::vec4 expected[kBatchFragments];
      {
        const TexelTraceScope scope(&expected_trace);
        for (int q = 0; q < kBatchQuads; ++q) {
          glm::vec2 uv[kQuadLanes];
          for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = {u[q * 4 + lane], v[q * 4 + lane]};
          texture->sample_quad(nearest_clamp(), uv, &expected[q * 4]);
        }
      }
      alignas(64) float out[4][kBatchFragments];
      std::optional<PixelFormat> codes_of = PixelFormat::RG16_FLOAT;
      {
        const TexelTraceScope scope(&trace);
        ASSERT_TRUE(sample_batch_nearest(*texture, nearest_clamp(), u, v, kBatchFragments, out, &codes_of));
      }
      EXPECT_EQ(trace, expected_trace) << target << " " << texture->name();
      EXPECT_EQ(codes_of, format) << texture->name();
      for (int f = 0; f < kBatchFragments; ++f) {
        for (int c = 0; c < 4; ++c) {
          ASSERT_EQ(std::bit_cast<uint32_t>(out[c][f]), std::bit_cast<uint32_t>(expected[f][c]));
        }
      }
    }
  }
}

// LoadTexelsKernel and the RGBA8 UNORM store check codes by one float division: it must give
// the decode table's value for every code, or those kernels fall back to table gathers.
TEST(TextureBatch, UnormCodesDecodeByOneDivision) {
  EXPECT_TRUE(unorm8_decodes_by_division());
}

// BatchOutput::output0_codes_of lets the batcher skip quantising decoded RGBA8 codes into an
// attachment of their format: quantize_pixels gives every code's value back, bit for bit.
TEST(TextureBatch, QuantisingDecodedRgba8CodesGivesThemBack) {
  for (const PixelFormat format : {PixelFormat::RGBA8_UNORM, PixelFormat::RGBA8_SRGB}) {
    const std::array<float, 256>& colour =
        format == PixelFormat::RGBA8_SRGB ? srgb8_decode_table() : unorm8_decode_table();
    alignas(64) float r[256], g[256], b[256], a[256];
    for (int c = 0; c < 256; ++c) {
      r[c] = g[c] = b[c] = colour[c];
      a[c] = unorm8_decode_table()[c];
    }
    quantize_pixels(format, r, g, b, a, 256);
    for (int c = 0; c < 256; ++c) {
      ASSERT_EQ(std::bit_cast<uint32_t>(r[c]), std::bit_cast<uint32_t>(colour[c])) << format_name(format) << " " << c;
      ASSERT_EQ(std::bit_cast<uint32_t>(b[c]), std::bit_cast<uint32_t>(colour[c]));
      ASSERT_EQ(std::bit_cast<uint32_t>(a[c]), std::bit_cast<uint32_t>(unorm8_decode_table()[c]));
      const glm::vec4 one = quantize_pixel(format, glm::vec4(colour[c], colour[c], colour[c], unorm8_decode_table()[c]));
      ASSERT_EQ(std::bit_cast<uint32_t>(one.x), std::bit_cast<uint32_t>(colour[c]));
      ASSERT_EQ(std::bit_cast<uint32_t>(one.w), std::bit_cast<uint32_t>(unorm8_decode_table()[c]));
    }
  }
}

// RGBA16F surfaces are sampled in place through half_decode_table: every code must decode as
// decode_pixel (the values the decoded copy held before) does, bit for bit.
TEST(TextureBatch, HalfFloatSurfaceTexelsDecodeAsDecodePixel) {
  std::vector<uint8_t> pixels(65536 / 4 * 8);
  for (uint32_t code = 0; code < 65536; ++code) {
    pixels[2 * code] = static_cast<uint8_t>(code);
    pixels[2 * code + 1] = static_cast<uint8_t>(code >> 8);
  }
  for (size_t texel = 0; texel < 65536 / 4; ++texel) {
    const glm::vec4 fast = Texture2D::load_surface_texel(PixelFormat::RGBA16_FLOAT, pixels.data(), texel);
    const glm::vec4 reference = decode_pixel(PixelFormat::RGBA16_FLOAT, pixels.data() + texel * 8);
    for (int c = 0; c < 4; ++c) {
      ASSERT_EQ(std::bit_cast<uint32_t>(fast[c]), std::bit_cast<uint32_t>(reference[c])) << "texel " << texel;
    }
  }
  EXPECT_TRUE(Texture2D::samples_in_place(PixelFormat::RGBA16_FLOAT));
}

TEST(TextureBatch, OtherSamplersAreLeftToSampleQuad) {
  const std::vector<uint8_t> bytes(16 * 4, 128);
  const auto texture = Texture2D::from_rgba8(4, 4, bytes, false, "t");
  float u[16] = {}, v[16] = {};
  alignas(64) float out[4][kBatchFragments];
  std::vector<uint64_t> trace;
  const TexelTraceScope scope(&trace);
  SamplerDesc linear = nearest_clamp();
  linear.mag_filter = FilterMode::Linear;
  EXPECT_FALSE(sample_batch_nearest(*texture, linear, u, v, 16, out));
  SamplerDesc repeat = nearest_clamp();
  repeat.wrap_v = WrapMode::Repeat;
  EXPECT_FALSE(sample_batch_nearest(*texture, repeat, u, v, 16, out));
  EXPECT_TRUE(trace.empty());
  EXPECT_TRUE(sample_batch_nearest(*texture, nearest_clamp(), u, v, 16, out));
  EXPECT_EQ(trace.size(), 1u);  // 16 reads of texel (0, 0): one granule
}

}  // namespace
}  // namespace ontile
