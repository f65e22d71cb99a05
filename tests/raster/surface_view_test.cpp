// Texture2D::view_of_surface: sampling a render target in place gives the values and the texel
// trace (relative to the texture's base) of sampling a decoded copy of it, for every format,
// filter and SIMD target; and the view reads the surface's bytes, not a copy.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include "raster/cell_raster.h"
#include "raster/pixel_format.h"
#include "raster/texel_trace.h"
#include "raster/texture.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr int kWidth = 37, kHeight = 23;

// Pixels of `format` made by encoding random values, some outside [0, 1] and some negative, so
// every code path of the formats' decoders is reached.
std::vector<uint8_t> random_pixels(PixelFormat format, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(-0.25f, 1.5f);
  const int bytes = bytes_per_pixel(format);
  std::vector<uint8_t> pixels(static_cast<size_t>(kWidth) * kHeight * bytes);
  for (size_t p = 0; p < pixels.size() / bytes; ++p) {
    encode_pixel(format, {value(rng), value(rng), value(rng), value(rng)}, &pixels[p * bytes]);
  }
  return pixels;
}

std::shared_ptr<const Texture2D> decoded_copy(PixelFormat format,
                                              const std::vector<uint8_t>& pixels) {
  std::vector<glm::vec4> rgba(static_cast<size_t>(kWidth) * kHeight);
  decode_pixels(format, pixels.data(), static_cast<int>(rgba.size()), rgba.data());
  std::vector<float> floats(&rgba[0].x, &rgba[0].x + 4 * rgba.size());
  return Texture2D::from_surface_texels(kWidth, kHeight, std::move(floats),
                                        bytes_per_pixel(format), "copy");
}

// The trace as offsets from the texture's first granule (views and copies are different
// texture regions).
std::vector<uint64_t> relative(const std::vector<uint64_t>& granules, const Texture2D& t) {
  std::vector<uint64_t> out;
  for (const uint64_t g : granules) out.push_back(g - (t.base_address() >> 6));
  return out;
}

void expect_same_bits(const glm::vec4& a, const glm::vec4& b, const char* what) {
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(std::bit_cast<uint32_t>(a[c]), std::bit_cast<uint32_t>(b[c])) << what << " ch " << c;
  }
}

TEST(SurfaceView, SamplesAndTracesLikeADecodedCopy) {
  struct AutomaticTargetOnExit {
    ~AutomaticTargetOnExit() { force_simd_target(""); }
  } restore;
  const PixelFormat formats[] = {
      PixelFormat::RGBA8_UNORM, PixelFormat::RGBA8_SRGB,   PixelFormat::RGB10A2_UNORM,
      PixelFormat::RG11B10_FLOAT, PixelFormat::RGBA16_FLOAT, PixelFormat::RG16_FLOAT,
      PixelFormat::R32_FLOAT,   PixelFormat::RGBA32_FLOAT, PixelFormat::D32_FLOAT,
      PixelFormat::D24S8,       PixelFormat::D16_UNORM,    PixelFormat::RG16_UNORM};
  SamplerDesc linear;
  linear.wrap_u = WrapMode::ClampToEdge;
  SamplerDesc nearest;
  nearest.mag_filter = nearest.min_filter = FilterMode::Nearest;
  nearest.wrap_v = WrapMode::MirroredRepeat;
  for (const std::string& target : simd_targets()) {
    SCOPED_TRACE(target);
    force_simd_target(target);
    for (const PixelFormat format : formats) {
      SCOPED_TRACE(format_name(format));
      const std::vector<uint8_t> pixels = random_pixels(format, static_cast<uint32_t>(format));
      const auto view = Texture2D::view_of_surface(kWidth, kHeight, format, pixels.data(), "view");
      const auto copy = decoded_copy(format, pixels);
      EXPECT_EQ(view->memory_bytes_per_texel(), bytes_per_pixel(format));
      EXPECT_EQ(view->level_count(), 1);
      const Texture2D::TexelView texels = view->texel_view(0);
      for (int y = 0; y < kHeight; y += 3) {
        for (int x = 0; x < kWidth; x += 2) {
          expect_same_bits(view->fetch(0, x, y), copy->fetch(0, x, y), "fetch");
          expect_same_bits(texels.load(x, y), copy->fetch(0, x, y), "texel view");
        }
      }
      for (const SamplerDesc& sampler : {linear, nearest}) {
        for (int i = 0; i < 30; ++i) {
          // Quads of assorted sizes and positions, partly outside [0, 1].
          const glm::vec2 origin(-0.1f + 0.043f * i, 1.05f - 0.037f * i);
          const float step = (0.3f + 0.25f * i) / kWidth;
          const glm::vec2 uv[4] = {origin, origin + glm::vec2(step, 0.0f),
                                   origin + glm::vec2(0.0f, step), origin + glm::vec2(step)};
          glm::vec4 from_view[4], from_copy[4];
          std::vector<uint64_t> view_trace, copy_trace;
          {
            TexelTraceScope scope(&view_trace);
            view->sample_quad(sampler, uv, from_view);
          }
          {
            TexelTraceScope scope(&copy_trace);
            copy->sample_quad(sampler, uv, from_copy);
          }
          EXPECT_EQ(relative(view_trace, *view), relative(copy_trace, *copy)) << "quad " << i;
          for (int lane = 0; lane < 4; ++lane) expect_same_bits(from_view[lane], from_copy[lane], "sample");
        }
      }
    }
  }
}

TEST(SurfaceView, ReadsTheSurfaceBytesInPlace) {
  std::vector<uint8_t> pixels(4 * 2 * 2, 0);
  const auto view = Texture2D::view_of_surface(2, 2, PixelFormat::RGBA8_UNORM, pixels.data(), "v");
  EXPECT_EQ(view->fetch(0, 1, 1), glm::vec4(0.0f));
  pixels[4 * 3] = 255;  // pixel (1, 1), red
  EXPECT_EQ(view->fetch(0, 1, 1), glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
  EXPECT_THROW(Texture2D::view_of_surface(0, 2, PixelFormat::RGBA8_UNORM, pixels.data(), "v"),
               Error);
  EXPECT_THROW(Texture2D::view_of_surface(2, 2, PixelFormat::RGBA8_UNORM, nullptr, "v"), Error);
}

}  // namespace
}  // namespace ontile
