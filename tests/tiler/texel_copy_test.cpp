// Declared texel copies passed through (texel_copy_rect.h): a blit with the universal copy
// material gives the destination bits, every counter of the report, every tile's and texture's
// traffic and the very texel trace that the shaded copy gives (set_texel_copy_pass_through
// off), at sizes that are and are not tile multiples, tile sizes 16 and 32, RGBA8 UNORM and
// sRGB and RGBA16F (sources of random bytes: every half code, NaNs included), 1 and 2 threads;
// copies the path cannot take (other sizes and formats, RGBA32F's decoded copy) are shaded.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "context/command_buffer.h"
#include "context/frame_report.h"
#include "context/render_context.h"
#include "memory/texture_replay_observer.h"
#include "pipelines/universal/post_processing.h"
#include "tiler/detail/texel_copy_rect.h"
#include "tiler/detail/tile_memory.h"

namespace ontile {
namespace {

struct PassThroughOnExit {
  ~PassThroughOnExit() { set_texel_copy_pass_through(true); }
};

struct Copy {
  int source_width, source_height;
  PixelFormat source_format;
  int width, height;  // the destination's
  PixelFormat format;
  int tile, threads;
};

std::string describe(const Copy& c) {
  return std::to_string(c.source_width) + "x" + std::to_string(c.source_height) + " " +
         format_name(c.source_format) + " -> " + std::to_string(c.width) + "x" +
         std::to_string(c.height) + " " + format_name(c.format) + ", tile " +
         std::to_string(c.tile) + ", " + std::to_string(c.threads) + " thread(s)";
}

struct Blitted {
  std::vector<uint8_t> source, destination;
  std::vector<std::vector<uint64_t>> granules;  // per tile, in tile order
  nlohmann::json report;  // per-tile statistics included, timings dropped
};

// Every tile's texture granules of the frame's passes as the replay saw them, less the region id.
class TraceRecorder final : public TextureReplayObserver {
 public:
  void before_replay(const TextureCache&) override {}
  void after_replay(const TextureCache&, const std::vector<TileTrace>& traces, const TextureTraffic&) override {
    // Each run samples a texture of its own (region ids in creation order): its offsets.
    constexpr uint64_t kOffsetMask = (uint64_t{1} << TextureCache::kRegionShiftGranules) - 1;
    for (const TileTrace& t : traces) {
      granules.push_back(t.texture_granules);
      for (uint64_t& g : granules.back()) g &= kOffsetMask;
    }
  }
  std::vector<std::vector<uint64_t>> granules;
};

// One frame: a blit of a source of pseudo-random bytes (every code, alpha included) over a
// destination holding other bytes.
Blitted blit(const Copy& c) {
  ContextConfig config;
  config.threads = c.threads;
  config.tiler.tile_size_px = c.tile;
  RenderContext context(config);
  Surface* source = context.create_surface("source", c.source_format, c.source_width, c.source_height);
  Surface* destination = context.create_surface("destination", c.format, c.width, c.height);
  uint32_t state = 12345u;
  for (int y = 0; y < c.source_height; ++y) {
    uint8_t* row = source->pixel_bytes(0, y);
    for (int i = 0; i < c.source_width * bytes_per_pixel(c.source_format); ++i) {
      state = state * 1664525u + 1013904223u;
      row[i] = static_cast<uint8_t>(state >> 24);
    }
  }
  destination->fill(glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
  const std::unique_ptr<Shader> blit_shader = make_universal_blit_shader();
  const std::unique_ptr<RenderMaterial> copy = make_copy_material(*blit_shader, "copy");
  CommandBuffer commands;
  commands.blit(RenderTargetRef::of(source), RenderTargetRef::of(destination), copy.get(), "Copy");
  context.execute_command_buffer(commands);
  FrameReportOptions options;
  options.tiles = true;
  TraceRecorder recorder;
  set_texture_replay_observer(&recorder);
  const FrameReport frame = context.submit();
  set_texture_replay_observer(nullptr);
  nlohmann::json report = frame_report_json(frame, options);
  report.erase("timing");
  return {source->bytes(), destination->bytes(), std::move(recorder.granules), std::move(report)};
}

TEST(TexelCopy, PassedThroughCopiesMatchTheShadedCopyBitForBit) {
  const PassThroughOnExit restore;
  using F = PixelFormat;
  std::vector<Copy> copies;
  for (const int threads : {1, 2}) {
    for (const F format : {F::RGBA8_UNORM, F::RGBA8_SRGB, F::RGBA16_FLOAT}) {
      copies.push_back({1920, 1080, format, 1920, 1080, format, 16, threads});
      copies.push_back({333, 177, format, 333, 177, format, 16, threads});  // odd edges, partial tiles
      copies.push_back({64, 64, format, 64, 64, format, 32, threads});
      copies.push_back({250, 142, format, 250, 142, format, 32, threads});  // partial batches
      copies.push_back({16, 16, format, 16, 16, format, 16, threads});     // rows of one granule
    }
  }
  for (const Copy& c : copies) {
    const std::string what = describe(c);
    set_texel_copy_pass_through(false);
    const uint64_t before_shaded = texel_copy_quads_passed_through();
    const Blitted shaded = blit(c);
    EXPECT_EQ(texel_copy_quads_passed_through(), before_shaded) << what;
    set_texel_copy_pass_through(true);
    const uint64_t before = texel_copy_quads_passed_through();
    const Blitted passed = blit(c);
    EXPECT_GT(texel_copy_quads_passed_through(), before) << what;
    // RGBA8 codes come back as they were; float formats as quantising keeps them (NaNs).
    if (TileMemory::holds_codes(c.format)) EXPECT_TRUE(passed.destination == passed.source) << what;
    EXPECT_TRUE(passed.destination == shaded.destination) << what;
    EXPECT_EQ(passed.report, shaded.report) << what;
    EXPECT_TRUE(passed.granules == shaded.granules) << what << ": the texel traces differ";
    EXPECT_GT(passed.report["passes"][0]["texture"]["accesses"].get<uint64_t>(), 0u) << what;
  }
}

// Sizes or formats that differ: the copy is no plain texel copy, and the shader runs.
TEST(TexelCopy, ScaledOrConvertingBlitsAreShaded) {
  using F = PixelFormat;
  const std::vector<Copy> copies = {
      {128, 96, F::RGBA8_UNORM, 64, 48, F::RGBA8_UNORM, 16, 1},   // downscale
      {64, 48, F::RGBA8_UNORM, 64, 48, F::RGBA8_SRGB, 16, 1},     // UNORM codes into sRGB
      {64, 48, F::RGBA8_SRGB, 64, 48, F::RGBA8_UNORM, 16, 1},
      {64, 48, F::RGBA8_UNORM, 64, 48, F::RGBA16_FLOAT, 16, 1},  // codes into halves
      {64, 48, F::RGBA16_FLOAT, 64, 48, F::RGBA8_UNORM, 16, 1},  // halves into codes
      {64, 48, F::RGBA16_FLOAT, 64, 48, F::RGBA32_FLOAT, 16, 1},
      {64, 48, F::RGBA32_FLOAT, 64, 48, F::RGBA32_FLOAT, 16, 1},  // sampled through a decoded copy
  };
  for (const Copy& c : copies) {
    const uint64_t before = texel_copy_quads_passed_through();
    const Blitted b = blit(c);
    EXPECT_EQ(texel_copy_quads_passed_through(), before) << describe(c);
  }
}

}  // namespace
}  // namespace ontile
