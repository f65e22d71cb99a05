// Hierarchical Z: exact counts of the 8x8 cells it skips behind an occluder, nothing skipped in
// front of it, and bit-identical images and traffic with it on and off.
#include <gtest/gtest.h>

#include <filesystem>

#include "context/frame_report.h"
#include "pipelines/kit/render_frame.h"
#include "scene/gltf_loader.h"
#include "support/raster_harness.h"

namespace ontile {
namespace {

constexpr int kW = 256, kH = 128;

// Two full-screen triangles (vertices beyond the viewport) at depths z_first then z_second.
FrameReport draw_two_layers(float z_first, float z_second, bool hierarchical_z, std::vector<float>* image) {
  using test::ClipSpaceVertexShader;
  std::vector<glm::vec4> pos;
  std::vector<float> var;
  for (float z : {z_first, z_second}) {
    for (const glm::vec2 p : {glm::vec2(-1, -1), glm::vec2(3, -1), glm::vec2(-1, 3)}) {
      pos.emplace_back(p.x, p.y, z, 1.0f);
      var.insert(var.end(), {z, 0.0f, 0.0f, 0.0f});  // VaryingsShader reads varyings 0-3
    }
  }
  const std::vector<uint32_t> idx = {0, 1, 2, 3, 4, 5};
  ContextConfig cfg;
  cfg.threads = 2;
  cfg.tiler.hierarchical_z = hierarchical_z;
  RenderContext ctx(cfg);
  Surface* color = ctx.create_surface("c", PixelFormat::R32_FLOAT, kW, kH);
  ClipSpaceVertexShader vs(pos, var, 4);
  test::VaryingsShader fs;
  ctx.begin_render_pass("layers", kW, kH, 1,
                        {{"c", PixelFormat::R32_FLOAT, LoadAction::Clear, StoreAction::Store, glm::vec4(0.0f), color, nullptr},
                         {"d", PixelFormat::D32_FLOAT, LoadAction::Clear, StoreAction::DontCare, glm::vec4(1.0f), nullptr, nullptr}},
                        1);
  ctx.begin_subpass({0});
  DrawCall d;
  d.vertex_shader = &vs;
  d.fragment_shader = &fs;
  d.vertex_count = vs.vertex_count();
  d.indices = idx.data();
  d.index_count = 6;
  d.raster.cull = CullMode::None;
  ctx.draw(d);
  ctx.end_subpass();
  ctx.end_render_pass();
  FrameReport report = ctx.submit();
  if (image) {
    image->clear();
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) image->push_back(color->read(x, y).x);
  }
  return report;
}

TEST(HierarchicalZ, SkipsEveryCellBehindAFullScreenOccluder) {
  std::vector<float> with_hiz, without_hiz;
  const FrameReport on = draw_two_layers(0.2f, 0.8f, true, &with_hiz);
  const FrameReport off = draw_two_layers(0.2f, 0.8f, false, &without_hiz);
  const uint64_t pixels = uint64_t{kW} * kH, cells = pixels / 64;
  const TileCounters& t = on.passes[0].tiles;
  EXPECT_EQ(t.cells_rasterized, 2 * cells);  // both layers cover every cell
  EXPECT_EQ(t.cells_hiz_rejected, cells);    // the far layer is skipped cell by cell
  EXPECT_EQ(t.fragments_shaded, pixels);
  EXPECT_EQ(t.fragments_depth_rejected, pixels);
  EXPECT_EQ(off.passes[0].tiles.cells_hiz_rejected, 0u);
  EXPECT_EQ(off.passes[0].tiles.fragments_shaded, t.fragments_shaded);
  EXPECT_EQ(off.passes[0].tiles.fragments_depth_rejected, t.fragments_depth_rejected);
  EXPECT_EQ(with_hiz, without_hiz);
  EXPECT_EQ(with_hiz[0], 0.2f);
}

TEST(HierarchicalZ, SkipsNothingInFrontOfTheStoredDepth) {
  const FrameReport r = draw_two_layers(0.8f, 0.2f, true, nullptr);
  EXPECT_EQ(r.passes[0].tiles.cells_hiz_rejected, 0u);
  EXPECT_EQ(r.passes[0].tiles.fragments_shaded, 2u * kW * kH);
}

TEST(HierarchicalZ, OnAndOffGiveTheSameImageAndTraffic) {
  const Scene scene = load_gltf(std::filesystem::path(ONTILE_SOURCE_DIR) / "scenes" / "demo.glb");
  for (const std::string pipeline : {"lambert", "deferred-subpass", "forward"}) {
    RenderSettings s;
    s.pipeline = pipeline;
    s.width_px = 480;
    s.height_px = 270;
    const RenderedFrame on = render_frame(scene, s);
    s.context.tiler.hierarchical_z = false;
    const RenderedFrame off = render_frame(scene, s);
    EXPECT_TRUE(on.outputs.color->bytes() == off.outputs.color->bytes()) << pipeline;
    nlohmann::json a = frame_report_json(on.outputs.report), b = frame_report_json(off.outputs.report);
    uint64_t skipped = 0;
    for (auto* j : {&a, &b}) {
      j->erase("timing");
      for (auto& p : (*j)["passes"]) {
        if (j == &a) skipped += p["cells_hiz_rejected"].get<uint64_t>();
        p.erase("cells_hiz_rejected");
      }
    }
    EXPECT_EQ(a, b) << pipeline;
    if (pipeline == "lambert") EXPECT_GT(skipped, 0u) << "the demo has occluded surfaces";
  }
}

}  // namespace
}  // namespace ontile
