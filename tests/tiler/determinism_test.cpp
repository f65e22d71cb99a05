// Determinism: the same frame at 1, 2 and 7 threads and at tile sizes 16 and 32 gives the
// same image bits and the same traffic counters (tile size changes the tile-dependent
// counters only, so those are compared across thread counts at a fixed tile size).
#include <gtest/gtest.h>

#include <filesystem>
#include <utility>
#include <vector>

#include "context/frame_report.h"
#include "pipelines/kit/render_frame.h"
#include "scene/gen/scene_generator.h"
#include "scene/gltf_loader.h"
#include "support/generated_scene.h"

namespace ontile {
namespace {

using test::generated_scene;

nlohmann::json report_without_timing(const FrameReport& report) {
  nlohmann::json j = frame_report_json(report);
  j.erase("timing");
  return j;
}

void check_scene(const Scene& scene, int width, int height, const std::string& pipeline = "lambert",
                 const std::vector<std::pair<std::string, std::string>>& options = {},
                 uint32_t parameter_cache_bytes = 0) {
  RenderSettings base;
  base.pipeline = pipeline;
  for (const auto& [key, value] : options) base.options.set(key, value);
  base.context.tiler.parameter_cache.size_bytes = parameter_cache_bytes;
  base.width_px = width;
  base.height_px = height;
  base.context.threads = 1;
  const RenderedFrame reference = render_frame(scene, base);
  const std::vector<uint8_t>& ref_bytes = reference.outputs.color->bytes();
  const nlohmann::json ref_report = report_without_timing(reference.outputs.report);
  EXPECT_GT(reference.outputs.report.passes[0].tiles.fragments_shaded, 0u);
  for (int threads : {2, 7}) {
    RenderSettings s = base;
    s.context.threads = threads;
    const RenderedFrame f = render_frame(scene, s);
    EXPECT_TRUE(f.outputs.color->bytes() == ref_bytes) << threads << " threads";
    EXPECT_EQ(report_without_timing(f.outputs.report), ref_report) << threads << " threads";
  }
  for (int tile : {32, 8}) {
    RenderSettings s = base;
    s.context.threads = 7;
    s.context.tiler.tile_size_px = tile;
    const RenderedFrame f = render_frame(scene, s);
    EXPECT_TRUE(f.outputs.color->bytes() == ref_bytes) << "tile " << tile;
    EXPECT_EQ(f.outputs.report.bytes_by_category().at("attachment_store"),
              reference.outputs.report.bytes_by_category().at("attachment_store"))
        << "attachment stores do not depend on the tile size";
  }
}

TEST(Determinism, DemoSceneIsBitIdenticalAcrossThreadsAndTileSizes) {
  check_scene(generated_scene("demo", 1.0), 320, 180);
}

TEST(Determinism, CartoonFramesAreBitIdenticalAcrossThreadsTileSizesAndRepeats) {
  // Two passes, render targets sampled as textures, generated MatCaps: images and every
  // counter (texture cache included) must repeat exactly, also within one process.
  check_scene(generated_scene("demo", 1.0), 320, 180, "cartoon");
}

TEST(Determinism, DeferredAndForwardFramesAreBitIdenticalAcrossThreadsAndTileSizes) {
  // Light grids, input attachments, G-buffer textures, tonemap subpasses, MSAA resolve passes
  // and the parameter-cache replay: every image and counter repeats exactly.
  const Scene demo = generated_scene("demo", 1.0);
  check_scene(demo, 320, 180, "deferred-classic", {{"lights", "24"}}, 64 * 1024);
  check_scene(demo, 320, 180, "deferred-subpass", {{"lights", "24"}, {"gbuffer", "unity"}});
  check_scene(demo, 320, 180, "forward", {{"lights", "24"}, {"msaa", "4"}, {"resolve", "separate"}}, 64 * 1024);
}

TEST(Determinism, AtriumIsBitIdenticalAcrossThreadsAndTileSizes) {
  check_scene(generated_scene("atrium", 0.1), 256, 144);
}

}  // namespace
}  // namespace ontile
