// The drivers' tile-size rules (tiler/tile_size_rules.h) as tables: for each attachment set the
// tile size equals what the rule gives by hand (the arithmetic is in each row's comment), and
// the --gpu presets pick those rules for whole passes.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "support/raster_harness.h"
#include "tiler/gpu_presets.h"
#include "tiler/tile_size_rules.h"
#include "util/error.h"

namespace ontile {
namespace {

using F = PixelFormat;

struct Row {
  std::string what;
  TileMemoryUse use;
  TileSize expected;
};

TEST(TileSizeRules, Panfrost) {
  constexpr uint32_t kG76TileBuffer = 16384 / 2;  // panfrost_query_optimal_tib_size
  const std::vector<Row> rows = {
      // 8192 >> ceil(log2(4)) = 2048 px, clamped to 256: 16x16.
      {"one RGBA8", {{F::RGBA8_SRGB}, F::D32_FLOAT, 1}, {16, 16}},
      // four blendable targets, 16 B: 8192 >> 4 = 512 -> 256.
      {"four RGBA8/RGB10A2", {{F::RGBA8_SRGB, F::RGBA8_UNORM, F::RGB10A2_UNORM, F::RGBA8_UNORM}, F::D32_FLOAT, 1}, {16, 16}},
      // RGBA32F is raw 16 B, twice: 32 B -> 8192 >> 5 = 256: still 16x16.
      {"two RGBA32F", {{F::RGBA32_FLOAT, F::RGBA32_FLOAT}, std::nullopt, 1}, {16, 16}},
      // 48 B rounds up to 64: 8192 >> 6 = 128 px: 16x8.
      {"three RGBA32F", {{F::RGBA32_FLOAT, F::RGBA32_FLOAT, F::RGBA32_FLOAT}, std::nullopt, 1}, {16, 8}},
      // RGBA16F x 4 samples = 32 B, plus RGBA8 x 4 = 16 B: 48 -> 64: 128 px.
      {"4x MSAA RGBA16F + RGBA8", {{F::RGBA16_FLOAT, F::RGBA8_UNORM}, F::D32_FLOAT, 4}, {16, 8}},
      // 8 x RGBA32F x 8 samples = 1024 B: 8192 >> 10 = 8 px, doubled (no pipelining) to 16: 4x4.
      {"8x MSAA, 8 RGBA32F", {std::vector<F>(8, F::RGBA32_FLOAT), std::nullopt, 8}, {4, 4}},
      // No colour target: the hardware's RGBA8 dummy, 4 B.
      {"depth only", {{}, F::D32_FLOAT, 1}, {16, 16}},
  };
  for (const Row& r : rows) {
    EXPECT_EQ(panfrost_tile_size(r.use, kG76TileBuffer, false), r.expected) << r.what;
  }
  // On v6 (Mali-G71) the doubling is not allowed: 8 px, 4x2.
  EXPECT_EQ(panfrost_tile_size(rows[5].use, 8192, true), (TileSize{4, 2}));
  EXPECT_EQ(panfrost_tib_bytes_per_sample(F::RGB10A2_UNORM), 4);
  EXPECT_EQ(panfrost_tib_bytes_per_sample(F::RG11B10_FLOAT), 4);  // raw 32 bits
  EXPECT_EQ(panfrost_tib_bytes_per_sample(F::RGBA16_FLOAT), 8);
}

TEST(TileSizeRules, AsahiShrinksFrom32x32To32x16To16x16) {
  const std::vector<Row> rows = {
      // 4 B rounded to 8: 8 x 1024 = 8192 <= 32767: 32x32.
      {"one RGBA8", {{F::RGBA8_SRGB}, F::D32_FLOAT, 1}, {32, 32}},
      // 4 x 4 B = 16 B: 16384: 32x32.
      {"four 32-bit targets", {{F::RGBA8_SRGB, F::RGBA8_UNORM, F::RGB10A2_UNORM, F::R32_FLOAT}, F::D32_FLOAT, 1}, {32, 32}},
      // Sorted by size, 16 + 8 = 24 B (in the given order RGBA16F would pad 8 B before RGBA32F):
      // 24576: 32x32.
      {"RGBA16F + RGBA32F", {{F::RGBA16_FLOAT, F::RGBA32_FLOAT}, std::nullopt, 1}, {32, 32}},
      // 16 + 8 + 4 = 28, rounded to 32 B: 32768 > 32767; x 512 = 16384: 32x16.
      {"RGBA8 + RGBA16F + RGBA32F", {{F::RGBA8_UNORM, F::RGBA16_FLOAT, F::RGBA32_FLOAT}, std::nullopt, 1}, {32, 16}},
      // 8 B x 4 samples = 32 B: 32x16.
      {"4x MSAA RGBA8", {{F::RGBA8_SRGB}, F::D32_FLOAT, 4}, {32, 16}},
      // 16 B x 4 samples = 64 B: 64 x 512 = 32768 > 32767; x 256 = 16384: 16x16.
      {"4x MSAA RGBA32F", {{F::RGBA32_FLOAT}, std::nullopt, 4}, {16, 16}},
  };
  for (const Row& r : rows) EXPECT_EQ(asahi_tile_size(r.use), r.expected) << r.what;
  // 8 x 16 B x 2 samples = 256 B per pixel does not fit 16x16 (65536 B).
  EXPECT_THROW(asahi_tile_size({std::vector<F>(8, F::RGBA32_FLOAT), std::nullopt, 2}), Error);
}

TEST(TileSizeRules, FreedrenoFitsColourAndDepthInGmem) {
  const FreedrenoGmem a630;  // 1 MiB, 32x16 alignment, 8 KiB pages
  struct FdRow {
    std::string what;
    TileMemoryUse use;
    int width, height;
    TileSize expected;
  };
  const std::vector<FdRow> rows = {
      // 1920x1080, RGBA8 + D32 = 8 B/px. 1x1..: grow rows/columns alternately (y first) until both
      // buffers fit: 2x2 bins of 960x544 need 2 x 2,088,960 B; 2x3: 960x368 x 4 B = 1,413,120 per
      // buffer; 3x3: 640x368 = 942,080 each, 1,884,160 > 1 MiB; 3x4: 640x272 x 4 = 696,320, two
      // buffers (second at 696,320 rounded up to 8 KiB = 704,512) = 1,400,832 > 1 MiB; 4x4:
      // 480x272 x 4 = 522,240, second at 524,288: 1,046,528 <= 1,048,576: fits. The trade (3x5)
      // is not fewer bins. Bins 480x272.
      {"1080p RGBA8 + D32", {{F::RGBA8_SRGB}, F::D32_FLOAT, 1}, 1920, 1080, {480, 272}},
      // Colour alone: 4 B/px. 2x2: 960x544 x 4 = 2,088,960 > 1 MiB; 2x3: 960x368 x 4 = 1,413,120;
      // 3x3: 640x368 x 4 = 942,080 fits; then the trade (nx-1, ny+1) = (2, 4): 960x272 x 4 =
      // 1,044,480 fits in 8 < 9 bins: 960x272.
      {"1080p RGBA8 only", {{F::RGBA8_SRGB}, std::nullopt, 1}, 1920, 1080, {960, 272}},
      // A small target fits in one bin (aligned up to 32x16).
      {"100x50 RGBA8 + D32", {{F::RGBA8_SRGB}, F::D32_FLOAT, 1}, 100, 50, {128, 64}},
  };
  for (const FdRow& r : rows) {
    EXPECT_EQ(freedreno_tile_size(r.use, r.width, r.height, a630), r.expected) << r.what;
  }
}

TEST(TileSizeRules, GpuPresetsPickTheirRules) {
  ASSERT_NE(find_gpu_preset("mali-g76"), nullptr);
  EXPECT_EQ(find_gpu_preset("no-such-gpu"), nullptr);
  TilerConfig c;
  apply_gpu_preset(*find_gpu_preset("mali-g76"), c);
  EXPECT_EQ(c.tile_size_px, 16);
  EXPECT_EQ(c.color_budget_bits_per_px, 128);
  EXPECT_TRUE(c.afbc);
  EXPECT_NE(c.transaction_elimination, nullptr);
  EXPECT_EQ(c.parameter_cache.size_bytes, 512u * 1024);
  EXPECT_EQ(c.texture_cache.size_bytes, 512u * 1024);
  // A pass with one RGBA8 target and depth, as each preset tiles it.
  RenderPassDesc pass;
  pass.width_px = 1920;
  pass.height_px = 1080;
  pass.attachments = {{"c", F::RGBA8_SRGB, LoadAction::Clear, StoreAction::Store, glm::vec4(0.0f), nullptr, nullptr},
                      {"d", F::D32_FLOAT, LoadAction::Clear, StoreAction::DontCare, glm::vec4(1.0f), nullptr, nullptr}};
  pass.depth_index = 1;
  const auto tile_of = [&](const std::string& gpu) {
    TilerConfig config;
    apply_gpu_preset(*find_gpu_preset(gpu), config);
    return pass_tile_size(config, pass);
  };
  EXPECT_EQ(tile_of("mali-g76"), (TileSize{16, 16}));
  EXPECT_EQ(tile_of("panfrost"), (TileSize{16, 16}));
  EXPECT_EQ(tile_of("apple-g13"), (TileSize{32, 32}));
  EXPECT_EQ(tile_of("adreno-630"), (TileSize{480, 272}));
}

}  // namespace
}  // namespace ontile
