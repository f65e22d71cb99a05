// The Sobel pass reading 10-bit normals as a view of the render target's surface (no decoded
// copy, as FrameExecutor::texture_of gives texel_source readers) against the decoded copy the
// context made before: the view's texels equal the copy's bit for bit, and whole batches shade
// the same colours with the same texel trace (the normal plane's granules at the copy's place).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "memory/trace_repeats.h"
#include "raster/pixel_format.h"
#include "raster/texel_trace.h"
#include "shaders/toon_test_support.h"
#include "shaders_cpp/full_screen.h"
#include "shaders_cpp/toon/sobel_edge_shader.h"

namespace ontile {
namespace {

bool same_bits(glm::vec4 a, glm::vec4 b) {
  for (int c = 0; c < 4; ++c)
    if (std::bit_cast<uint32_t>(a[c]) != std::bit_cast<uint32_t>(b[c])) return false;
  return true;
}

TEST(SobelSurfaceView, TenBitNormalViewShadesAndTracesAsTheDecodedCopy) {
  std::mt19937 rng(4242);
  const auto uniform = [&](float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(rng);
  };
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  constexpr int kW = 70, kH = 38;
  const float kDepths[] = {0.3f, 0.3f, 0.95f, 0.97f, 0.999f, 1.0f};
  const auto depth = test::make_float_texture(kW, kH, [&](int x, int y) {
    return glm::vec4(pick(8) == 0 ? kDepths[pick(6)] : kDepths[(x / 5 + 3 * (y / 4)) % 6], 0, 0, 1);
  });
  const auto color = test::make_float_texture(kW, kH, [&](int, int) {
    return glm::vec4(uniform(0, 1), uniform(0, 1), uniform(0, 1), 1.0f);
  });
  const auto border = test::make_float_texture(kW, kH, [&](int, int) {
    return glm::vec4(uniform(0, 1), uniform(0, 1), uniform(0, 1), 0.5f * static_cast<float>(pick(3)));
  });
  // Normals in blocks with noise and background zeros, stored as RGB10A2 (encode_pixels).
  std::vector<glm::vec4> encoded(static_cast<size_t>(kW) * kH);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const int roll = pick(10);
      glm::vec3 n = glm::normalize(glm::vec3(static_cast<float>((x / 3) % 4) - 1.5f,
                                             static_cast<float>((y / 4) % 3) - 1.0f, 2.0f));
      if (roll == 1) n = glm::normalize(glm::vec3(uniform(-1, 1), uniform(-1, 1), 1.0f));
      encoded[static_cast<size_t>(y) * kW + x] =
          roll == 0 ? glm::vec4(0.5f, 0.5f, 0.5f, 1.0f) : encode_view_normal(n, NormalEncoding::Unorm);
    }
  }
  std::vector<uint8_t> bytes(encoded.size() * 4);
  encode_pixels(PixelFormat::RGB10A2_UNORM, encoded.data(), static_cast<int>(encoded.size()),
                bytes.data());
  std::vector<glm::vec4> decoded(encoded.size());
  decode_pixels(PixelFormat::RGB10A2_UNORM, bytes.data(), static_cast<int>(bytes.size() / 4),
                decoded.data());
  std::vector<float> rgba(decoded.size() * 4);
  for (size_t i = 0; i < decoded.size(); ++i)
    for (int c = 0; c < 4; ++c) rgba[i * 4 + c] = decoded[i][c];
  const auto view = Texture2D::view_of_surface(kW, kH, PixelFormat::RGB10A2_UNORM, bytes.data(),
                                               "normals");
  const auto copy = Texture2D::from_surface_texels(kW, kH, std::move(rgba), 4, "normals");

  // The same texels and the same texel layout (bytes per texel) as the copy.
  const Texture2D::TexelView view_texels = view->texel_view(0), copy_texels = copy->texel_view(0);
  ASSERT_EQ(view_texels.memory_bytes_per_texel, copy_texels.memory_bytes_per_texel);
  ASSERT_EQ(view_texels.address % 64, copy_texels.address % 64);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      ASSERT_TRUE(same_bits(view_texels.load(x, y), copy_texels.load(x, y))) << x << "," << y;
  const uint64_t view_first = view_texels.address >> 6;
  const uint64_t view_last = (view_texels.address + uint64_t{kW} * kH * 4 - 1) >> 6;
  const uint64_t to_copy = (copy_texels.address >> 6) - view_first;

