// Whole covered quad rows queued without per-quad coverage work (set_whole_quad_rows): frames
// with full-screen passes (cartoon's Sobel pass, universal's copy and tonemap blits, deferred
// lighting) and ordinary geometry give the same image bits and every counter with the fast
// path on and off, at even and odd sizes and tile sizes 8, 16 and 32.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "context/frame_report.h"
#include "pipelines/kit/render_frame.h"
#include "support/generated_scene.h"
#include "tiler/detail/tile_executor.h"

namespace ontile {
namespace {

struct WholeRowsOnExit {
  ~WholeRowsOnExit() { set_whole_quad_rows(true); }
};

nlohmann::json report_without_timing(const FrameReport& report) {
  nlohmann::json j = frame_report_json(report);
  j.erase("timing");
  return j;
}

TEST(WholeQuadRows, FramesMatchThePerQuadWalkBitForBit) {
  const WholeRowsOnExit restore;
  const Scene demo = test::generated_scene("demo", 1.0);
  struct Case {
    std::string pipeline;
    std::vector<std::pair<std::string, std::string>> options;
    int width, height, tile;
  };
  const std::vector<Case> cases = {
      {"cartoon", {}, 320, 180, 16},
      {"cartoon", {}, 317, 179, 8},
      {"universal", {}, 250, 142, 32},
      {"deferred-subpass", {{"lights", "8"}}, 203, 117, 16},
      {"lambert", {}, 160, 90, 16},
      {"forward", {{"msaa", "4"}}, 160, 90, 16},
  };
  for (const Case& c : cases) {
    RenderSettings s;
    s.pipeline = c.pipeline;
    for (const auto& [key, value] : c.options) s.options.set(key, value);
    s.width_px = c.width;
    s.height_px = c.height;
    s.context.threads = 2;
    s.context.tiler.tile_size_px = c.tile;
    set_whole_quad_rows(false);
    const RenderedFrame per_quad = render_frame(demo, s);
    set_whole_quad_rows(true);
    const RenderedFrame whole_rows = render_frame(demo, s);
    const std::string what = c.pipeline + " " + std::to_string(c.width) + "x" +
                             std::to_string(c.height) + " tile " + std::to_string(c.tile);
    uint64_t shaded = 0;
    for (const auto& pass : per_quad.outputs.report.passes) shaded += pass.tiles.fragments_shaded;
    EXPECT_GT(shaded, 0u) << what;
    EXPECT_TRUE(whole_rows.outputs.color->bytes() == per_quad.outputs.color->bytes()) << what;
    EXPECT_EQ(report_without_timing(whole_rows.outputs.report),
              report_without_timing(per_quad.outputs.report))
        << what;
  }
}

}  // namespace
}  // namespace ontile
