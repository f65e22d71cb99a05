// The AFBC size model (memory/afbc.h): sizes of hand-built superblocks follow the documented
// encoding exactly, and a frame rendered with AFBC on has the same image bits, stores exactly
// the model's size of its output surface, and charges the tiles shares that sum to it.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <numeric>
#include <random>
#include <vector>

#include "memory/afbc.h"
#include "pipelines/kit/render_frame.h"
#include "support/generated_scene.h"

namespace ontile {
namespace {

std::vector<uint8_t> rgba8(int width, int height, uint8_t (*channel)(int x, int y, int c)) {
  std::vector<uint8_t> bytes(static_cast<size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < 4; ++c) bytes[(static_cast<size_t>(y) * width + x) * 4 + c] = channel(x, y, c);
    }
  }
  return bytes;
}

TEST(Afbc, SuperblockSizesFollowTheEncoding) {
  // Solid colour: the header alone.
  const auto solid = rgba8(16, 16, [](int, int, int c) { return uint8_t(40 + c); });
  EXPECT_EQ(afbc_block_bytes(PixelFormat::RGBA8_UNORM, solid.data(), 16, 16, 64), std::vector<uint64_t>{16});
  // Red = x: each 4x4 subblock spans 4 values (2 bits a pixel): red 8 + 16 x 2 bits, green, blue
  // and alpha 8 bits each: 64 bits = 8 bytes; 16 subblocks plus the header.
  const auto ramp = rgba8(16, 16, [](int x, int, int c) { return uint8_t(c == 0 ? x : 0); });
  EXPECT_EQ(afbc_block_bytes(PixelFormat::RGBA8_UNORM, ramp.data(), 16, 16, 64), std::vector<uint64_t>{16 + 16 * 8});
  // Noise: every subblock stored raw (64 bytes), never more.
  std::mt19937 rng(7);
  std::vector<uint8_t> noise(16 * 16 * 4);
  for (uint8_t& b : noise) b = static_cast<uint8_t>(rng());
  EXPECT_EQ(afbc_block_bytes(PixelFormat::RGBA8_UNORM, noise.data(), 16, 16, 64), std::vector<uint64_t>{16 + 1024});
  // A 20x16 surface: a second superblock 4 px wide (4 subblocks of 4x4); solid blocks anywhere.
  const auto wide = rgba8(20, 16, [](int x, int, int c) { return uint8_t(c == 0 && x >= 16 ? x : 0); });
  EXPECT_EQ(afbc_block_bytes(PixelFormat::RGBA8_UNORM, wide.data(), 20, 16, 80),
            (std::vector<uint64_t>{16, 16 + 4 * 8}));
  // RGB10A2 fields are 10, 10, 10 and 2 bits: a constant subblock costs 32 bits = 4 bytes, and a
  // superblock with one odd pixel pays that in 15 subblocks and more in the 16th.
  std::vector<uint8_t> packed(16 * 16 * 4, 0);
  packed[0] = 3;  // red of pixel (0, 0) = 3: 2 bits per pixel in its subblock
  EXPECT_EQ(afbc_block_bytes(PixelFormat::RGB10A2_UNORM, packed.data(), 16, 16, 64),
            std::vector<uint64_t>{16 + 15 * 4 + (32 + 16 * 2) / 8});
}

TEST(Afbc, OnlySingleSampleColourOfUpTo32BitsIsCompressed) {
  EXPECT_TRUE(afbc_compresses(PixelFormat::RGBA8_SRGB, 1));
  EXPECT_TRUE(afbc_compresses(PixelFormat::RGB10A2_UNORM, 1));
  EXPECT_FALSE(afbc_compresses(PixelFormat::RGBA8_SRGB, 4));
  EXPECT_FALSE(afbc_compresses(PixelFormat::D32_FLOAT, 1));
  EXPECT_FALSE(afbc_compresses(PixelFormat::D24S8, 1));
  EXPECT_FALSE(afbc_compresses(PixelFormat::RGBA16_FLOAT, 1));
}

