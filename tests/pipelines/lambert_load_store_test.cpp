// The Vulkan-Samples render_passes anchor (docs/fidelity.md): on a tile-based GPU, changing the
// colour load action LOAD -> CLEAR saves exactly one read of the target (W x H x 4 bytes for
// RGBA8), and depth STORE -> DONT_CARE saves exactly one write of the depth target (W x H x its
// bytes per pixel); nothing else in the frame's traffic changes. Mali-G71 measured 1.09x and
// 1.01x of those figures.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "pipelines/kit/render_frame.h"
#include "support/generated_scene.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr int kWidth = 222, kHeight = 108;  // the sample's 2220x1080 aspect, a tenth of its size

FrameReport render_lambert(const Scene& scene, std::vector<std::pair<std::string, std::string>> options) {
  RenderSettings s;
  s.pipeline = "lambert";
  s.width_px = kWidth;
  s.height_px = kHeight;
  s.context.threads = 2;
  for (const auto& [key, value] : options) s.options.set(key, value);
  return render_frame(scene, s).outputs.report;
}

TEST(LambertLoadStore, LoadToClearSavesExactlyOneReadOfTheColourTarget) {
  const Scene demo = test::generated_scene("demo", 1.0);
  const FrameReport load = render_lambert(demo, {{"color_load", "load"}});
  const FrameReport clear = render_lambert(demo, {{"color_load", "clear"}});
  const FrameReport dont_care = render_lambert(demo, {{"color_load", "dont_care"}});
  const FrameReport by_default = render_lambert(demo, {});
  const uint64_t target_bytes = uint64_t{kWidth} * kHeight * 4;  // RGBA8 sRGB
  EXPECT_EQ(load.bytes_read() - clear.bytes_read(), target_bytes);
  EXPECT_EQ(load.bytes_by_category().at("attachment_load"), target_bytes);
  EXPECT_EQ(load.bytes_written(), clear.bytes_written());
  EXPECT_EQ(dont_care.bytes_read(), clear.bytes_read());
  EXPECT_EQ(dont_care.bytes_written(), clear.bytes_written());
  EXPECT_EQ(by_default.bytes_read(), clear.bytes_read());
}

TEST(LambertLoadStore, DepthStoreToDontCareSavesExactlyOneWriteOfTheDepthTarget) {
  const Scene demo = test::generated_scene("demo", 1.0);
  for (const auto& [depth, bytes_per_px] : std::vector<std::pair<std::string, uint64_t>>{
           {"d32f", 4}, {"d24", 4}, {"d16", 2}}) {
    const FrameReport store = render_lambert(demo, {{"depth", depth}, {"depth_store", "store"}});
    const FrameReport dont_care = render_lambert(demo, {{"depth", depth}, {"depth_store", "dont_care"}});
    EXPECT_EQ(store.bytes_written() - dont_care.bytes_written(), uint64_t{kWidth} * kHeight * bytes_per_px) << depth;
    EXPECT_EQ(store.bytes_read(), dont_care.bytes_read()) << depth;
  }
  // Multisampled depth stores every sample.
  const FrameReport store4 = render_lambert(demo, {{"msaa", "4"}, {"depth_store", "store"}});
  const FrameReport dont_care4 = render_lambert(demo, {{"msaa", "4"}});
  EXPECT_EQ(store4.bytes_written() - dont_care4.bytes_written(), uint64_t{kWidth} * kHeight * 4 * 4);
}

TEST(LambertLoadStore, RejectsLoadingAMultisampledColourAndUnknownActions) {
  const Scene demo = test::generated_scene("demo", 1.0);
  EXPECT_THROW(render_lambert(demo, {{"msaa", "4"}, {"color_load", "load"}}), Error);
  EXPECT_THROW(render_lambert(demo, {{"color_load", "keep"}}), Error);
  EXPECT_THROW(render_lambert(demo, {{"depth_store", "resolve"}}), Error);
}

}  // namespace
}  // namespace ontile
