// Degenerate and tiny triangles: zero-area and collinear ones are counted and draw nothing,
// slivers (area < 1e-6 px^2) never light a pixel away from their own line and keep a mesh
// watertight, and a million sub-pixel triangles tiling a rectangle cover it exactly once.
#include <gtest/gtest.h>

#include "support/projected_coverage.h"
#include "support/raster_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 96, kH = 64;

glm::vec4 px(double x, double y) { return pixel_to_clip(x, y, kW, kH); }

int sum(const CountResult& r) {
  double total = 0.0;
  for (float c : r.counts) total += c;
  return static_cast<int>(total);
}

TEST(Degenerate, ZeroAreaAndCollinearTrianglesDrawNothingAndAreCounted) {
  const std::vector<glm::vec4> pos = {
      px(10.5, 10.5), px(10.5, 10.5), px(50.5, 30.5),            // repeated vertex
      px(5.5, 5.5), px(25.5, 15.5), px(45.5, 25.5),              // collinear through centres
      px(3.0, 60.0), px(3.0, 60.0), px(3.0, 60.0),               // a point
      px(2.25, 40.0), px(70.75, 40.0), px(30.0, 40.0)};          // collinear along a row
  std::vector<uint32_t> idx(pos.size());
  for (uint32_t i = 0; i < idx.size(); ++i) idx[i] = i;
  const CountResult r = draw_counting(pos, idx, kW, kH);
  EXPECT_EQ(sum(r), 0);
  EXPECT_EQ(r.report.passes[0].geometry.triangles_zero_area, 4u);
  EXPECT_EQ(r.report.passes[0].geometry.triangles_binned, 0u);
}

// Slivers: 1e-8 px high and up to 90 px long, at many angles and positions. After snapping a
// sliver either vanishes or becomes a one-subpixel-thin triangle; it may light pixel centres
// only within the snapping distance of its own segment.
TEST(Degenerate, SliversLightNoPixelAwayFromTheirLine) {
  uint32_t seed = 99u;
  auto next = [&seed] { seed ^= seed << 13; seed ^= seed >> 17; seed ^= seed << 5; return (seed & 0xFFFFFF) / double(0x1000000); };
  int strays = 0, lit = 0;
  for (int i = 0; i < 400; ++i) {
    const glm::dvec2 a(2.0 + next() * 90.0, 2.0 + next() * 60.0);
    const double angle = next() * 6.283185307179586, length = 5.0 + next() * 85.0;
    const glm::dvec2 dir(std::cos(angle), std::sin(angle)), normal(-dir.y, dir.x);
    const glm::dvec2 b = a + length * dir, c = a + 0.5 * length * dir + 1e-8 * normal;
    ASSERT_LT(0.5 * length * 1e-8, 1e-6) << "area in px^2";
    const CountResult r = draw_counting({px(a.x, a.y), px(b.x, b.y), px(c.x, c.y)}, {0, 1, 2}, kW, kH);
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        if (r.at(x, y, kW) == 0.0f) continue;
        ++lit;
        strays += r.at(x, y, kW) != 1.0f ||
                  detail::distance_to_segment({x + 0.5, y + 0.5}, a, b) > 2.0 * kSnapDistancePx + 1e-6;
      }
    }
  }
  EXPECT_EQ(strays, 0);
  EXPECT_LT(lit, 400) << "a sliver lights at most the few centres its snapped edge passes";
}

// A sliver inside a mesh: a square fanned around a point 1e-9 px from its bottom edge. The
// sliver's neighbours share its edges, so the square is still covered exactly once.
TEST(Degenerate, SliverInsideAMeshKeepsItWatertight) {
  for (double offset : {0.0, 0.3, 0.77}) {
    const double x0 = 10.25 + offset, x1 = 80.6 + offset, y0 = 8.4, y1 = 55.1 + offset;
    const std::vector<glm::vec4> pos = {px(x0, y0), px(x1, y0), px(x1, y1), px(x0, y1),
                                        px(0.5 * (x0 + x1) + 0.1, y1 - 1e-9)};
    const CountResult r = draw_counting(pos, {4, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0}, kW, kH);
    int expected = 0, wrong = 0;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        const bool inside = x + 0.5 > x0 && x + 0.5 < x1 && y + 0.5 > y0 && y + 0.5 < y1;
        expected += inside;
        wrong += r.at(x, y, kW) != (inside ? 1.0f : 0.0f);
      }
    }
    EXPECT_EQ(wrong, 0) << offset;
    EXPECT_EQ(sum(r), expected) << offset;
  }
}

