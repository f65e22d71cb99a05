// IMR render-target cache model: exact traffic for hand-made fragment traces (layout, LRU,
// replay order, MRT subsets, resolve) and for whole passes run through the render context
// (full-screen triangle, small cache, determinism across threads, same image as TBDR).
#include <gtest/gtest.h>

#include "context/frame_report.h"
#include "support/raster_harness.h"
#include "memory/imr_model.h"
#include "tiler/render_pass_executor.h"
#include "util/error.h"

namespace ontile::test {
namespace {

FragmentAccess fragment(uint32_t ref, int x, int y, uint8_t samples, uint8_t flags,
                        uint8_t subpass = 0) {
  FragmentAccess f;
  f.triangle_ref = ref;
  f.x_px = static_cast<uint16_t>(x);
  f.y_px = static_cast<uint16_t>(y);
  f.covered_samples = samples;
  f.written_samples = samples;
  f.flags = flags;
  f.subpass = subpass;
  return f;
}

RenderPassDesc pass_of(int width, int height, int samples, std::vector<AttachmentDesc> attachments,
                       int depth_index, std::vector<std::vector<int>> subpass_outputs) {
  RenderPassDesc pass;
  pass.name = "imr";
  pass.width_px = width;
  pass.height_px = height;
  pass.samples = samples;
  pass.attachments = std::move(attachments);
  pass.depth_index = depth_index;
  for (auto& outputs : subpass_outputs) pass.subpasses.push_back(SubpassDesc{outputs, {}, false, {}});
  return pass;
}

AttachmentDesc attachment(PixelFormat format, LoadAction load, StoreAction store) {
  return AttachmentDesc{"a", format, load, store, glm::vec4(1.0f), nullptr, nullptr};
}

TEST(ImrModel, ClearStoreWithoutDrawsWritesTheSurfaceOnce) {
  // 8x8 RGBA8: the clear writes 8 * 8 * 4 = 256 bytes; nothing is read or cached.
  const RenderPassDesc pass =
      pass_of(8, 8, 1, {attachment(PixelFormat::RGBA8_UNORM, LoadAction::Clear, StoreAction::Store)},
              -1, {{0}});
  const ImrTraffic t = simulate_imr_pass(describe_pass_memory(pass, 16, 16), std::vector<TileTrace>(4), {});
  ASSERT_EQ(t.attachments.size(), 1u);
  EXPECT_EQ(t.attachments[0].bytes_written, 256u);
  EXPECT_EQ(t.attachments[0].bytes_read, 0u);
  EXPECT_EQ(t.cache_hits, 0u);
  EXPECT_EQ(t.cache_misses, 0u);
}

TEST(ImrModel, SamplesOfAPixelAreAdjacentAndSpanLines) {
  // 8 samples of RGBA32F = 128 bytes per pixel: pixel 0 is lines 0-1, pixel 1 lines 2-3 (64-byte
  // lines). Samples 0-3 of pixel 1 are line 2, samples 4-7 line 3; mask 0x11 of pixel 0 touches
  // lines 0 and 1. Accesses: w2 miss, w3 miss, r0 miss, r1 miss, w0 hit, w1 hit.
  const RenderPassDesc pass =
      pass_of(2, 1, 8, {attachment(PixelFormat::RGBA32_FLOAT, LoadAction::DontCare, StoreAction::Store)},
              -1, {{0}});
  std::vector<TileTrace> traces(1);
  traces[0].fragments = {fragment(0, 1, 0, 0x0F, kColorWritten), fragment(1, 1, 0, 0xF0, kColorWritten),
                         fragment(2, 0, 0, 0x11, kColorWritten | kColorRead)};
  const ImrTraffic t = simulate_imr_pass(describe_pass_memory(pass, 16, 16), traces, {});
  EXPECT_EQ(t.cache_misses, 4u);
  EXPECT_EQ(t.cache_hits, 2u);
  EXPECT_EQ(t.attachments[0].bytes_read, 4u * 64);     // four fills
  EXPECT_EQ(t.attachments[0].bytes_written, 4u * 64);  // four dirty lines at the flush
}

TEST(ImrModel, LeastRecentlyUsedLineIsEvicted) {
  // One set of two 64-byte ways; D32F 64x1 depth, so pixel x lies in line x / 16.
  // w0 miss, w16 miss, r0 hit (0 becomes most recent), w32 miss evicting dirty 16 (+64 written),
  // r0 hit, w16 miss evicting dirty 32 (+64). Flush writes dirty 0 and 16 (+128).
  // FIFO would evict line 0 at w32 instead, and r0 would then miss.
  const RenderPassDesc pass =
      pass_of(64, 1, 1, {attachment(PixelFormat::D32_FLOAT, LoadAction::DontCare, StoreAction::DontCare)},
              0, {{}});
  std::vector<TileTrace> traces(1);
  traces[0].fragments = {fragment(0, 0, 0, 1, kDepthWritten), fragment(1, 16, 0, 1, kDepthWritten),
                         fragment(2, 0, 0, 1, kDepthRead), fragment(3, 32, 0, 1, kDepthWritten),
                         fragment(4, 0, 0, 1, kDepthRead), fragment(5, 16, 0, 1, kDepthWritten)};
  const ImrTraffic t = simulate_imr_pass(describe_pass_memory(pass, 16, 16), traces, {128, 64, 2});
  EXPECT_EQ(t.cache_hits, 2u);
  EXPECT_EQ(t.cache_misses, 4u);
  EXPECT_EQ(t.attachments[0].bytes_read, 4u * 64);
  EXPECT_EQ(t.attachments[0].bytes_written, 4u * 64);
}

TEST(ImrModel, LinesMapToSetsByLineAddressModuloSetCount) {
  // Direct-mapped, two sets: lines 0 and 2 share set 0, line 1 is in set 1 (R32F 64x1: pixel
  // x in line x / 16). r0 miss, r16 miss, r0 hit, r32 miss (evicts 0), r0 miss. Clean lines
  // are never written back.
  const RenderPassDesc pass =
      pass_of(64, 1, 1, {attachment(PixelFormat::D32_FLOAT, LoadAction::Clear, StoreAction::Store)},
              0, {{}});
  std::vector<TileTrace> traces(1);
  for (uint32_t i = 0; const int x : {0, 16, 0, 32, 0}) traces[0].fragments.push_back(fragment(i++, x, 0, 1, kDepthRead));
  const ImrTraffic t = simulate_imr_pass(describe_pass_memory(pass, 16, 16), traces, {128, 64, 1});
  EXPECT_EQ(t.cache_hits, 1u);
  EXPECT_EQ(t.cache_misses, 4u);
  EXPECT_EQ(t.attachments[0].bytes_read, 4u * 64);
  EXPECT_EQ(t.attachments[0].bytes_written, 64u * 4);  // the clear only
}

TEST(ImrModel, ReplaysTrianglesInSubmissionOrderThenTileOrder) {
  // A one-line cache makes every change of line a miss. R32F 32x1: x 0 is line 0, x 16 line 1.
  // Tile 0: refs 5, 5, 9 at lines 0, 0, 1; tile 1: refs 5, 7 at lines 1, 0.
  // Merged order: t0 r5 (0 miss, 0 hit), t1 r5 (1 miss), t1 r7 (0 miss), t0 r9 (1 miss):
  // 4 misses, 1 hit. Tile-by-tile order would give 0, 0, 1, 1, 0: 3 misses, 2 hits.
  const RenderPassDesc pass =
      pass_of(32, 1, 1, {attachment(PixelFormat::D32_FLOAT, LoadAction::DontCare, StoreAction::Store)},
              0, {{}});
  std::vector<TileTrace> traces(2);
  traces[0].fragments = {fragment(5, 0, 0, 1, kDepthRead), fragment(5, 1, 0, 1, kDepthRead),
                         fragment(9, 16, 0, 1, kDepthRead)};
  traces[1].fragments = {fragment(5, 16, 0, 1, kDepthRead), fragment(7, 0, 0, 1, kDepthRead)};
  const ImrTraffic t = simulate_imr_pass(describe_pass_memory(pass, 16, 16), traces, {64, 64, 1});
  EXPECT_EQ(t.cache_misses, 4u);
  EXPECT_EQ(t.cache_hits, 1u);

  traces[1].fragments = {fragment(7, 16, 0, 1, kDepthRead), fragment(5, 0, 0, 1, kDepthRead)};
  EXPECT_THROW(simulate_imr_pass(describe_pass_memory(pass, 16, 16), traces, {64, 64, 1}), Error);
}

TEST(ImrModel, ColourGoesToTheFragmentSubpassOutputsOnly) {
  // Subpass 0 writes attachments 0 and 1, subpass 1 writes attachment 2 (RGBA8 4x4, one line
  // each). Only subpass 0's fragment: attachment 2 moves nothing.
  const AttachmentDesc c = attachment(PixelFormat::RGBA8_UNORM, LoadAction::DontCare, StoreAction::Store);
  const RenderPassDesc pass = pass_of(4, 4, 1, {c, c, c}, -1, {{0, 1}, {2}});
  std::vector<TileTrace> traces(1);
  traces[0].fragments = {fragment(0, 1, 1, 1, kColorWritten, 0)};
  ImrTraffic t = simulate_imr_pass(describe_pass_memory(pass, 16, 16), traces, {});
  for (int a : {0, 1}) {
    EXPECT_EQ(t.attachments[a].bytes_read, 64u) << a;
    EXPECT_EQ(t.attachments[a].bytes_written, 64u) << a;
  }
  EXPECT_EQ(t.attachments[2].bytes_read, 0u);
  EXPECT_EQ(t.attachments[2].bytes_written, 0u);
  EXPECT_EQ(t.cache_misses, 2u);

  traces[0].fragments.push_back(fragment(1, 2, 2, 1, kColorWritten, 1));
  t = simulate_imr_pass(describe_pass_memory(pass, 16, 16), traces, {});
  EXPECT_EQ(t.attachments[2].bytes_read, 64u);
  EXPECT_EQ(t.attachments[2].bytes_written, 64u);
  EXPECT_EQ(t.cache_misses, 3u);
  EXPECT_EQ(t.cache_hits, 0u);
}

TEST(ImrModel, ResolveReadsAllSamplesAndWritesOnePerPixel) {
  // 4x4, 4 samples, RGBA8, Clear + Resolve, no fragments: clear 4*4*4*4 = 256 written; the
  // resolve reads those 256 bytes and writes 4*4*4 = 64.
  const RenderPassDesc pass =
      pass_of(4, 4, 4, {attachment(PixelFormat::RGBA8_UNORM, LoadAction::Clear, StoreAction::Resolve)},
              -1, {{0}});
  const ImrTraffic t = simulate_imr_pass(describe_pass_memory(pass, 16, 16), std::vector<TileTrace>(1), {});
  EXPECT_EQ(t.attachments[0].bytes_read, 256u);
  EXPECT_EQ(t.attachments[0].bytes_written, 256u + 64u);
  EXPECT_EQ(t.attachments[0].bytes_resolved, 64u);
}

TEST(ImrModel, RejectsInvalidCacheConfigurations) {
  const RenderPassDesc pass =
      pass_of(4, 4, 1, {attachment(PixelFormat::RGBA8_UNORM, LoadAction::Clear, StoreAction::Store)},
              -1, {{0}});
  const std::vector<TileTrace> traces(1);
  EXPECT_THROW(simulate_imr_pass(describe_pass_memory(pass, 16, 16), traces, {1024, 48, 4}), Error);   // line not a power of 2
  EXPECT_THROW(simulate_imr_pass(describe_pass_memory(pass, 16, 16), traces, {1000, 64, 4}), Error);   // not whole sets
  EXPECT_THROW(simulate_imr_pass(describe_pass_memory(pass, 16, 16), traces, {1024, 64, 0}), Error);   // no ways
  EXPECT_NO_THROW(simulate_imr_pass(describe_pass_memory(pass, 16, 16), traces, {192, 64, 1}));        // 3 sets is fine
}

// --- Whole passes through the render context ------------------------------------------------

struct Drawn {
  FrameReport report;
  std::vector<uint8_t> image;
};

struct Triangles {
  std::vector<glm::vec4> positions;
  std::vector<float> colours;  // 4 varyings per vertex
  std::vector<uint32_t> indices;
  void add(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double z, glm::vec4 colour, int w, int h) {
    for (const glm::dvec2& p : {a, b, c}) {
      indices.push_back(static_cast<uint32_t>(positions.size()));
      positions.push_back(pixel_to_clip(p.x, p.y, w, h, 1.0, z));
      for (int k = 0; k < 4; ++k) colours.push_back(colour[k]);
    }
  }
};

// RGBA8 colour (Clear + Store) and transient D32F depth (Clear 1.0 + DontCare). The first
// `opaque_count` triangles draw opaque with depth test and write; the rest blend additively.
Drawn draw_pass(const Triangles& tris, size_t opaque_count, int w, int h, int threads,
                Architecture arch, RenderTargetCacheConfig cache = {}) {
  ContextConfig cfg;
  cfg.threads = threads;
  cfg.tiler.tile_size_px = 16;
  cfg.tiler.architecture = arch;
  cfg.tiler.render_target_cache = cache;
  RenderContext ctx(cfg);
  Surface* colour = ctx.create_surface("colour", PixelFormat::RGBA8_UNORM, w, h);
  ClipSpaceVertexShader vs(tris.positions, tris.colours, 4);
  VaryingsShader fs;
  const AttachmentDesc colour_desc{"colour", PixelFormat::RGBA8_UNORM, LoadAction::Clear,
                                   StoreAction::Store, glm::vec4(0.0f), colour, nullptr};
  const AttachmentDesc depth_desc{"depth", PixelFormat::D32_FLOAT, LoadAction::Clear,
                                  StoreAction::DontCare, glm::vec4(1.0f), nullptr, nullptr};
  ctx.begin_render_pass("imr", w, h, 1, {colour_desc, depth_desc}, 1);
  ctx.begin_subpass({0});
  DrawCall d;
  d.vertex_shader = &vs;
  d.fragment_shader = &fs;
  d.vertex_count = vs.vertex_count();
  d.raster.cull = CullMode::None;
  d.indices = tris.indices.data();
  d.index_count = static_cast<uint32_t>(opaque_count * 3);
  if (d.index_count) ctx.draw(d);
  d.indices += d.index_count;
  d.index_count = static_cast<uint32_t>(tris.indices.size()) - d.index_count;
  d.blend.mode = BlendMode::Additive;
  d.raster.depth_write = false;
  if (d.index_count) ctx.draw(d);
  ctx.end_subpass();
  ctx.end_render_pass();
  Drawn out;
  out.report = ctx.submit();
  out.image = colour->bytes();
  return out;
}

// A triangle covering the whole target without clipping (the guard band holds it).
void add_full_screen(Triangles& tris, int w, int h, double z) {
  tris.add({0, 0}, {2.0 * w, 0}, {0, 2.0 * h}, z, glm::vec4(0.5f), w, h);
}

TEST(ImrModel, FullScreenTriangleInACacheThatHoldsTheTarget) {
  // 16x16: colour RGBA8 and depth D32F are 1024 bytes = 16 lines each, 32 lines in all, in
  // distinct sets of the default 128 KiB / 64 B / 16-way cache (128 sets), so each line misses
  // once. Per attachment: clear 1024 written, fills 1024 read, flush 1024 written (depth too:
  // an IMR cannot discard, DontCare saves nothing). Accesses: 256 pixels x (depth read, depth
  // write, colour write) = 768, of which 32 miss.
  constexpr int kW = 16, kH = 16;
  Triangles tris;
  add_full_screen(tris, kW, kH, 0.5);
  const Drawn imr = draw_pass(tris, 1, kW, kH, 2, Architecture::Imr);
  const PassReport& p = imr.report.passes.at(0);
  ASSERT_EQ(p.geometry.triangles_clipped, 0u);
  ASSERT_EQ(p.tiles.fragments_shaded, uint64_t{kW * kH});
  EXPECT_EQ(p.architecture, "imr");
  for (const AttachmentTraffic& a : p.attachments) {
    EXPECT_FALSE(a.transient) << a.name;
    EXPECT_EQ(a.bytes_loaded, 1024u) << a.name;
    EXPECT_EQ(a.bytes_stored, 2048u) << a.name;
  }
  EXPECT_EQ(p.render_target_cache_misses, 32u);
  EXPECT_EQ(p.render_target_cache_hits, 768u - 32u);
}

TEST(ImrModel, SmallCacheMovesMoreThanALargeOne) {
  // 32x32, two full-screen triangles (the second nearer, so it passes the depth test and
  // rewrites everything). Large cache: as above, 4096 bytes filled and 4096 written back per
  // attachment. 1 KiB cache (16 lines, one set): quads are walked row by row in each 16x16 tile,
  // and a tile row is one 64-byte line per attachment, so no line is revisited within a
  // triangle after it left the cache, and all have left by the second triangle: every line is
  // filled and written back once per triangle, 2 * 4096 bytes each.
  constexpr int kW = 32, kH = 32;
  Triangles tris;
  add_full_screen(tris, kW, kH, 0.5);
  add_full_screen(tris, kW, kH, 0.25);
  const Drawn large = draw_pass(tris, 2, kW, kH, 2, Architecture::Imr);
  const Drawn small = draw_pass(tris, 2, kW, kH, 2, Architecture::Imr, {1024, 64, 16});
  for (size_t a = 0; a < 2; ++a) {
    EXPECT_EQ(large.report.passes[0].attachments[a].bytes_loaded, 4096u) << a;
    EXPECT_EQ(large.report.passes[0].attachments[a].bytes_stored, 4096u + 4096u) << a;
    EXPECT_EQ(small.report.passes[0].attachments[a].bytes_loaded, 2u * 4096u) << a;
    EXPECT_EQ(small.report.passes[0].attachments[a].bytes_stored, 4096u + 2u * 4096u) << a;
  }
  EXPECT_GT(small.report.bytes_read() + small.report.bytes_written(),
            large.report.bytes_read() + large.report.bytes_written());
  EXPECT_EQ(small.report.passes[0].render_target_cache_misses, 2u * 4 * 32);
  EXPECT_EQ(large.report.passes[0].render_target_cache_misses, 2u * 64);
  EXPECT_TRUE(small.image == large.image);
}

nlohmann::json without_timing(const FrameReport& report) {
  nlohmann::json j = frame_report_json(report);
  j.erase("timing");
  return j;
}

TEST(ImrModel, SameTrafficAtAnyThreadCountAndSameImageAsTbdr) {
  // Overlapping opaque and blended triangles across tile borders, in a 4 KiB cache so that
  // eviction order matters.
  constexpr int kW = 72, kH = 40;
  Triangles tris;
  tris.add({3, 2}, {70, 9}, {20, 38}, 0.6, {0.9f, 0.1f, 0.2f, 1.0f}, kW, kH);
  tris.add({60, 1}, {5, 30}, {66, 39}, 0.4, {0.1f, 0.8f, 0.3f, 1.0f}, kW, kH);
  tris.add({-10, 20}, {80, 15}, {35, -5}, 0.5, {0.2f, 0.2f, 0.9f, 1.0f}, kW, kH);
  tris.add({10, 35}, {50, 3}, {71, 33}, 0.3, {0.25f, 0.125f, 0.0625f, 0.5f}, kW, kH);
  tris.add({0, 0}, {72, 40}, {0, 40}, 0.7, {0.0625f, 0.25f, 0.125f, 0.5f}, kW, kH);
  const RenderTargetCacheConfig cache{4096, 64, 4};
  const Drawn reference = draw_pass(tris, 3, kW, kH, 1, Architecture::Imr, cache);
  const nlohmann::json reference_json = without_timing(reference.report);
  EXPECT_GT(reference.report.passes[0].render_target_cache_misses, 0u);
  for (int threads : {2, 7}) {
    const Drawn d = draw_pass(tris, 3, kW, kH, threads, Architecture::Imr, cache);
    EXPECT_EQ(without_timing(d.report), reference_json) << threads << " threads";
    EXPECT_TRUE(d.image == reference.image) << threads << " threads";
  }
  const Drawn tbdr = draw_pass(tris, 3, kW, kH, 2, Architecture::Tbdr, cache);
  EXPECT_TRUE(tbdr.image == reference.image);
  EXPECT_EQ(tbdr.report.passes[0].architecture, "tbdr");
  EXPECT_GT(reference.report.bytes_read(), tbdr.report.bytes_read());
}

}  // namespace
}  // namespace ontile::test
