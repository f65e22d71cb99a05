// Batches across triangles in whole frames (set_batches_across_triangles): the universal
// pipeline's frame (shadow casters, depth normals, the Lit forward pass with shadow lookups, the
// copy, outline and tonemap blits) and the AOV pass give the same bits and every counter with
// batches spanning triangles and with one triangle per batch, on a scene of small triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "aov/aov_pass.h"
#include "context/frame_report.h"
#include "pipelines/kit/render_frame.h"
#include "support/generated_scene.h"
#include "tiler/detail/quad_batcher.h"

namespace ontile {
namespace {

struct AcrossTrianglesOnExit {
  ~AcrossTrianglesOnExit() { set_batches_across_triangles(true); }
};

nlohmann::json report_without_timing(const FrameReport& report) {
  nlohmann::json j = frame_report_json(report);
  j.erase("timing");
  for (auto& pass : j["passes"]) pass.erase("timing");
  return j;
}

RenderSettings small_frame(const std::string& pipeline, int threads) {
  RenderSettings s;
  s.pipeline = pipeline;
  s.width_px = 224;
  s.height_px = 126;
  s.context.threads = threads;
  s.context.tiler.tile_size_px = 16;
  return s;
}

TEST(CrossTriangleBatches, UniversalFramesMatchOneTrianglePerBatch) {
  const AcrossTrianglesOnExit restore;
  const Scene atrium = test::generated_scene("atrium", 1.0);
  for (const int threads : {1, 2}) {
    const RenderSettings s = small_frame("universal", threads);
    set_batches_across_triangles(false);
    const RenderedFrame per_triangle = render_frame(atrium, s);
    set_batches_across_triangles(true);
    const RenderedFrame across = render_frame(atrium, s);
    uint64_t shaded = 0, texels = 0;
    for (const auto& pass : per_triangle.outputs.report.passes) shaded += pass.tiles.fragments_shaded;
    const nlohmann::json report = report_without_timing(per_triangle.outputs.report);
    for (const auto& pass : report["passes"]) texels += pass["texture"]["accesses"].get<uint64_t>();
    EXPECT_GT(shaded, 0u);
    EXPECT_GT(texels, 0u);  // the shadow lookups and blits are traced
    EXPECT_TRUE(across.outputs.color->bytes() == per_triangle.outputs.color->bytes()) << threads << " threads";
    EXPECT_EQ(report_without_timing(across.outputs.report), report) << threads << " threads";
  }
}

TEST(CrossTriangleBatches, AovFramesMatchOneTrianglePerBatch) {
  const AcrossTrianglesOnExit restore;
  const Scene atrium = test::generated_scene("atrium", 1.0);
  const std::vector<AovKind> kinds = {AovKind::Depth, AovKind::PrimitiveId, AovKind::Normal};
  for (const int threads : {1, 2}) {
    const RenderSettings s = small_frame("lambert", threads);
    set_batches_across_triangles(false);
    const AovFrame per_triangle = render_aov_frame(atrium, s, kinds);
    set_batches_across_triangles(true);
    const AovFrame across = render_aov_frame(atrium, s, kinds);
    for (size_t k = 0; k < kinds.size(); ++k) {
      EXPECT_TRUE(aov_channels(*across.surfaces[k], kinds[k]) == aov_channels(*per_triangle.surfaces[k], kinds[k]))
          << aov_name(kinds[k]) << ", " << threads << " threads";
    }
    // Many distinct primitive ids: batches that span triangles must keep each quad's own id.
    const std::vector<float> ids = aov_channels(*across.surfaces[1], AovKind::PrimitiveId);
    std::vector<float> distinct(ids);
    std::sort(distinct.begin(), distinct.end());
    EXPECT_GT(std::unique(distinct.begin(), distinct.end()) - distinct.begin(), 500);
    EXPECT_EQ(report_without_timing(across.report), report_without_timing(per_triangle.report));
  }
}

}  // namespace
}  // namespace ontile