// 708 x 708 cells (1,002,528 triangles) of about 0.09 x 0.07 px, vertices jittered, tiling a
// 64 x 48 px rectangle whose sides lie between pixel centres: every centre inside is covered
// exactly once, so the total is the rectangle's pixel count.
TEST(Degenerate, AMillionSubPixelTrianglesCoverTheirRegionExactlyOnce) {
  const int cells = 708;
  const double x0 = 16.3, y0 = 8.2, width = 64.0, height = 48.0;
  uint32_t seed = 7u;
  auto next = [&seed] { seed ^= seed << 13; seed ^= seed >> 17; seed ^= seed << 5; return (seed & 0xFFFFFF) / double(0x1000000); };
  std::vector<glm::vec4> pos;
  pos.reserve((cells + 1) * (cells + 1));
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      double u = double(i) / cells, v = double(j) / cells;
      if (i > 0 && i < cells) u += (next() - 0.5) * 0.3 / cells;
      if (j > 0 && j < cells) v += (next() - 0.5) * 0.3 / cells;
      pos.push_back(px(x0 + u * width, y0 + v * height));
    }
  }
  std::vector<uint32_t> idx;
  idx.reserve(size_t{6} * cells * cells);
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const uint32_t a = j * (cells + 1) + i, b = a + 1, c = a + cells + 1, d = c + 1;
      idx.insert(idx.end(), {a, b, d, a, d, c});
    }
  }
  ASSERT_GE(idx.size() / 3, 1000000u);
  const CountResult r = draw_counting(pos, idx, kW, kH);
  int wrong = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const bool inside = x + 0.5 > x0 && x + 0.5 < x0 + width && y + 0.5 > y0 && y + 0.5 < y0 + height;
      wrong += r.at(x, y, kW) != (inside ? 1.0f : 0.0f);
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(sum(r), 64 * 48);
  const GeometryCounters& g = r.report.passes[0].geometry;
  EXPECT_EQ(g.triangles_submitted, idx.size() / 3);
  EXPECT_EQ(g.triangles_binned + g.triangles_zero_area, g.triangles_submitted);
}

// Interpolated varyings of tiny and sliver triangles stay finite and within the range of the
// vertex values (perspective weights of covered samples are non-negative).
TEST(Degenerate, VaryingsOfTinyTrianglesStayFiniteAndInRange) {
  std::vector<glm::vec4> pos;
  std::vector<float> var;
  std::vector<uint32_t> idx;
  for (int i = 0; i < 32; ++i) {
    // Around a pixel centre, 0.05 px across; odd ones are slivers along their bottom edge.
    const double x = 3.5 + i * 2.0, y = 4.5 + (i % 8) * 7.0;
    const double w = 0.5 + 0.25 * (i % 5);  // different w per vertex: perspective weights
    for (const glm::dvec2 d : {glm::dvec2(-0.02, -0.01), glm::dvec2(0.03, 0.0), glm::dvec2(0.0, i % 2 ? -0.01 + 1e-7 : 0.02)}) {
      pos.push_back(pixel_to_clip(x + d.x, y + d.y, kW, kH, w * (1.0 + d.x)));
      var.insert(var.end(), {1000.0f * i, -3.0f, 1e-30f, 7.0f});
    }
    idx.insert(idx.end(), {uint32_t(3 * i), uint32_t(3 * i + 1), uint32_t(3 * i + 2)});
  }
  ContextConfig cfg;
  cfg.threads = 2;
  RenderContext ctx(cfg);
  Surface* target = ctx.create_surface("v", PixelFormat::RGBA32_FLOAT, kW, kH);
  ClipSpaceVertexShader vs(pos, var, 4);
  VaryingsShader fs;
  ctx.begin_render_pass("v", kW, kH, 1, {{"v", PixelFormat::RGBA32_FLOAT, LoadAction::Clear, StoreAction::Store, glm::vec4(-1.0f), target, nullptr}}, -1);
  ctx.begin_subpass({0});
  ctx.draw(unculled_draw(vs, fs, idx));
  ctx.end_subpass();
  ctx.end_render_pass();
  ctx.submit();
  int written = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const glm::vec4 v = target->read(x, y);
      if (v == glm::vec4(-1.0f)) continue;
      ++written;
      const int i = static_cast<int>(std::lround(v.x / 1000.0f));
      EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w));
      EXPECT_NEAR(v.x, 1000.0f * i, 1000.0f * i * 1.2e-7f);  // 2 float ulps of the constant
      EXPECT_NEAR(v.y, -3.0f, 3.0f * 1.2e-7f);
      EXPECT_NEAR(v.w, 7.0f, 7.0f * 1.2e-7f);
      EXPECT_LE(std::abs(v.z), 1.0001e-30f);
    }
  }
  EXPECT_GE(written, 16) << "every non-sliver triangle holds a pixel centre";
}

}  // namespace
}  // namespace ontile::test
