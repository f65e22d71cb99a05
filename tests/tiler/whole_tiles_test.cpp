// Triangles covering whole tiles shaded in whole batches straight from the tile's quad grid
// (set_whole_tiles): full-screen passes (cartoon's Sobel pass, universal's blits, deferred
// lighting) and ordinary geometry give the same image bits and every counter as the same quads
// queued one by one, at sizes whose tiles hold whole batches, a partial last batch, or odd
// edges, on every SIMD target.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "context/frame_report.h"
#include "pipelines/kit/render_frame.h"
#include "raster/cell_raster.h"
#include "support/generated_scene.h"
#include "tiler/detail/tile_executor.h"

namespace ontile {
namespace {

struct DefaultsOnExit {
  ~DefaultsOnExit() {
    set_whole_tiles(true);
    force_simd_target("");
  }
};

nlohmann::json report_without_timing(const FrameReport& report) {
  nlohmann::json j = frame_report_json(report);
  j.erase("timing");
  return j;
}

struct Case {
  std::string pipeline;
  std::vector<std::pair<std::string, std::string>> options;
  int width, height, tile;
};

struct Frame {
  std::vector<uint8_t> image;
  nlohmann::json report;
};

Frame render(const Scene& scene, const Case& c) {
  RenderSettings s;
  s.pipeline = c.pipeline;
  for (const auto& [key, value] : c.options) s.options.set(key, value);
  s.width_px = c.width;
  s.height_px = c.height;
  s.context.threads = 2;
  s.context.tiler.tile_size_px = c.tile;
  const RenderedFrame f = render_frame(scene, s);
  return {f.outputs.color->bytes(), report_without_timing(f.outputs.report)};
}

TEST(WholeTiles, FramesMatchTheQueuedQuadsBitForBit) {
  const DefaultsOnExit restore;
  const Scene demo = test::generated_scene("demo", 1.0);
  const std::vector<Case> cases = {
      {"cartoon", {}, 320, 180, 16},   // bottom tiles 4 rows high: one whole batch each
      {"cartoon", {}, 320, 182, 16},   // bottom tiles 6 rows: a whole batch and 8 queued quads
      {"cartoon", {}, 317, 179, 8},    // odd edges: those tiles take the queued path
      {"universal", {}, 250, 142, 32},
      {"deferred-subpass", {{"lights", "8"}}, 203, 117, 16},
      {"deferred-classic", {{"lights", "8"}}, 200, 118, 16},  // discarding lighting functor
      {"lambert", {}, 160, 90, 16},
      {"forward", {{"msaa", "4"}}, 160, 90, 16},
  };
  const std::vector<std::string> targets = simd_targets();
  for (const Case& c : cases) {
    const std::string what = c.pipeline + " " + std::to_string(c.width) + "x" +
                             std::to_string(c.height) + " tile " + std::to_string(c.tile);
    force_simd_target("");
    set_whole_tiles(false);
    const uint64_t taken_before = whole_tiles_shaded();
    const Frame queued = render(demo, c);
    EXPECT_EQ(whole_tiles_shaded(), taken_before) << what;
    set_whole_tiles(true);
    for (const std::string& target : targets) {
      force_simd_target(target);
      const uint64_t before = whole_tiles_shaded();
      const Frame whole = render(demo, c);
      // Full-screen passes take the path; 4x MSAA never does.
      if (c.pipeline != "forward") {
        EXPECT_GT(whole_tiles_shaded(), before) << what;
      }
      EXPECT_TRUE(whole.image == queued.image) << what << " on " << target;
      EXPECT_EQ(whole.report, queued.report) << what << " on " << target;
    }
  }
}

}  // namespace
}  // namespace ontile
