// The optional parameter-buffer read cache: with it, a triangle listed in many tiles is fetched
// once (exact granule counts from the documented layout); without it, every list entry is
// charged in full; and the counts do not depend on the thread count.
#include <gtest/gtest.h>

#include "support/raster_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 64, kH = 64;  // 16 tiles of 16x16
constexpr int kVaryings = 4;     // post-transform vertex: 16 + 4 x 4 = 32 bytes

FrameReport draw_full_screen_triangle(uint32_t parameter_cache_bytes, int threads = 2) {
  ContextConfig config;
  config.threads = threads;
  config.tiler.parameter_cache.size_bytes = parameter_cache_bytes;
  RenderContext ctx(config);
  Surface* s = ctx.create_surface("c", PixelFormat::RGBA8_UNORM, kW, kH);
  // One triangle covering the whole target (listed in all 16 tiles), drawn twice.
  const std::vector<glm::vec4> pos = {{-1, -1, 0.5f, 1}, {3, -1, 0.5f, 1}, {-1, 3, 0.5f, 1}};
  ClipSpaceVertexShader vs(pos, std::vector<float>(pos.size() * kVaryings, 0.25f), kVaryings);
  ConstantOneShader fs;
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 1, 2};
  ctx.begin_render_pass("p", kW, kH, 1,
                        {{"c", PixelFormat::RGBA8_UNORM, LoadAction::Clear, StoreAction::Store, glm::vec4(0.0f), s, nullptr}},
                        -1);
  ctx.begin_subpass({0});
  DrawCall d;
  d.vertex_shader = &vs;
  d.fragment_shader = &fs;
  d.vertex_count = 3;
  d.indices = idx.data();
  d.index_count = 6;
  d.raster.cull = CullMode::None;
  ctx.draw(d);
  ctx.end_subpass();
  ctx.end_render_pass();
  return ctx.submit();
}

TEST(ParameterCache, WithoutItEveryListEntryIsChargedInFull) {
  const FrameReport r = draw_full_screen_triangle(0);
  // 2 triangles x 16 tiles, each entry: 4 (list) + 12 (record) + 3 x 32 (vertices).
  EXPECT_EQ(r.passes[0].tiles.parameter_bytes_read, 32u * (4 + 12 + 96));
  EXPECT_EQ(r.passes[0].parameter_cache.accesses, 0u);
}

TEST(ParameterCache, ATriangleListedInManyTilesIsFetchedOnce) {
  const FrameReport r = draw_full_screen_triangle(64 * 1024);
  const TextureTraffic& c = r.passes[0].parameter_cache;
  // Layout: 32 list entries (128 B: lines 0-1), 2 records at 128 (24 B: line 2), the draw's 3
  // shared vertices of 32 B at 192 (lines 3, 3, 4). Per tile: 2 entries (same line), 2 records
  // (line 2), 2 x 3 vertex reads: 10 lookups.
  EXPECT_EQ(c.accesses, 16u * 10);
  EXPECT_EQ(c.misses, 5u) << "lines 0-4, each fetched once";
  EXPECT_EQ(c.hits, c.accesses - c.misses);
  EXPECT_EQ(r.passes[0].tiles.parameter_bytes_read, 5u * 64);
}

TEST(ParameterCache, CountsDoNotDependOnTheThreadCount) {
  const FrameReport one = draw_full_screen_triangle(4096, 1);
  const FrameReport many = draw_full_screen_triangle(4096, 7);
  EXPECT_EQ(one.passes[0].parameter_cache.misses, many.passes[0].parameter_cache.misses);
  EXPECT_EQ(one.passes[0].tiles.parameter_bytes_read, many.passes[0].tiles.parameter_bytes_read);
}

}  // namespace
}  // namespace ontile::test
