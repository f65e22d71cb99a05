// External traffic equals the analytic formulas: attachment loads and stores per format, the
// transient rule, MSAA resolve, parameter-buffer records, and tile-size reduction.
#include <gtest/gtest.h>

#include "support/raster_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 100, kH = 60;  // not a multiple of the tile size on purpose

struct PassSetup {
  std::vector<AttachmentDesc> attachments;
  int depth_index = -1;
  int samples = 1;
};

FrameReport run(RenderContext& ctx, const PassSetup& setup, const std::vector<glm::vec4>& pos,
                const std::vector<uint32_t>& idx, int varyings = 0) {
  ClipSpaceVertexShader vs(pos, std::vector<float>(pos.size() * varyings, 0.25f), varyings);
  ConstantOneShader fs;
  ctx.begin_render_pass("p", kW, kH, setup.samples, setup.attachments, setup.depth_index);
  std::vector<int> outputs;
  for (size_t a = 0; a < setup.attachments.size(); ++a)
    if (static_cast<int>(a) != setup.depth_index) outputs.push_back(static_cast<int>(a));
  ctx.begin_subpass(outputs);
  DrawCall d;
  d.vertex_shader = &vs;
  d.fragment_shader = &fs;
  d.vertex_count = static_cast<uint32_t>(pos.size());
  d.indices = idx.data();
  d.index_count = static_cast<uint32_t>(idx.size());
  d.raster.cull = CullMode::None;
  if (!idx.empty()) ctx.draw(d);
  ctx.end_subpass();
  ctx.end_render_pass();
  return ctx.submit();
}

TEST(Traffic, ClearStoreWritesExactlyTheSurface) {
  RenderContext ctx;
  Surface* s = ctx.create_surface("c", PixelFormat::RGBA8_UNORM, kW, kH);
  const FrameReport r = run(ctx, {{{"c", PixelFormat::RGBA8_UNORM, LoadAction::Clear, StoreAction::Store,
                                     glm::vec4(0.5f), s, nullptr}}}, {}, {});
  EXPECT_EQ(r.bytes_written(), 4u * kW * kH);
  EXPECT_EQ(r.bytes_read(), 0u);
  EXPECT_EQ(r.passes[0].tiles.tiles_executed, 0u) << "a clear needs no primitives";
  EXPECT_EQ(s->read(kW - 1, kH - 1).x, 128.0f / 255.0f);
}

TEST(Traffic, LoadStoreReadsAndWritesTheSurface) {
  RenderContext ctx;
  Surface* s = ctx.create_surface("c", PixelFormat::RGBA16_FLOAT, kW, kH);
  const FrameReport r = run(ctx, {{{"c", PixelFormat::RGBA16_FLOAT, LoadAction::Load, StoreAction::Store,
                                     glm::vec4(0.0f), s, nullptr}}}, {}, {});
  EXPECT_EQ(r.bytes_read(), 8u * kW * kH);
  EXPECT_EQ(r.bytes_written(), 8u * kW * kH);
}

TEST(Traffic, TransientAttachmentsCostNothing) {
  RenderContext ctx;
  Surface* s = ctx.create_surface("c", PixelFormat::RGBA8_UNORM, kW, kH);
  const FrameReport r = run(ctx, {{{"c", PixelFormat::RGBA8_UNORM, LoadAction::Clear, StoreAction::Store,
                                     glm::vec4(0.0f), s, nullptr},
                                    {"g", PixelFormat::RGBA16_FLOAT, LoadAction::Clear, StoreAction::Store,
                                     glm::vec4(0.0f), nullptr, nullptr},
                                    {"z", PixelFormat::D32_FLOAT, LoadAction::Clear, StoreAction::Store,
                                     glm::vec4(1.0f), nullptr, nullptr}}, 2}, {}, {});
  EXPECT_EQ(r.bytes_written(), 4u * kW * kH);
  EXPECT_TRUE(r.passes[0].attachments[1].transient);
  EXPECT_EQ(r.passes[0].attachments[1].bytes_stored, 0u);
  EXPECT_EQ(r.passes[0].attachments[2].bytes_stored, 0u);
}

