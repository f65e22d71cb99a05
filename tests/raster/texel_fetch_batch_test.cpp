// Batch texel fetches (raster/texel_fetch_batch.h) against Texture2D::fetch fragment by fragment:
// the same values bit for bit (load_texels) and the same texel trace (trace_fetches), for several
// textures read per fragment with different fragment masks, on every SIMD target.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "raster/cell_raster.h"
#include "raster/texel_fetch_batch.h"
#include "raster/texel_trace.h"
#include "raster/texture_batch_simd.h"

namespace ontile {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

TEST(TexelFetchBatch, MatchesFetchFragmentByFragment) {
  std::mt19937 rng(99);
  constexpr int kW = 37, kH = 23;
  std::vector<uint8_t> bytes(static_cast<size_t>(kW) * kH * 8);
  for (auto& b : bytes) b = static_cast<uint8_t>(rng());
  std::vector<uint8_t> depth_bytes(static_cast<size_t>(kW) * kH * 4);
  for (size_t i = 0; i < depth_bytes.size(); i += 4) {
    const float d = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
    std::memcpy(&depth_bytes[i], &d, 4);
  }
  std::vector<float> floats(static_cast<size_t>(kW) * kH * 4);
  for (auto& f : floats) f = std::uniform_real_distribution<float>(-2.0f, 2.0f)(rng);
  const std::shared_ptr<const Texture2D> textures[] = {
      Texture2D::view_of_surface(kW, kH, PixelFormat::D32_FLOAT, depth_bytes.data(), "depth"),
      Texture2D::view_of_surface(kW, kH, PixelFormat::RGBA8_UNORM, bytes.data(), "albedo"),
      Texture2D::view_of_surface(kW, kH, PixelFormat::RGB10A2_UNORM, bytes.data(), "normal"),
      Texture2D::view_of_surface(kW, kH, PixelFormat::RGBA16_FLOAT, bytes.data(), "light"),
      Texture2D::from_rgba32f(kW, kH, floats, "float"),
      Texture2D::from_rgba8(kW, kH, std::vector<uint8_t>(bytes.begin(), bytes.begin() + kW * kH * 4), true, "srgb"),
  };
  const AutomaticTargetOnExit restore;
  const std::vector<std::string> targets = simd_targets();
  for (int round = 0; round < 120; ++round) {
    force_simd_target(targets[round % targets.size()]);
    const int texture_count = 1 + round % 4;
    const Texture2D* chosen[4];
    Texture2D::TexelView views[4];
    for (int k = 0; k < texture_count; ++k) {
      chosen[k] = textures[(round + 2 * k) % std::size(textures)].get();
      ASSERT_TRUE(batch_fetch_view(*chosen[k], views[k]));
    }
    const int fragments = 4 * (1 + static_cast<int>(rng() % kBatchQuads));
    alignas(64) int32_t x[kBatchFragments] = {}, y[kBatchFragments] = {};
    for (int f = 0; f < fragments; ++f) {
      // Neighbours often share a granule, so consecutive repeats are dropped across textures too.
      x[f] = round % 2 ? f % kW : static_cast<int32_t>(rng() % kW);
      y[f] = round % 2 ? (f / kW) % kH : static_cast<int32_t>(rng() % kH);
    }
    uint64_t fetched[4];
    fetched[0] = (uint64_t{rng()} << 32 | rng()) & (fragments == 64 ? ~uint64_t{0} : (uint64_t{1} << fragments) - 1);
    for (int k = 1; k < 4; ++k) fetched[k] = fetched[0] & (uint64_t{rng()} << 32 | rng());
    std::vector<uint64_t> expected_trace{5}, trace{5};
    std::vector<glm::vec4> expected(static_cast<size_t>(4 * kBatchFragments));
    {
      const TexelTraceScope scope(&expected_trace);
      for (int f = 0; f < fragments; ++f) {
        for (int k = 0; k < texture_count; ++k) {
          if ((fetched[k] >> f) & 1u) expected[k * kBatchFragments + f] = chosen[k]->fetch(0, x[f], y[f]);
        }
      }
    }
    {
      const TexelTraceScope scope(&trace);
      trace_fetches(views, texture_count, x, y, fragments, fetched);
    }
    ASSERT_EQ(trace, expected_trace) << "round " << round;
    for (int k = 0; k < texture_count; ++k) {
      alignas(64) float out[4][kBatchFragments] = {};
      load_texels(views[k], x, y, (fragments + 15) & ~15, fetched[k], out);
      for (int f = 0; f < fragments; ++f) {
        if (!((fetched[k] >> f) & 1u)) continue;
        for (int c = 0; c < 4; ++c) {
          ASSERT_EQ(std::bit_cast<uint32_t>(out[c][f]), std::bit_cast<uint32_t>(expected[k * kBatchFragments + f][c]))
              << "round " << round << " texture " << k << " fragment " << f << " channel " << c;
        }
      }
    }
  }
}

}  // namespace
}  // namespace ontile