RenderedFrame render(const Scene& scene, const std::string& pipeline, bool afbc, int threads,
                     std::vector<std::pair<std::string, std::string>> options = {}) {
  RenderSettings s;
  s.pipeline = pipeline;
  s.width_px = 203;  // partial superblocks and tiles at the edges
  s.height_px = 117;
  s.context.threads = threads;
  s.context.tiler.afbc = afbc;
  for (const auto& [k, v] : options) s.options.set(k, v);
  return render_frame(scene, s);
}

uint64_t model_bytes(const Surface& s) {
  const std::vector<uint64_t> blocks = afbc_block_bytes(s.format(), s.pixel_bytes(0, 0), s.width(), s.height(),
                                                        static_cast<size_t>(s.width()) * bytes_per_pixel(s.format()));
  return std::accumulate(blocks.begin(), blocks.end(), uint64_t{0});
}

TEST(Afbc, FramesStoreTheModelsSizeAndKeepTheirImages) {
  const Scene demo = test::generated_scene("demo", 1.0);
  const RenderedFrame off = render(demo, "lambert", false, 2);
  const RenderedFrame on = render(demo, "lambert", true, 2);
  const RenderedFrame on1 = render(demo, "lambert", true, 1);
  const Surface& image = *on.outputs.color;
  ASSERT_EQ(image.width(), off.outputs.color->width());
  for (int y = 0; y < image.height(); ++y) {
    ASSERT_EQ(0, std::memcmp(image.pixel_bytes(0, y), off.outputs.color->pixel_bytes(0, y), image.width() * 4)) << y;
  }
  const PassReport& pass = on.outputs.report.passes[0];
  const AttachmentTraffic& color = pass.attachments[0];
  EXPECT_TRUE(color.afbc);
  EXPECT_EQ(color.bytes_stored, model_bytes(image));
  const uint64_t uncompressed = uint64_t{203} * 117 * 4;
  EXPECT_EQ(off.outputs.report.passes[0].attachments[0].bytes_stored, uncompressed);
  EXPECT_LT(color.bytes_stored, uncompressed);  // the demo's sky and ground compress
  EXPECT_EQ(color.afbc_bytes_saved, static_cast<int64_t>(uncompressed - color.bytes_stored));
  EXPECT_FALSE(pass.attachments[1].afbc);  // depth
  uint64_t tiles_stored = 0;
  for (const TileStats& t : pass.tile_stats) tiles_stored += t.bytes_stored;
  EXPECT_EQ(tiles_stored, pass.attachment_bytes_stored());
  EXPECT_EQ(on1.outputs.report.bytes_written(), on.outputs.report.bytes_written());
  EXPECT_EQ(on.outputs.report.bytes_read(), off.outputs.report.bytes_read());

  // MSAA: the samples stay uncompressed, the single-sample resolve target is compressed.
  const RenderedFrame msaa = render(demo, "lambert", true, 2, {{"msaa", "4"}, {"depth_store", "store"}});
  const PassReport& m = msaa.outputs.report.passes[0];
  EXPECT_TRUE(m.attachments[0].afbc);
  EXPECT_EQ(m.attachments[0].bytes_resolved, model_bytes(*msaa.outputs.color));
  EXPECT_FALSE(m.attachments[1].afbc);
  EXPECT_EQ(m.attachments[1].bytes_stored, uint64_t{203} * 117 * 4 * 4);

  // A load reads the compressed size of what the surface held before the pass (zeros: solid).
  const RenderedFrame load = render(demo, "lambert", true, 2, {{"color_load", "load"}});
  const uint64_t superblocks = uint64_t{(203 + 15) / 16} * ((117 + 15) / 16);
  EXPECT_EQ(load.outputs.report.passes[0].attachments[0].bytes_loaded, superblocks * kAfbcHeaderBytes);
}

}  // namespace
}  // namespace ontile