TEST(Traffic, MultisampleResolveStoresOnlyResolvedPixels) {
  RenderContext ctx;
  Surface* resolved = ctx.create_surface("r", PixelFormat::RGBA8_UNORM, kW, kH);
  const FrameReport r = run(ctx, {{{"c", PixelFormat::RGBA8_UNORM, LoadAction::Clear, StoreAction::Resolve,
                                     glm::vec4(0.0f), nullptr, resolved}}, -1, 4}, {}, {});
  EXPECT_EQ(r.bytes_written(), 4u * kW * kH);
  EXPECT_EQ(r.passes[0].attachments[0].bytes_resolved, 4u * kW * kH);
}

TEST(Traffic, ParameterBufferMatchesTheRecordSizes) {
  // One triangle inside a single 16x16 tile, 3 varyings: 3 vertices of 16 + 12 bytes written,
  // one primitive record and one list entry; the tile reads them back once.
  RenderContext ctx;
  Surface* s = ctx.create_surface("c", PixelFormat::R32_FLOAT, kW, kH);
  const std::vector<glm::vec4> pos = {pixel_to_clip(17, 17, kW, kH), pixel_to_clip(30, 18, kW, kH),
                                      pixel_to_clip(20, 30, kW, kH)};
  const FrameReport r = run(ctx, {{{"c", PixelFormat::R32_FLOAT, LoadAction::Clear, StoreAction::Store,
                                     glm::vec4(0.0f), s, nullptr}}}, pos, {0, 1, 2}, 3);
  const PassReport& p = r.passes[0];
  const uint64_t vertex = 16 + 4 * 3;
  EXPECT_EQ(p.geometry.tile_list_entries, 1u);
  EXPECT_EQ(p.geometry.parameter_bytes_written, 3 * vertex + 12 + 4);
  EXPECT_EQ(p.tiles.parameter_bytes_read, 4 + 12 + 3 * vertex);
  EXPECT_EQ(p.geometry.index_bytes_read, 12u);
  EXPECT_EQ(p.tiles.tiles_executed, 1u);
}

TEST(Traffic, OverBudgetColourHalvesTheTileArea) {
  RenderContext ctx;
  std::vector<AttachmentDesc> gbuffer;
  for (const char* name : {"a", "b", "c"}) {  // 3 x 64 bits = 192 > 128
    gbuffer.push_back({name, PixelFormat::RGBA16_FLOAT, LoadAction::Clear, StoreAction::DontCare,
                       glm::vec4(0.0f), nullptr, nullptr});
  }
  const FrameReport r = run(ctx, {gbuffer}, {}, {});
  EXPECT_EQ(r.passes[0].tile_width_px * r.passes[0].tile_height_px, 128);
  EXPECT_TRUE(r.passes[0].tile_size_reduced);
  EXPECT_EQ(r.passes[0].color_bits_per_px, 192);
}

TEST(Traffic, NonFiniteTrianglesAreDroppedAndCountedAndChangeNothingElse) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<glm::vec4> pos = {pixel_to_clip(5, 5, kW, kH), pixel_to_clip(60, 8, kW, kH),
                                pixel_to_clip(10, 50, kW, kH), {nan, 0.0f, 0.5f, 1.0f},
                                {0.0f, inf, 0.5f, 1.0f}, {0.1f, 0.1f, 0.5f, -inf}};
  const CountResult clean = draw_counting(pos, {0, 1, 2}, kW, kH);
  const CountResult dirty = draw_counting(pos, {0, 1, 2, 0, 3, 1, 4, 1, 2, 5, 0, 2}, kW, kH);
  EXPECT_EQ(dirty.report.passes[0].geometry.triangles_non_finite, 3u);
  EXPECT_EQ(clean.counts, dirty.counts);
}

TEST(Traffic, NothingRunsBeforeSubmit) {
  RenderContext ctx;
  Surface* s = ctx.create_surface("c", PixelFormat::RGBA8_UNORM, kW, kH);
  s->fill(glm::vec4(0.0f));
  ctx.begin_render_pass("p", kW, kH, 1, {{"c", PixelFormat::RGBA8_UNORM, LoadAction::Clear,
                                          StoreAction::Store, glm::vec4(1.0f), s, nullptr}}, -1);
  ctx.begin_subpass({0});
  ctx.end_subpass();
  ctx.end_render_pass();
  EXPECT_EQ(s->read(0, 0).x, 0.0f);
  ctx.submit();
  EXPECT_EQ(s->read(0, 0).x, 1.0f);
}

}  // namespace
}  // namespace ontile::test