  auto batch = std::make_unique<FragmentBatch>();
  auto out_view = std::make_unique<BatchOutput>();
  auto out_copy = std::make_unique<BatchOutput>();
  const float thicknesses[] = {1.0f, 2.0f, 0.5f, 1.0f};
  int fragments = 0, normal_granules = 0, edges = 0;
  for (int config = 0; config < 8; ++config) {
    SobelEdgeParams p;
    p.color = color.get();
    p.depth = depth.get();
    p.border = config % 2 ? border.get() : nullptr;
    p.depth_linearization = DepthLinearization{false, 0.1f, 50.0f};
    p.view_ray_scale = glm::vec2(0.8f, 0.45f);
    p.thickness_px = thicknesses[config % 4];
    p.depth_threshold = uniform(0.01f, 0.3f);
    p.normal_threshold = uniform(0.5f, 2.5f);
    p.normal = view.get();
    const SobelEdgeShader view_shader(p);
    p.normal = copy.get();
    const SobelEdgeShader copy_shader(p);
    for (int b = 0; b < 24; ++b) {
      // 16x4 pixels of a 16-pixel tile anywhere, borders included; some partial, some jittered.
      const int tile_x = 16 * pick(kW / 16 + 1), tile_y = 2 * pick(kH / 2);
      batch->quad_count = kBatchQuads;
      batch->varying_count = 2;
      for (int q = 0; q < kBatchQuads; ++q) {
        const int x = tile_x + 2 * (q % 8), y = tile_y + 2 * (q / 8);
        batch->quad_x_px[q] = x;
        batch->quad_y_px[q] = y;
        batch->lane_mask[q] = b % 4 == 3 ? static_cast<uint8_t>(1 + pick(15)) : 0xF;
        for (int lane = 0; lane < kQuadLanes; ++lane) {
          glm::vec2 uv((x + (lane & 1) + 0.5f) / kW, (y + (lane >> 1) + 0.5f) / kH);
          if (b % 4 == 2) uv += glm::vec2(uniform(-0.5f, 0.5f) / kW, uniform(-0.5f, 0.5f) / kH);
          batch->varyings[FullScreenVertexShader::kUv][q * kQuadLanes + lane] = uv.x;
          batch->varyings[FullScreenVertexShader::kUv + 1][q * kQuadLanes + lane] = uv.y;
        }
      }
      std::vector<uint64_t> view_trace, copy_trace;
      {
        const TexelTraceScope scope(&view_trace);
        view_shader.shade_batch(*batch, *out_view);
      }
      {
        const TexelTraceScope scope(&copy_trace);
        copy_shader.shade_batch(*batch, *out_copy);
      }
      // Repeat entries (trace_repeats.h) expanded: only granules move to the copy's place.
      view_trace = expand_trace_repeats(view_trace);
      copy_trace = expand_trace_repeats(copy_trace);
      for (uint64_t& g : view_trace) {
        if (g >= view_first && g <= view_last) {
          g += to_copy;
          ++normal_granules;
        }
      }
      ASSERT_EQ(view_trace, copy_trace) << "config " << config << " batch " << b;
      for (int f = 0; f < batch->fragment_count(); ++f) {
        if (!batch->active(f)) continue;
        ++fragments;
        ASSERT_TRUE(same_bits(out_view->get(0, f), out_copy->get(0, f)))
            << "config " << config << " batch " << b << " fragment " << f;
        edges += !same_bits(out_view->get(0, f), color->texel_view(0).load(
            std::min(kW - 1, batch->quad_x_px[f / 4] + (f & 1)),
            std::min(kH - 1, batch->quad_y_px[f / 4] + ((f >> 1) & 1))));
      }
    }
  }
  EXPECT_GT(fragments, 8 * 24 * 40);
  EXPECT_GT(normal_granules, fragments);  // normals read at every fragment, all of them often
  EXPECT_GT(edges, fragments / 50);       // edges drawn: borders and the default colour
}

}  // namespace
}  // namespace ontile
