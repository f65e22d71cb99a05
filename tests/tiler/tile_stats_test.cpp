// Per-tile statistics and per-texture attribution of a pass's traffic (PassReport::tile_stats,
// texture_sources): every column sums to the pass's own counter, the deterministic columns do not
// depend on the thread count (serial texture replay at 1 thread, parallel from 4), and texture
// bytes read from render targets are attributed to the targets an earlier pass stored.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "pipelines/kit/render_frame.h"
#include "support/generated_scene.h"

namespace ontile {
namespace {

RenderedFrame render_demo(const Scene& scene, const std::string& pipeline, int threads) {
  RenderSettings s;
  s.pipeline = pipeline;
  s.width_px = 317;  // odd sizes: partial tiles at the right and bottom edges
  s.height_px = 181;
  s.context.threads = threads;
  return render_frame(scene, s);
}

template <typename Field>
uint64_t column_sum(const PassReport& p, Field field) {
  uint64_t sum = 0;
  for (const TileStats& t : p.tile_stats) sum += field(t);
  return sum;
}

void expect_columns_sum_to_the_pass(const PassReport& p, const std::string& what) {
  ASSERT_EQ(p.tile_stats.size(), p.tiles_total) << what;
  ASSERT_EQ(static_cast<uint64_t>(p.tiles_x()) * p.tiles_y(), p.tiles_total) << what;
  EXPECT_EQ(column_sum(p, [](const TileStats& t) { return t.triangles; }), p.geometry.tile_list_entries) << what;
  EXPECT_EQ(column_sum(p, [](const TileStats& t) { return t.fragments_shaded; }), p.tiles.fragments_shaded) << what;
  EXPECT_EQ(column_sum(p, [](const TileStats& t) { return t.fragments_depth_rejected; }),
            p.tiles.fragments_depth_rejected) << what;
  EXPECT_EQ(column_sum(p, [](const TileStats& t) { return t.cells_rasterized; }), p.tiles.cells_rasterized) << what;
  EXPECT_EQ(column_sum(p, [](const TileStats& t) { return t.cells_hiz_rejected; }), p.tiles.cells_hiz_rejected) << what;
  EXPECT_EQ(column_sum(p, [](const TileStats& t) { return t.parameter_bytes_read; }), p.tiles.parameter_bytes_read) << what;
  EXPECT_EQ(column_sum(p, [](const TileStats& t) { return t.bytes_loaded; }), p.attachment_bytes_loaded()) << what;
  EXPECT_EQ(column_sum(p, [](const TileStats& t) { return t.bytes_stored; }), p.attachment_bytes_stored()) << what;
  EXPECT_EQ(column_sum(p, [](const TileStats& t) { return t.texture_bytes_read; }), p.texture.bytes_read) << what;
  uint64_t source_misses = 0, source_bytes = 0;
  for (const TextureSourceTraffic& s : p.texture_sources) {
    source_misses += s.misses;
    source_bytes += s.bytes_read;
    EXPECT_FALSE(s.name.empty()) << what;
  }
  EXPECT_EQ(source_misses, p.texture.misses) << what;
  EXPECT_EQ(source_bytes, p.texture.bytes_read) << what;
}

// The deterministic columns and the sources of two renders of one frame.
void expect_same_counts(const PassReport& a, const PassReport& b, const std::string& what) {
  ASSERT_EQ(a.tile_stats.size(), b.tile_stats.size()) << what;
  for (size_t t = 0; t < a.tile_stats.size(); ++t) {
    const TileStats &x = a.tile_stats[t], &y = b.tile_stats[t];
    const std::string tile = what + " tile " + std::to_string(t);
    EXPECT_EQ(x.triangles, y.triangles) << tile;
    EXPECT_EQ(x.fragments_shaded, y.fragments_shaded) << tile;
    EXPECT_EQ(x.fragments_depth_rejected, y.fragments_depth_rejected) << tile;
    EXPECT_EQ(x.cells_rasterized, y.cells_rasterized) << tile;
    EXPECT_EQ(x.cells_hiz_rejected, y.cells_hiz_rejected) << tile;
    EXPECT_EQ(x.bytes_loaded, y.bytes_loaded) << tile;
    EXPECT_EQ(x.bytes_stored, y.bytes_stored) << tile;
    EXPECT_EQ(x.texture_bytes_read, y.texture_bytes_read) << tile;
  }
  ASSERT_EQ(a.texture_sources.size(), b.texture_sources.size()) << what;
  for (size_t i = 0; i < a.texture_sources.size(); ++i) {
    EXPECT_EQ(a.texture_sources[i].name, b.texture_sources[i].name) << what;
    EXPECT_EQ(a.texture_sources[i].render_target, b.texture_sources[i].render_target) << what;
    EXPECT_EQ(a.texture_sources[i].bytes_read, b.texture_sources[i].bytes_read) << what;
  }
}

TEST(TileStats, ColumnsSumToThePassAndDoNotDependOnThreads) {
  const Scene demo = test::generated_scene("demo", 1.0);
  for (const std::string pipeline : {"lambert", "cartoon", "deferred-classic", "universal"}) {
    const RenderedFrame serial = render_demo(demo, pipeline, 1);
    const RenderedFrame parallel = render_demo(demo, pipeline, 4);  // parallel texture replay
    const std::vector<PassReport>& a = serial.outputs.report.passes;
    const std::vector<PassReport>& b = parallel.outputs.report.passes;
    ASSERT_EQ(a.size(), b.size()) << pipeline;
    for (size_t i = 0; i < a.size(); ++i) {
      const std::string what = pipeline + " pass " + a[i].name;
      expect_columns_sum_to_the_pass(a[i], what);
      expect_columns_sum_to_the_pass(b[i], what + " (4 threads)");
      expect_same_counts(a[i], b[i], what);
      std::set<uint32_t> orders;
      for (const TileStats& t : b[i].tile_stats) {
        EXPECT_GE(t.thread, 0) << what;
        EXPECT_LT(t.thread, 4) << what;
        orders.insert(t.order);
      }
      // Every tile started once: the orders are a permutation of 0..tiles-1.
      EXPECT_EQ(orders.size(), b[i].tile_stats.size()) << what;
      if (!orders.empty()) {
        EXPECT_EQ(*orders.rbegin(), b[i].tile_stats.size() - 1) << what;
      }
    }
  }
}

// Classic deferred reads its G-buffer back as textures in the lighting pass: those bytes must be
// charged to the G-buffer targets, each one an attachment an earlier pass stored.
TEST(TileStats, RenderTargetReadsAreAttributedToTheTargetsEarlierPassesStored) {
  const Scene demo = test::generated_scene("demo", 1.0);
  for (const std::string pipeline : {"deferred-classic", "cartoon"}) {
    const RenderedFrame frame = render_demo(demo, pipeline, 2);
    std::set<std::string> stored;
    uint64_t render_target_bytes = 0;
    for (const PassReport& p : frame.outputs.report.passes) {
      for (const TextureSourceTraffic& s : p.texture_sources) {
        if (!s.render_target) continue;
        EXPECT_TRUE(stored.count(s.name)) << pipeline << ": pass " << p.name << " reads '" << s.name
                                          << "', which no earlier pass stored";
        render_target_bytes += s.bytes_read;
      }
      for (const AttachmentTraffic& a : p.attachments) {
        if (a.bytes_stored || a.bytes_resolved) stored.insert(a.name);
      }
    }
    EXPECT_GT(render_target_bytes, 0u) << pipeline;
  }
}

// The IMR model has no tile memory: per-tile attachment bytes are 0, the rest still sums.
TEST(TileStats, ImrPassesChargeNoAttachmentBytesToTiles) {
  const Scene demo = test::generated_scene("demo", 1.0);
  RenderSettings s;
  s.pipeline = "cartoon";
  s.width_px = 160;
  s.height_px = 90;
  s.context.tiler.architecture = Architecture::Imr;
  const RenderedFrame frame = render_frame(demo, s);
  for (const PassReport& p : frame.outputs.report.passes) {
    EXPECT_GT(p.attachment_bytes_stored(), 0u) << p.name;
    EXPECT_EQ(column_sum(p, [](const TileStats& t) { return t.bytes_loaded + t.bytes_stored; }), 0u) << p.name;
    EXPECT_EQ(column_sum(p, [](const TileStats& t) { return t.texture_bytes_read; }), p.texture.bytes_read) << p.name;
  }
}

}  // namespace
}  // namespace ontile
