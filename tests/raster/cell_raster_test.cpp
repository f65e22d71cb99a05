// The hierarchical cell rasterizer against the scalar quad walker it replaced: identical sample
// coverage for random triangles of every size (int32 SIMD lanes and the int64 path), every
// sample count and the top-left rule; the float interpolation's documented error bound; and
// the same bits on every SIMD target Highway offers on this machine.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "raster/cell_raster.h"
#include "raster/rasterize.h"
#include "raster/small_cell_coverage.h"

namespace ontile {
namespace {

constexpr int kWidth = 200, kHeight = 120;

glm::vec4 clip_of_pixel(double x, double y, double w) {
  return glm::vec4(static_cast<float>((x / kWidth * 2.0 - 1.0) * w),
                   static_cast<float>((1.0 - y / kHeight * 2.0) * w), static_cast<float>(0.3 * w),
                   static_cast<float>(w));
}

// Per-sample coverage of one cell by the reference walker (rasterize_quads).
void reference_cell(const TriangleSetup& t, const SamplePattern& p, int cx, int cy, CellMask out[kMaxSamples]) {
  for (int s = 0; s < kMaxSamples; ++s) out[s] = 0;
  const PixelRect rect{cx, cy, std::min(cx + kCellSizePx, kWidth), std::min(cy + kCellSizePx, kHeight)};
  rasterize_quads(t, p, rect, [&](int qx, int qy, QuadCoverage c) {
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      const int bit = (qy - cy + (lane >> 1)) * kCellSizePx + (qx - cx + (lane & 1));
      for (int s = 0; s < p.count; ++s) {
        if ((c >> (lane * kMaxSamples + s)) & 1u) out[s] |= CellMask{1} << bit;
      }
    }
  });
}

// Compares every cell of the target for `count` random triangles spanning up to `extent_px`.
void expect_cells_match(double extent_px, int count, uint32_t seed, int* int64_cells = nullptr,
                        int* small_triangles = nullptr) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> centre_x(-20.0, kWidth + 20.0), centre_y(-20.0, kHeight + 20.0);
  std::uniform_real_distribution<double> offset(-extent_px, extent_px), w(0.5, 3.0);
  int compared = 0;
  for (int i = 0; i < count; ++i) {
    const double x = centre_x(rng), y = centre_y(rng);
    glm::vec4 clip[3];
    for (auto& c : clip) c = clip_of_pixel(x + offset(rng), y + offset(rng), w(rng));
    TriangleSetup t;
    if (setup_triangle(clip, kWidth, kHeight, CullMode::None, FrontFace::CounterClockwise, t) != SetupResult::Ok) continue;
    if (small_triangles && CellEdges(t).small) ++*small_triangles;
    if (int64_cells) {
      for (const EdgeFunction& e : t.edge) {
        if (std::abs(e.a) + std::abs(e.b) > (int64_t{1} << 19)) ++*int64_cells;
      }
    }
    for (int samples : {1, 2, 4, 8}) {
      const SamplePattern& p = *standard_sample_pattern(samples);
      for (int cy = 0; cy < kHeight; cy += kCellSizePx) {
        for (int cx = 0; cx < kWidth; cx += kCellSizePx) {
          CellMask expected[kMaxSamples], actual[kMaxSamples];
          reference_cell(t, p, cx, cy, expected);
          const CellMask valid = cell_rect_mask(cx, cy, 0, 0, kWidth, kHeight);
          const CellMask any = cell_coverage(t, p, cx, cy, valid, actual);
          CellMask expected_any = 0;
          for (int s = 0; s < samples; ++s) {
            ASSERT_EQ(actual[s], expected[s]) << "triangle " << i << " samples " << samples << " cell " << cx << "," << cy;
            expected_any |= expected[s];
          }
          ASSERT_EQ(any, expected_any);
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 0);
}

// Small triangles take CellEdges' all-int32 path (every cell of the target compared, those
// far from the triangle included); medium ones both paths.
TEST(CellRaster, CoverageEqualsTheScalarWalkerForSmallTriangles) {
  int small = 0;
  expect_cells_match(6.0, 300, 1, nullptr, &small);
  EXPECT_GT(small, 150);
}
TEST(CellRaster, CoverageEqualsTheScalarWalkerForMediumTriangles) {
  int small = 0;
  expect_cells_match(60.0, 200, 2, nullptr, &small);
  EXPECT_GT(small, 10);
  EXPECT_LT(small, 190);
}
// Triangles around the size limit of the int32 path (spans up to 200 px: some small, most not).
TEST(CellRaster, CoverageEqualsTheScalarWalkerAtTheSmallTriangleLimit) {
  int small = 0;
  expect_cells_match(100.0, 200, 4, nullptr, &small);
  EXPECT_GT(small, 5);
}

// cells_trivially_accepted (the tile executor's one test per tile): whenever it accepts a block
// of cells, cell_coverage gives every cell of the block its valid mask at every sample count.
// Large triangles, so many blocks are accepted and many only just miss.
TEST(CellRaster, TriviallyAcceptedBlocksAreCoveredWhole) {
  std::mt19937 rng(1212);
  std::uniform_real_distribution<double> centre_x(0.0, kWidth), centre_y(0.0, kHeight);
  std::uniform_real_distribution<double> offset(-400.0, 400.0), w(0.5, 3.0);
  int accepted = 0, rejected = 0;
  for (int i = 0; i < 300; ++i) {
    glm::vec4 clip[3];
    const double x = centre_x(rng), y = centre_y(rng);
    for (auto& c : clip) c = clip_of_pixel(x + offset(rng), y + offset(rng), w(rng));
    TriangleSetup t;
    if (setup_triangle(clip, kWidth, kHeight, CullMode::None, FrontFace::CounterClockwise, t) != SetupResult::Ok) continue;
    for (int block = 0; block < 20; ++block) {
      const int ci0 = static_cast<int>(rng() % (kWidth / kCellSizePx)), cj0 = static_cast<int>(rng() % (kHeight / kCellSizePx));
      const int ci1 = ci0 + static_cast<int>(rng() % 4), cj1 = cj0 + static_cast<int>(rng() % 4);
      if (!cells_trivially_accepted(t, ci0 * kCellSizePx, cj0 * kCellSizePx, ci1 * kCellSizePx, cj1 * kCellSizePx)) {
        ++rejected;
        continue;
      }
      ++accepted;
      for (int samples : {1, 4}) {
        const SamplePattern& p = *standard_sample_pattern(samples);
        for (int cj = cj0; cj <= cj1; ++cj) {
          for (int ci = ci0; ci <= ci1; ++ci) {
            const CellMask valid = rng() % 2 ? ~CellMask{0} : CellMask{rng()} << 20 | rng();
            CellMask out[kMaxSamples];
            ASSERT_EQ(cell_coverage(t, p, ci * kCellSizePx, cj * kCellSizePx, valid, out), valid);
            for (int s = 0; s < samples; ++s) ASSERT_EQ(out[s], valid);
          }
        }
      }
    }
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(rejected, 100);
}

TEST(CellRaster, SteepEdgesUseTheInt64PathAndStayExact) {
  int steep_edges = 0;
  expect_cells_match(20000.0, 60, 3, &steep_edges);
  EXPECT_GT(steep_edges, 0) << "no edge exercised the 64-bit path";
}

// Every rectangle with corners from 2 pixels before to 2 pixels past the cell, pixel by pixel.
TEST(CellRaster, RectMaskHoldsExactlyThePixelsInsideTheRectangle) {
  const int cx = 16, cy = 40;
  for (int x0 = cx - 2; x0 <= cx + 10; ++x0) {
    for (int x1 = cx - 2; x1 <= cx + 10; ++x1) {
      for (int y0 = cy - 2; y0 <= cy + 10; ++y0) {
        for (int y1 = cy - 2; y1 <= cy + 10; ++y1) {
          CellMask expected = 0;
          for (int bit = 0; bit < kCellPixels; ++bit) {
            const int x = cx + bit % kCellSizePx, y = cy + bit / kCellSizePx;
            if (x >= x0 && x < x1 && y >= y0 && y < y1) expected |= CellMask{1} << bit;
          }
          ASSERT_EQ(cell_rect_mask(cx, cy, x0, y0, x1, y1), expected) << x0 << "," << y0 << " - " << x1 << "," << y1;
        }
      }
    }
  }
}

TEST(CellRaster, TopLeftRuleOnSharedEdgesCoversEachSampleOnce) {
  // A square from pixel centre (8.5, 8.5) to (40.5, 40.5) split on its diagonal: edges run
  // through pixel centres, so the top-left rule alone decides. Exactly the 32x32 pixels
  // [8, 40)^2 are covered, each by exactly one triangle.
  const glm::vec4 a = clip_of_pixel(8.5, 8.5, 1), b = clip_of_pixel(40.5, 8.5, 1);
  const glm::vec4 c = clip_of_pixel(40.5, 40.5, 1), d = clip_of_pixel(8.5, 40.5, 1);
  const glm::vec4 tris[2][3] = {{a, b, c}, {a, c, d}};
  int hits[kHeight][kWidth] = {};
  const SamplePattern& p = *standard_sample_pattern(1);
  for (const auto& tri : tris) {
    TriangleSetup t;
    ASSERT_EQ(setup_triangle(tri, kWidth, kHeight, CullMode::None, FrontFace::CounterClockwise, t), SetupResult::Ok);
    for (int cy = 0; cy < 48; cy += kCellSizePx) {
      for (int cx = 0; cx < 48; cx += kCellSizePx) {
        CellMask m[kMaxSamples];
        cell_coverage(t, p, cx, cy, ~CellMask{0}, m);
        for (int bit = 0; bit < kCellPixels; ++bit) {
          if ((m[0] >> bit) & 1u) ++hits[cy + bit / kCellSizePx][cx + bit % kCellSizePx];
        }
      }
    }
  }
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 48; ++x) {
      const bool inside = x >= 8 && x < 40 && y >= 8 && y < 40;
      ASSERT_EQ(hits[y][x], inside ? 1 : 0) << "pixel " << x << "," << y;
    }
  }
}

// Float plane interpolation against the exact double formula: depth within the bound the HiZ
// margin assumes, varyings within a few float ulps of their magnitude.
TEST(CellRaster, InterpolationErrorStaysWithinTheDocumentedBound) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(0.0, 190.0), w(0.2, 5.0), z(0.0, 1.0);
  double worst_depth_ulps = 0.0, worst_varying_rel = 0.0;
  for (int i = 0; i < 400; ++i) {
    glm::vec4 clip[3];
    for (auto& c : clip) {
      // One draw per statement: the order of evaluation of function arguments is unspecified
      // (GCC draws the second argument first, clang the first), so the sample, and this
      // test's worst error, depended on the compiler. Kept in GCC's order: y, then x.
      const double ww = w(rng);
      const double y_px = pos(rng) * 0.6;
      const double x_px = pos(rng);
      c = clip_of_pixel(x_px, y_px, ww);
      c.z = static_cast<float>(z(rng) * ww);
    }
    TriangleSetup t;
    if (setup_triangle(clip, kWidth, kHeight, CullMode::None, FrontFace::CounterClockwise, t) != SetupResult::Ok) continue;
    const TrianglePlanes planes(t);
    const float vertex_values[3][1] = {{-3.0f}, {11.0f}, {250.0f}};
    for (int cy = 0; cy < kHeight; cy += kCellSizePx) {
      for (int cx = 0; cx < kWidth; cx += kCellSizePx) {
        CellPlane cp[3];
        planes.at_cell(cx, cy, cp);
        alignas(64) float fx[16], fy[16], o1[16], o2[16], oz[16], depth[16], var[16];
        for (int f = 0; f < 16; ++f) {
          fx[f] = static_cast<float>(f % 8);
          fy[f] = static_cast<float>(f / 8);
          o1[f] = cp[0].origin;
          o2[f] = cp[1].origin;
          oz[f] = cp[2].origin;
        }
        InterpolationInput in{fx, fy, o1, o2, oz, cp[0].dx, cp[0].dy, cp[1].dx, cp[1].dy, cp[2].dx, cp[2].dy,
                              {t.inv_w[0], t.inv_w[1], t.inv_w[2]},
                              {vertex_values[t.vertex_order[0]], vertex_values[t.vertex_order[1]], vertex_values[t.vertex_order[2]]}, 1};
        interpolate_fragments(in, 16, depth, var, 16);
        double lo, hi;
        cell_depth_bounds(cp[2], cx, cy, cx, cy, cx + 8, cy + 2, lo, hi);
        for (int f = 0; f < 16; ++f) {
          const int64_t px = int64_t{cx + f % 8} * kSubpixelScale + 128, py = int64_t{cy + f / 8} * kSubpixelScale + 128;
          const double l1 = static_cast<double>(t.edge[1].at(px, py)) / t.area2;
          const double l2 = static_cast<double>(t.edge[2].at(px, py)) / t.area2;
          const double l0 = 1.0 - l1 - l2;
          const double exact_z = l0 * t.depth[0] + l1 * t.depth[1] + l2 * t.depth[2];
          const double clamped = std::clamp(exact_z, 0.0, 1.0);
          EXPECT_GE(depth[f], std::clamp(lo, 0.0, 1.0));
          EXPECT_LE(depth[f], std::clamp(hi, 0.0, 1.0));
          worst_depth_ulps = std::max(worst_depth_ulps, std::abs(depth[f] - clamped) / 0x1p-24);
          // Only positions inside the triangle: extrapolated helper values are not bounded.
          if (l0 < 0 || l1 < 0 || l2 < 0) continue;
          const double q0 = l0 * t.inv_w[0], q1 = l1 * t.inv_w[1], q2 = l2 * t.inv_w[2];
          const double s = q0 + q1 + q2;
          const double exact_v = (q0 * vertex_values[t.vertex_order[0]][0] + q1 * vertex_values[t.vertex_order[1]][0] +
                                  q2 * vertex_values[t.vertex_order[2]][0]) / s;
          worst_varying_rel = std::max(worst_varying_rel, std::abs(var[f] - exact_v) / 250.0);
        }
      }
    }
  }
  // docs/rasterization.md: depth within 8 ulps of 1.0, varyings within 2^-18 of the largest
  // vertex magnitude inside the triangle.
  EXPECT_LE(worst_depth_ulps, 8.0);
  EXPECT_LE(worst_varying_rel, 0x1p-18);
  RecordProperty("worst_depth_ulps", std::to_string(worst_depth_ulps));
  RecordProperty("worst_varying_rel", std::to_string(worst_varying_rel));
}

// SmallCellCoverage (the tile loop's one-sample coverage of small triangles, with per-edge
// trivial tests) against cell_coverage, on every SIMD target: every cell of the target with
// random valid masks (whole cells, rectangles, single rows), triangles from sub-pixel to the
// size limit, both the standard centre sample and off-centre positions.
TEST(CellRaster, SmallCellCoverageEqualsCellCoverageOnEveryTarget) {
  struct RestoreTarget {
    ~RestoreTarget() { force_simd_target(""); }
  } restore;
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> centre_x(-20.0, kWidth + 20.0), centre_y(-20.0, kHeight + 20.0);
  std::uniform_real_distribution<double> w(0.5, 3.0);
  SamplePattern off_centre = *standard_sample_pattern(1);
  int small = 0, compared = 0, empty_in_box = 0, partial = 0;
  for (const std::string& target : simd_targets()) {
    force_simd_target(target);
    for (int i = 0; i < 400; ++i) {
      const double extent = i % 4 == 0 ? 1.5 : i % 4 == 1 ? 6.0 : i % 4 == 2 ? 20.0 : 90.0;
      std::uniform_real_distribution<double> offset(-extent, extent);
      const double x = centre_x(rng), y = centre_y(rng);
      glm::vec4 clip[3];
      for (auto& c : clip) c = clip_of_pixel(x + offset(rng), y + offset(rng), w(rng));
      TriangleSetup t;
      if (setup_triangle(clip, kWidth, kHeight, CullMode::None, FrontFace::CounterClockwise, t) != SetupResult::Ok) continue;
      const CellEdges edges(t);
      if (!edges.small) continue;
      ++small;
      off_centre.x[0] = static_cast<int32_t>(rng() % kSubpixelScale);
      off_centre.y[0] = static_cast<int32_t>(rng() % kSubpixelScale);
      for (const SamplePattern* p : {standard_sample_pattern(1), static_cast<const SamplePattern*>(&off_centre)}) {
        const SmallCellCoverage coverage(edges, p->x[0], p->y[0], true, coverage_lanes_kernel());
        for (int cy = 0; cy < kHeight; cy += kCellSizePx) {
          for (int cx = 0; cx < kWidth; cx += kCellSizePx) {
            const int kind = static_cast<int>(rng() % 3);
            const int x0 = cx + static_cast<int>(rng() % 8), y0 = cy + static_cast<int>(rng() % 8);
            const CellMask valid =
                kind == 0 ? cell_rect_mask(cx, cy, 0, 0, kWidth, kHeight)
                : kind == 1 ? cell_rect_mask(cx, cy, x0, y0, x0 + 1 + static_cast<int>(rng() % 8), y0 + 1 + static_cast<int>(rng() % 8))
                            : cell_rect_mask(cx, cy, 0, y0, kWidth, y0 + 1);
            CellMask expected[kMaxSamples];
            const CellMask any = cell_coverage(edges, *p, cx, cy, valid, expected);
            ASSERT_EQ(coverage(cx, cy, valid), any) << target << " triangle " << i << " cell " << cx << "," << cy;
            ASSERT_EQ(coverage.untested(cx, cy, valid), any) << target << " triangle " << i << " cell " << cx << "," << cy;
            ASSERT_EQ(any, expected[0]);
            const bool in_box = cx >= edges.small_x0 && cx < edges.small_x1 && cy >= edges.small_y0 && cy < edges.small_y1;
            if (in_box && valid && !any) ++empty_in_box;
            if (any && any != valid) ++partial;
            ++compared;
          }
        }
      }
    }
  }
  EXPECT_GT(small, 400);
  EXPECT_GT(compared, 100000);
  EXPECT_GT(empty_in_box, 100);  // cells the trivial reject decides
  EXPECT_GT(partial, 100);       // cells the kernel decides
}

// Hierarchical Z's per-cell bounds: depth_range against the scalar definition, on every SIMD
// target, for row widths that are and are not multiples of the vector width, with NaN away from
// the first value (never chosen) and at the first value (always kept).
TEST(CellRaster, DepthRangeMatchesTheScalarMinMaxOnEveryTarget) {
  struct RestoreTarget {
    ~RestoreTarget() { force_simd_target(""); }
  } restore;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (const std::string& target : simd_targets()) {
    force_simd_target(target);
    for (int trial = 0; trial < 400; ++trial) {
      // A third of the trials whole cell rows (8 floats, the single-sample fast path).
      const int count = trial % 3 == 0 ? kCellSizePx : 1 + trial % 64, rows = 1 + (trial / 7) % 8, stride = 70;
      std::vector<float> plane(static_cast<size_t>(stride) * rows);
      for (float& v : plane) v = unit(rng);
      if (trial % 5 == 1) plane[static_cast<size_t>(rng() % rows) * stride + rng() % count] = NAN;
      if (trial % 17 == 3) plane[0] = NAN;
      float lo = plane[0], hi = plane[0];
      for (int r = 0; r < rows; ++r) {
        for (int i = 0; i < count; ++i) {
          const float v = plane[static_cast<size_t>(r) * stride + i];
          lo = v < lo ? v : lo;
          hi = v > hi ? v : hi;
        }
      }
      float simd_lo = 0.0f, simd_hi = 0.0f;
      depth_range(plane.data(), stride, count, rows, simd_lo, simd_hi);
      if (std::isnan(lo)) {
        EXPECT_TRUE(std::isnan(simd_lo) && std::isnan(simd_hi)) << target;
      } else {
        EXPECT_EQ(lo, simd_lo) << target << " count " << count << " rows " << rows;
        EXPECT_EQ(hi, simd_hi) << target << " count " << count << " rows " << rows;
      }
    }
  }
}

}  // namespace
}  // namespace ontile
