// Transaction elimination (memory/transaction_elimination.h): a tile write whose CRC equals the
// previous frame's costs nothing. A static frame rendered twice eliminates every stored colour
// tile; a frame where one square moves eliminates exactly the tiles whose pixels did not change;
// the images are the same with TE on or off; tiles other than 16x16 are not compared (the CLI
// refuses them: tests/cli/gpu_preset_cli_test.cpp).
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>

#include "memory/transaction_elimination.h"
#include "support/raster_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 80, kH = 48;                   // 5 x 3 = 15 tiles of 16x16
constexpr int kTiles = (kW / 16) * (kH / 16);
constexpr uint64_t kTileBytes = 16 * 16 * 4;      // RGBA8

struct Frame {
  FrameReport report;
  std::vector<uint8_t> pixels;
};

// One pass: clear to black, a white axis-aligned square with its top-left corner at (x, y),
// `size` pixels wide, stored to an RGBA8 surface.
Frame render_square(const std::shared_ptr<TileSignatureHistory>& history, int x, int y, int size, int tile = 16) {
  ContextConfig config;
  config.threads = 2;
  config.tiler.tile_size_px = tile;
  config.tiler.transaction_elimination = history;
  RenderContext ctx(config);
  Surface* s = ctx.create_surface("colour", PixelFormat::RGBA8_UNORM, kW, kH);
  const std::vector<glm::vec4> pos = {pixel_to_clip(x, y, kW, kH), pixel_to_clip(x + size, y, kW, kH),
                                      pixel_to_clip(x, y + size, kW, kH), pixel_to_clip(x + size, y + size, kW, kH)};
  ClipSpaceVertexShader vs(pos, {}, 0);
  ConstantOneShader fs;
  const std::vector<uint32_t> idx = {0, 1, 2, 2, 1, 3};
  record_additive_pass(ctx, "square", kW, kH, 1,
                       {"colour", PixelFormat::RGBA8_UNORM, LoadAction::Clear, StoreAction::Store, glm::vec4(0.0f), s,
                        nullptr},
                       vs, fs, idx);
  Frame f;
  f.report = ctx.submit();
  f.pixels = s->bytes();
  return f;
}

// Tiles whose bytes are the same in both frames.
int equal_tiles(const Frame& a, const Frame& b) {
  int equal = 0;
  for (int ty = 0; ty < kH / 16; ++ty) {
    for (int tx = 0; tx < kW / 16; ++tx) {
      bool same = true;
      for (int y = ty * 16; y < ty * 16 + 16; ++y) {
        const size_t row = (static_cast<size_t>(y) * kW + tx * 16) * 4;
        same = same && std::memcmp(a.pixels.data() + row, b.pixels.data() + row, 16 * 4) == 0;
      }
      equal += same ? 1 : 0;
    }
  }
  return equal;
}

TEST(TransactionElimination, AStaticFrameEliminatesEveryStoredTile) {
  auto history = std::make_shared<TileSignatureHistory>();
  const Frame first = render_square(history, 20, 10, 12);
  const Frame second = render_square(history, 20, 10, 12);
  const AttachmentTraffic& a1 = first.report.passes[0].attachments[0];
  const AttachmentTraffic& a2 = second.report.passes[0].attachments[0];
  EXPECT_TRUE(second.report.passes[0].transaction_elimination);
  EXPECT_EQ(a1.te_tiles_eliminated, 0u) << "the first frame has nothing to compare with";
  EXPECT_EQ(a1.bytes_stored, kTiles * kTileBytes);
  EXPECT_EQ(a2.te_tiles_eliminated, static_cast<uint64_t>(kTiles));
  EXPECT_EQ(a2.te_bytes_saved, kTiles * kTileBytes);
  EXPECT_EQ(a2.bytes_stored, 0u);
  uint64_t stored_by_tiles = 0;
  for (const TileStats& t : second.report.passes[0].tile_stats) stored_by_tiles += t.bytes_stored;
  EXPECT_EQ(stored_by_tiles, 0u);
}

TEST(TransactionElimination, OnlyTheChangedTilesAreWritten) {
  auto history = std::make_shared<TileSignatureHistory>();
  // The square moves from tile (1, 0) to tile (3, 2): those two tiles change, 13 do not.
  const Frame first = render_square(history, 20, 2, 10);
  const Frame second = render_square(history, 52, 34, 10);
  const int unchanged = equal_tiles(first, second);
  ASSERT_EQ(unchanged, kTiles - 2);
  const AttachmentTraffic& a = second.report.passes[0].attachments[0];
  EXPECT_EQ(a.te_tiles_eliminated, static_cast<uint64_t>(unchanged));
  EXPECT_EQ(a.te_bytes_saved, unchanged * kTileBytes);
  EXPECT_EQ(a.bytes_stored, (kTiles - unchanged) * kTileBytes);
  // The tiles' shares: the two changed tiles store, the others nothing.
  const std::vector<TileStats>& tiles = second.report.passes[0].tile_stats;
  EXPECT_EQ(tiles[1].bytes_stored, kTileBytes);
  EXPECT_EQ(tiles[2 * 5 + 3].bytes_stored, kTileBytes);
  EXPECT_EQ(tiles[0].bytes_stored, 0u);
}

TEST(TransactionElimination, ImagesDoNotChange) {
  auto history = std::make_shared<TileSignatureHistory>();
  render_square(history, 20, 2, 10);
  const Frame with_te = render_square(history, 20, 2, 10);
  const Frame without = render_square(nullptr, 20, 2, 10);
  EXPECT_EQ(with_te.pixels, without.pixels);
  EXPECT_FALSE(without.report.passes[0].transaction_elimination);
  EXPECT_EQ(without.report.passes[0].attachments[0].te_tiles_eliminated, 0u);
}

TEST(TransactionElimination, OtherTileSizesAreNotCompared) {
  auto history = std::make_shared<TileSignatureHistory>();
  render_square(history, 20, 2, 10, 32);
  const Frame second = render_square(history, 20, 2, 10, 32);
  EXPECT_FALSE(second.report.passes[0].transaction_elimination);
  EXPECT_EQ(second.report.passes[0].attachments[0].te_tiles_eliminated, 0u);
}

}  // namespace
}  // namespace ontile::test
