// The Sobel pass's 32-bit trace kernel (tagged granules, gathered read patterns) against the
// 64-bit one: the same granules, count and last granule on full-screen batches (interior,
// clamped borders, granule boundaries, edges with and without border reads), random taps,
// partial masks, one texture bound as two planes, on every SIMD target.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "memory/trace_repeats.h"
#include "raster/cell_raster.h"
#include "shaders_cpp/toon/sobel_trace_kernel.h"

namespace ontile::sobel {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

TracePlane plane(uint64_t texture_id, uint64_t offset_bytes, uint64_t texel_bytes, int width,
                 int height) {
  TracePlane p;
  p.origin = (texture_id << 40) + offset_bytes;  // as Texture2D places level 0 (plus an offset)
  p.texel_bytes = texel_bytes;
  p.width = width;
  p.height = height;
  return p;
}

// Taps of a 16x4 block of pixels at (x0, y0) in quad order, as a full-screen pass at thickness
// `step` places them (clamped to the grid), or anywhere in the grid when scattered.
void fill_taps(std::mt19937& rng, int x0, int y0, int step, bool scattered, int grid_w, int grid_h,
               int color_w, int color_h, FragmentTaps& taps) {
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  const auto clamp = [](int v, int hi) { return v < 0 ? 0 : (v >= hi ? hi - 1 : v); };
  for (int f = 0; f < kBatchFragments; ++f) {
    const int q = f / 4, lane = f % 4;
    const int x = scattered ? pick(grid_w) : x0 + 2 * (q % 8) + (lane & 1);
    const int y = scattered ? pick(grid_h) : y0 + 2 * (q / 8) + (lane >> 1);
    for (int a = 0; a < kTapsPerAxis; ++a) {
      taps.x[a][f] = clamp(x + (a - 1) * step, grid_w);
      taps.y[a][f] = clamp(y + (a - 1) * step, grid_h);
    }
    taps.color_x[f] = clamp(x * color_w / grid_w, color_w);
    taps.color_y[f] = clamp(y * color_h / grid_h, color_h);
  }
}

// Random edge flags of a batch, an edge about once in `edge_odds` fragments, and nearest taps.
FragmentEdges random_edges(std::mt19937& rng, int edge_odds) {
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  FragmentEdges edges;
  for (int f = 0; f < kBatchFragments; ++f) {
    const bool depth_edge = pick(edge_odds) == 0;
    const bool edge = depth_edge || pick(edge_odds) == 0;
    edges.depth_edge |= uint64_t{depth_edge} << f;
    edges.edge |= uint64_t{edge} << f;
    edges.nearest_tap[f] = pick(kTaps);
  }
  return edges;
}

// The active fragments of a batch of `count`: all of them, or random ones in every fifth batch.
// The two draws are separate statements (operands of | are unsequenced).
uint64_t random_active(std::mt19937& rng, int b, int count) {
  const uint64_t in_count = count == 64 ? ~uint64_t{0} : (uint64_t{1} << count) - 1;
  if (b % 5 != 4) return in_count;
  const uint64_t low = rng();
  const uint64_t high = rng();
  return (low | high << 32) & in_count;
}

// The granules a kernel's entries stand for, after checking its repeat entries keep the rules of
// trace_repeats.h within what the call wrote: a window of at least 2 granules, no repeat entry
// among them, none before the call's first entry. Counts the repeat entries in `repeats`.
std::vector<uint64_t> expand_checked(const std::vector<uint64_t>& entries, int& repeats) {
  for (size_t i = 0; i < entries.size(); ++i) {
    if (!is_trace_repeat(entries[i])) continue;
    ++repeats;
    const uint32_t window = trace_repeat_window(entries[i]);
    EXPECT_GE(window, 2u) << "entry " << i;
    EXPECT_GE(trace_repeat_count(entries[i]), 1u) << "entry " << i;
    EXPECT_LE(window, i) << "entry " << i;
    for (size_t k = i - std::min<size_t>(window, i); k < i; ++k) {
      EXPECT_FALSE(is_trace_repeat(entries[k])) << "entry " << i << " window entry " << k;
    }
  }
  return expand_trace_repeats(entries);
}

TEST(SobelTraceKernel, ThirtyTwoBitLanesRecordTheSixtyFourBitKernelsGranules) {
  std::mt19937 rng(2026);
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  const uint64_t texel_sizes[] = {4, 4, 8, 16, 2, 12};
  int batches = 0, granules = 0, dropped_firsts = 0;
  for (int config = 0; config < 96; ++config) {
    force_simd_target(targets[config % targets.size()]);
    const int w = 16 + pick(90), h = 8 + pick(40);
    const int color_w = config % 5 == 4 ? 7 + pick(30) : w;
    const int color_h = config % 5 == 4 ? 5 + pick(20) : h;
    BatchTracePlanes planes;
    // Every pick in its own statement: the order of evaluation of a call's arguments (and of
    // an operator's operands) is unspecified, so one expression with two picks would give
    // different configurations under different compilers and flags (the sanitizer build).
    const uint64_t depth_page = 4096 * pick(3);
    const uint64_t depth_origin = depth_page + 4 * pick(20);
    planes.depth = plane(3, depth_origin, texel_sizes[pick(6)], w, h);
    planes.has_normal = config % 4 != 0;
    if (config % 7 == 6) {
      planes.normal = planes.depth;  // one texture as two planes
    } else {
      const uint64_t normal_origin = 4 * pick(20);
      planes.normal = plane(4, normal_origin, texel_sizes[pick(6)], w, h);
    }
    planes.color = plane(5, 0, texel_sizes[pick(6)], color_w, color_h);
    planes.has_border = config % 3 != 0;
    planes.border = config % 9 == 8 ? planes.normal : plane(6, 64 * pick(5), 4, w, h);
    if (config % 11 == 10 && color_w == w && color_h == h) planes.border = planes.color;
    planes.prepare_tags();
    ASSERT_TRUE(planes.tags_fit) << "config " << config;
    for (int b = 0; b < 24; ++b) {
      const int kind = b % 4;  // interior, corner (clamped), thick taps, scattered
      const int step = kind == 2 ? 2 + pick(3) : 1;
      const int x0 = kind == 1 ? (pick(2) ? 0 : w - 16) : pick(w - 15);
      const int y0 = kind == 1 ? (pick(2) ? 0 : h - 4) : pick(h - 3);
      FragmentTaps taps;
      fill_taps(rng, x0, y0, step, kind == 3, w, h, color_w, color_h, taps);
      const FragmentEdges edges = random_edges(rng, b % 3 == 0 ? 2 : 12);
      const int count = b % 6 == 5 ? 16 * (1 + pick(4)) : kBatchFragments;
      const uint64_t active = random_active(rng, b, count);
      std::vector<uint64_t> expected(kBatchFragments * kTraceSlots), got(expected.size());
      // The trace before: a random granule, or the first read's (dropped when repeated).
      uint64_t last_expected = pick(2) ? rng() : (planes.depth.origin + 4096) >> 6;
      if (pick(4) == 0) {
        last_expected = (planes.depth.origin + (uint64_t{static_cast<uint32_t>(taps.y[0][0])} * w +
                                                static_cast<uint32_t>(taps.x[0][0])) *
                                                   planes.depth.texel_bytes) >> 6;
        dropped_firsts += (active & 1u) != 0;
      }
      uint64_t last_got = last_expected;
      const int n_expected = trace_batch_64(planes, taps, edges, count, active, expected.data(),
                                            last_expected);
      const int n_got = trace_batch_32(planes, taps, edges, count, active, got.data(), last_got);
      ASSERT_EQ(n_got, n_expected) << "config " << config << " batch " << b;
      expected.resize(n_expected);
      got.resize(n_got);
      ASSERT_EQ(got, expected) << "config " << config << " batch " << b;
      ASSERT_EQ(last_got, last_expected) << "config " << config << " batch " << b;
      ++batches;
      granules += n_got;
    }
  }
  EXPECT_EQ(batches, 96 * 24);
  EXPECT_GT(granules, batches * 64 * 4);
  EXPECT_GT(dropped_firsts, 10);
}

// The template kernel on planes that allow it (granule-aligned depth and normal planes whose
// rows are whole granules) against the 64-bit kernel: the same granules, count and last granule
// where it takes a batch, and trace_batch (which tries it first) the same on every batch.
TEST(SobelTraceKernel, TemplatesRecordTheSixtyFourBitKernelsGranules) {
  std::mt19937 rng(1411);
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  const uint64_t texel_sizes[] = {4, 4, 8, 16, 2};
  int taken = 0, batches = 0, pair_configs = 0, own_color_configs = 0, repeats = 0;
  for (int config = 0; config < 60; ++config) {
    const uint64_t texel_bytes = texel_sizes[pick(5)];
    const int granule_texels = static_cast<int>(64 / texel_bytes);
    const int w = std::max(16, granule_texels) + granule_texels * pick(96 / granule_texels + 1);
    const int h = 8 + pick(40);
    const int color_w = config % 5 == 4 ? 7 + pick(30) : w;
    const int color_h = config % 5 == 4 ? 5 + pick(20) : h;
    BatchTracePlanes planes;
    planes.depth = plane(3, 4096 * pick(3), texel_bytes, w, h);
    planes.has_normal = config % 4 != 0;
    planes.normal = plane(4, 64 * pick(20), texel_bytes, w, h);
    // Every other config a colour plane laid out as depth (quad-row pairs from pair templates),
    // every fourth one starting on a granule with another texel size (pairs with their own
    // colour offset where its rows are whole granules).
    if (config % 2 == 0) {
      planes.color = plane(5, 64 * pick(4), texel_bytes, color_w, color_h);
    } else {
      const uint64_t color_origin = config % 4 == 1 ? 64 * pick(4) : 4 * pick(20);
      const uint64_t color_texel_bytes = config % 4 == 1 ? texel_sizes[1 + pick(3)] : texel_sizes[pick(5)];
      planes.color = plane(5, color_origin, color_texel_bytes, color_w, color_h);
    }
    planes.has_border = config % 3 != 0;
    planes.border = config % 9 == 8 ? planes.normal : plane(6, 4 * pick(5), 4, w, h);
    if (config % 11 == 10 && color_w == w && color_h == h) planes.border = planes.color;
    planes.prepare_tags();
    ASSERT_TRUE(planes.templates.usable) << "config " << config;
    pair_configs += planes.templates.pairs;
    own_color_configs += planes.templates.pairs && !planes.templates.color_at_offset;
    for (int b = 0; b < 24; ++b) {
      force_simd_target(targets[(config + b) % targets.size()]);
      const int kind = b % 4;  // interior, corner (clamped), thick taps, scattered
      const int step = kind == 2 ? 2 + pick(3) : 1;
      // Half the others start on a 16-texel column: granule-aligned quad rows.
      int x0 = kind == 1 ? (pick(2) ? 0 : w - 16) : pick(w - 15);
      if (kind != 1 && pick(2)) x0 &= ~15;
      const int y0 = kind == 1 ? (pick(2) ? 0 : h - 4) : pick(h - 3);
      FragmentTaps taps;
      fill_taps(rng, x0, y0, step, kind == 3, w, h, color_w, color_h, taps);
      const FragmentEdges edges = random_edges(rng, b % 3 == 0 ? 2 : 12);
      const int count = b % 6 == 5 ? 16 * (1 + pick(4)) : kBatchFragments;
      const uint64_t active = random_active(rng, b, count);
      const size_t room = kBatchFragments * kTraceSlots + kTraceSlack;
      std::vector<uint64_t> expected(room), got(room), dispatched(room);
      // The trace before: a random granule, or the first read's (the template kernel declines).
      uint64_t last_expected = pick(2) ? rng() : (planes.depth.origin + 4096) >> 6;
      if (pick(8) == 0) {
        last_expected = (planes.depth.origin + (uint64_t{static_cast<uint32_t>(taps.y[0][0])} * w +
                                                static_cast<uint32_t>(taps.x[0][0])) *
                                                   planes.depth.texel_bytes) >> 6;
      }
      uint64_t last_got = last_expected, last_dispatched = last_expected;
      const uint64_t last_before = last_expected;
      const int n_expected = trace_batch_64(planes, taps, edges, count, active, expected.data(),
                                            last_expected);
      expected.resize(n_expected);
      const int n_got =
          trace_batch_template(planes, taps, edges, count, active, got.data(), last_got);
      if (n_got >= 0) {
        ++taken;
        got.resize(n_got);
        ASSERT_EQ(expand_checked(got, repeats), expected) << "config " << config << " batch " << b;
        ASSERT_EQ(last_got, last_expected) << "config " << config << " batch " << b;
      } else {
        ASSERT_EQ(last_got, last_before) << "config " << config << " batch " << b;
      }
      const int n_dispatched =
          trace_batch(planes, taps, edges, count, active, dispatched.data(), last_dispatched);
      dispatched.resize(n_dispatched);
      ASSERT_EQ(expand_checked(dispatched, repeats), expected)
          << "config " << config << " batch " << b;
      ASSERT_EQ(last_dispatched, last_expected) << "config " << config << " batch " << b;
      ++batches;
    }
  }
  EXPECT_EQ(batches, 60 * 24);
  EXPECT_GT(pair_configs, 20);
  EXPECT_GE(own_color_configs, 5);  // 5 of the 15 configs whose colour has another texel size
  EXPECT_GT(taken, batches / 6);  // most interior batches (a quarter), off the top and bottom rows
  EXPECT_GT(repeats, 0);  // quad rows that row_fits takes fold
}

// trace_regular_batch (quad rows from the row template) against the 64-bit kernel on whole
// full-screen batches inside the texture (the batches find_edges_rows takes), granule-aligned or
// not, with and without edges, on every SIMD target.
TEST(SobelTraceKernel, RegularBatchesRecordTheSixtyFourBitKernelsGranules) {
  std::mt19937 rng(1414);
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  int batches = 0, repeats = 0;
  size_t entries = 0, granules = 0;
  for (int config = 0; config < 24; ++config) {
    const int w = 48 + 16 * pick(6), h = 12 + pick(30);
    BatchTracePlanes planes;
    planes.depth = plane(3, 4096 * pick(3), 4, w, h);
    planes.has_normal = config % 4 != 0;
    planes.normal = plane(4, 64 * pick(20), 4, w, h);
    // Colour planes laid out as depth, with their own texel size on a granule (rows with the
    // colour at its own offset), or off a granule (no rows).
    const uint64_t color_texel_bytes = config % 5 == 4 ? 8 : (config % 5 == 3 ? 8 + 8 * pick(2) : 4);
    const uint64_t color_origin = config % 5 == 4 ? 4 * pick(20) : 64 * pick(4);
    planes.color = plane(5, color_origin, color_texel_bytes, w, h);
    planes.has_border = config % 3 != 0;
    planes.border = plane(6, 4 * pick(5), 4, w, h);
    planes.prepare_tags();
    ASSERT_TRUE(planes.templates.usable) << "config " << config;
    for (int b = 0; b < 24; ++b) {
      force_simd_target(targets[(config + b) % targets.size()]);
      // Inside the texture (taps unclamped), every other batch on a granule.
      int x0 = 1 + pick(w - 18);
      if (pick(2)) x0 &= ~15;
      const int y0 = 1 + pick(h - 5);
      FragmentTaps taps;
      fill_taps(rng, x0 == 0 ? 16 : x0, y0, 1, false, w, h, w, h, taps);
      const FragmentEdges edges = random_edges(rng, b % 3 == 0 ? 40 : (b % 3 == 1 ? 300 : 6));
      const size_t room = kBatchFragments * kTraceSlots + kTraceSlack;
      std::vector<uint64_t> expected(room), got(room);
      uint64_t last_expected = pick(2) ? rng() : (planes.depth.origin + 4096) >> 6;
      uint64_t last_got = last_expected;
      const int n_expected = trace_batch_64(planes, taps, edges, kBatchFragments, ~uint64_t{0},
                                            expected.data(), last_expected);
      const int n_got = trace_regular_batch(planes, taps, edges, got.data(), last_got);
      expected.resize(n_expected);
      got.resize(n_got);
      ASSERT_EQ(expand_checked(got, repeats), expected) << "config " << config << " batch " << b;
      ASSERT_EQ(last_got, last_expected) << "config " << config << " batch " << b;
      ++batches;
      entries += got.size();
      granules += expected.size();
    }
  }
  EXPECT_EQ(batches, 24 * 24);
  // Edge-free granule-aligned quad rows fold: fewer entries than the granules they stand for.
  EXPECT_GT(repeats, batches / 8);
  EXPECT_LT(entries, granules);
}

// The kernels' repeat entries are the memory layer's (trace_repeats.h), which the shaders layer
// cannot include.
TEST(SobelTraceKernel, RepeatEntriesAreTheTraceFormats) {
  static_assert(repeat_entry(2, 1) == trace_repeat(2, 1));
  static_assert(repeat_entry(40, 0xffffffffu) == trace_repeat(40, kTraceRepeatMaxCount));
  static_assert(repeat_entry(0x7fffffffu, 7) == trace_repeat(0x7fffffffu, 7));
  static_assert(is_repeat_entry(trace_repeat(3, 1)) && !is_repeat_entry(~kTraceRepeatBit));
  EXPECT_EQ(trace_repeat_window(repeat_entry(18, 5)), 18u);
  EXPECT_EQ(trace_repeat_count(repeat_entry(18, 5) + 1), 6u);  // ++ adds a repeat
}

// An edge-free granule-aligned batch of the regular pass: each quad row's middle quads fold into
// one repeat entry of a whole quad (8 granules per pixel become 121 entries per 32 pixels with a
// normal plane), and the entries expand to the 64-bit kernel's granules.
TEST(SobelTraceKernel, EdgeFreeQuadRowsFoldIntoRepeats) {
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  constexpr int kW = 128, kH = 32;
  BatchTracePlanes planes;
  planes.depth = plane(3, 0, 4, kW, kH);
  planes.has_normal = true;
  planes.normal = plane(4, 0, 4, kW, kH);
  planes.color = plane(5, 0, 4, kW, kH);
  planes.has_border = true;
  planes.border = plane(6, 0, 4, kW, kH);
  planes.prepare_tags();
  ASSERT_TRUE(planes.templates.rows);
  EXPECT_EQ(planes.templates.row_count, 121);
  EXPECT_EQ(planes.templates.row_repeats, 1);
  // 8-byte colour texels: the colour granule changes at pixel 8, so quads 1-3 and 4-6 repeat
  // twice each, too few to fold; the row template writes its colour reads at their offset.
  BatchTracePlanes wide_color = planes;
  wide_color.color = plane(5, 0, 8, kW, kH);
  wide_color.prepare_tags();
  ASSERT_TRUE(wide_color.templates.rows);
  EXPECT_FALSE(wide_color.templates.color_at_offset);
  EXPECT_EQ(wide_color.templates.row_count, 280);
  EXPECT_EQ(wide_color.templates.row_repeats, 0);
  EXPECT_EQ(wide_color.templates.row_colors, 32);
  std::mt19937 rng(7);
  for (const std::string& target : targets) {
    force_simd_target(target);
    {
      FragmentTaps taps;
      fill_taps(rng, 48, 4, 1, false, kW, kH, kW, kH, taps);
      const FragmentEdges edges{};
      const size_t room = kBatchFragments * kTraceSlots + kTraceSlack;
      std::vector<uint64_t> expected(room), got(room);
      uint64_t last_expected = 1, last_got = 1;
      expected.resize(trace_batch_64(wide_color, taps, edges, kBatchFragments, ~uint64_t{0},
                                     expected.data(), last_expected));
      got.resize(trace_regular_batch(wide_color, taps, edges, got.data(), last_got));
      EXPECT_EQ(got, expected) << target;
      EXPECT_EQ(last_got, last_expected) << target;
    }
    FragmentTaps taps;
    fill_taps(rng, 32, 8, 1, false, kW, kH, kW, kH, taps);
    const FragmentEdges edges{};  // none
    const size_t room = kBatchFragments * kTraceSlots + kTraceSlack;
    std::vector<uint64_t> expected(room), got(room);
    uint64_t last_expected = 1, last_got = 1;
    expected.resize(trace_batch_64(planes, taps, edges, kBatchFragments, ~uint64_t{0},
                                   expected.data(), last_expected));
    got.resize(trace_regular_batch(planes, taps, edges, got.data(), last_got));
    int repeats = 0;
    EXPECT_EQ(expand_checked(got, repeats), expected) << target;
    EXPECT_EQ(repeats, 2) << target;
    EXPECT_EQ(got.size(), 2u * 121u) << target;
    EXPECT_EQ(expected.size(), 2u * 32u * 8u + 2u * 24u) << target;  // 8 per pixel, 12 per edge pixel
    EXPECT_EQ(last_got, last_expected) << target;
  }
}

// Unaligned depth or normal planes, one texture as two planes, or differing texel sizes leave
// the templates unused.
TEST(SobelTraceKernel, TemplatesNeedAlignedDistinctPlanes) {
  BatchTracePlanes planes;
  planes.depth = plane(3, 0, 4, 64, 64);
  planes.has_normal = true;
  planes.normal = plane(4, 0, 4, 64, 64);
  planes.color = plane(5, 4, 4, 64, 64);
  planes.prepare_tags();
  EXPECT_TRUE(planes.templates.usable);
  planes.depth = plane(3, 4, 4, 64, 64);  // not on a granule
  planes.prepare_tags();
  EXPECT_FALSE(planes.templates.usable);
  planes.depth = plane(3, 0, 4, 60, 64);  // rows of 240 bytes
  planes.normal = plane(4, 0, 4, 60, 64);
  planes.prepare_tags();
  EXPECT_FALSE(planes.templates.usable);
  planes.depth = plane(3, 0, 4, 64, 64);
  planes.normal = plane(4, 0, 8, 64, 64);  // other texel size
  planes.prepare_tags();
  EXPECT_FALSE(planes.templates.usable);
  planes.normal = planes.depth;  // one texture
  planes.prepare_tags();
  EXPECT_FALSE(planes.templates.usable);
}

// Planes whose tags cannot be told apart (overlapping at different origins, one origin with
// two layouts) or whose bytes exceed 32 bits go to the 64-bit kernel.
TEST(SobelTraceKernel, TagsDoNotFitOverlappingOrHugePlanes) {
  BatchTracePlanes planes;
  planes.depth = plane(3, 0, 4, 64, 64);
  planes.color = plane(4, 0, 4, 64, 64);
  planes.prepare_tags();
  EXPECT_TRUE(planes.tags_fit);
  planes.color = plane(3, 1024, 4, 64, 64);  // inside the depth plane
  planes.prepare_tags();
  EXPECT_FALSE(planes.tags_fit);
  planes.color = plane(3, 0, 8, 64, 64);  // the depth plane's origin, other texel size
  planes.prepare_tags();
  EXPECT_FALSE(planes.tags_fit);
  planes.color = plane(3, 0, 4, 64, 32);  // the same texels, fewer rows: one tag
  planes.prepare_tags();
  EXPECT_TRUE(planes.tags_fit);
  EXPECT_EQ(planes.tag[BatchTracePlanes::kColor], planes.tag[BatchTracePlanes::kDepth]);
  planes.color = plane(4, 0, 16, 32768, 8192);  // 2^32 bytes
  planes.prepare_tags();
  EXPECT_FALSE(planes.tags_fit);
}

}  // namespace
}  // namespace ontile::sobel
