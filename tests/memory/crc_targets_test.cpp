// Which writes of a pass keep transaction-elimination CRCs (memory/transaction_elimination.h,
// CrcTargets): a Mali framebuffer descriptor has one CRC buffer, so on Bifrost v7 one colour
// target per pass is compared (the first, or the first whose CRCs are valid), on Bifrost v6 only
// a pass with a single colour target, and `every-target` compares them all. A static two-target
// pass rendered twice shows exactly which targets' tiles were eliminated.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "memory/transaction_elimination.h"
#include "support/raster_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 64, kH = 32;                  // 4 x 2 = 8 tiles of 16x16
constexpr uint64_t kTiles = (kW / 16) * (kH / 16);
constexpr uint64_t kTileBytes = 16 * 16 * 4;     // RGBA8

// Writes 1 to both colour targets.
class TwoTargetsShader final : public FragmentShader {
 public:
  void shade(const QuadFragment&, QuadOutput& out) const override {
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      out.color[0][lane] = glm::vec4(1.0f);
      out.color[1][lane] = glm::vec4(0.5f);
    }
  }
};

// One pass "gbuffer" with colour targets "a" and "b" (stored when `store_a` / `store_b`; else
// their contents are dropped) over a square, then the per-target traffic.
std::vector<AttachmentTraffic> render_pass(const std::shared_ptr<TileSignatureHistory>& history, bool store_a,
                                           bool store_b) {
  ContextConfig config;
  config.threads = 2;
  config.tiler.tile_size_px = 16;
  config.tiler.transaction_elimination = history;
  RenderContext ctx(config);
  Surface* a = ctx.create_surface("a", PixelFormat::RGBA8_UNORM, kW, kH);
  Surface* b = ctx.create_surface("b", PixelFormat::RGBA8_UNORM, kW, kH);
  const std::vector<glm::vec4> pos = {pixel_to_clip(5, 3, kW, kH), pixel_to_clip(40, 3, kW, kH),
                                      pixel_to_clip(5, 29, kW, kH), pixel_to_clip(40, 29, kW, kH)};
  ClipSpaceVertexShader vs(pos, {}, 0);
  TwoTargetsShader fs;
  const std::vector<uint32_t> idx = {0, 1, 2, 2, 1, 3};
  ctx.begin_render_pass("gbuffer", kW, kH, 1,
                        {{"a", PixelFormat::RGBA8_UNORM, LoadAction::Clear,
                          store_a ? StoreAction::Store : StoreAction::DontCare, glm::vec4(0.0f), a, nullptr},
                         {"b", PixelFormat::RGBA8_UNORM, LoadAction::Clear,
                          store_b ? StoreAction::Store : StoreAction::DontCare, glm::vec4(0.0f), b, nullptr}},
                        -1);
  ctx.begin_subpass({0, 1});
  ctx.draw(unculled_draw(vs, fs, idx));
  ctx.end_subpass();
  ctx.end_render_pass();
  return ctx.submit().passes.at(0).attachments;
}

TEST(CrcTargets, OnePerPassComparesTheFirstColourTarget) {
  auto history = std::make_shared<TileSignatureHistory>(CrcTargets::OnePerPass);
  render_pass(history, true, true);
  const std::vector<AttachmentTraffic> second = render_pass(history, true, true);
  EXPECT_EQ(second[0].te_tiles_eliminated, kTiles);
  EXPECT_EQ(second[0].bytes_stored, 0u);
  EXPECT_EQ(second[1].te_tiles_eliminated, 0u) << "the descriptor has one CRC buffer";
  EXPECT_EQ(second[1].bytes_stored, kTiles * kTileBytes);
}

TEST(CrcTargets, OnePerPassPrefersATargetWhoseCrcsAreValid) {
  auto history = std::make_shared<TileSignatureHistory>(CrcTargets::OnePerPass);
  render_pass(history, false, true);  // only "b" is written: it gets the CRCs
  const std::vector<AttachmentTraffic> second = render_pass(history, true, true);
  EXPECT_EQ(second[0].te_tiles_eliminated, 0u);
  EXPECT_EQ(second[0].bytes_stored, kTiles * kTileBytes);
  EXPECT_EQ(second[1].te_tiles_eliminated, kTiles) << "pan_select_crc_rt keeps the target with valid CRCs";
  EXPECT_EQ(second[1].bytes_stored, 0u);
}

TEST(CrcTargets, SingleTargetPassesCompareNothingInAPassWithTwoTargets) {
  auto history = std::make_shared<TileSignatureHistory>(CrcTargets::SingleTargetPasses);
  render_pass(history, true, true);
  const std::vector<AttachmentTraffic> second = render_pass(history, true, true);
  for (const AttachmentTraffic& t : second) {
    EXPECT_EQ(t.te_tiles_eliminated, 0u) << t.name;
    EXPECT_EQ(t.bytes_stored, kTiles * kTileBytes) << t.name;
  }
}

TEST(CrcTargets, EveryTargetComparesBoth) {
  auto history = std::make_shared<TileSignatureHistory>(CrcTargets::EveryTarget);
  render_pass(history, true, true);
  const std::vector<AttachmentTraffic> second = render_pass(history, true, true);
  for (const AttachmentTraffic& t : second) {
    EXPECT_EQ(t.te_tiles_eliminated, kTiles) << t.name;
    EXPECT_EQ(t.bytes_stored, 0u) << t.name;
  }
}

TEST(CrcTargets, NamesRoundTrip) {
  for (const CrcTargets t : {CrcTargets::OnePerPass, CrcTargets::SingleTargetPasses, CrcTargets::EveryTarget}) {
    const CrcTargets* parsed = parse_crc_targets(crc_targets_name(t));
    ASSERT_NE(parsed, nullptr);
    EXPECT_EQ(*parsed, t);
  }
  EXPECT_EQ(parse_crc_targets("off"), nullptr);
}

}  // namespace
}  // namespace ontile::test
