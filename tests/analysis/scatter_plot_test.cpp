// Plot rasterisation: nice axis ranges, exact glyph pixels (horizontal and vertical text), and
// the scatter plot's size, Pareto highlight and input errors.
#include <gtest/gtest.h>

#include <limits>

#include "analysis/bitmap_font.h"
#include "analysis/scatter_plot.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr Rgba8 kInk{10, 20, 30, 255};

bool is_ink(const Canvas& c, int x, int y) {
  const Rgba8 p = c.at(x, y);
  return p.r == kInk.r && p.g == kInk.g && p.b == kInk.b;
}

TEST(ScatterPlot, NiceAxisRangesStartAndEndOnTicks) {
  const AxisTicks a = nice_axis(0.3, 9.7, 6);  // 9.4 / 6 = 1.57 -> step 2
  EXPECT_DOUBLE_EQ(a.step, 2.0);
  EXPECT_DOUBLE_EQ(a.lo, 0.0);
  EXPECT_DOUBLE_EQ(a.hi, 10.0);
  const AxisTicks b = nice_axis(1.21, 1.38, 6);  // 0.17 / 6 = 0.028 -> step 0.05
  EXPECT_DOUBLE_EQ(b.step, 0.05);
  EXPECT_DOUBLE_EQ(b.lo, 1.2);
  EXPECT_DOUBLE_EQ(b.hi, 1.4);
  const AxisTicks c = nice_axis(5.0, 5.0, 5);  // widened to [4.5, 5.5]: step 0.2
  EXPECT_DOUBLE_EQ(c.step, 0.2);
  EXPECT_LE(c.lo, 4.5);
  EXPECT_GE(c.hi, 5.5);
}

TEST(ScatterPlot, TextPixelsAreTheGlyphs) {
  Canvas c(20, 12, {255, 255, 255, 255});
  c.text(1, 2, "7", kInk);
  const auto& rows = glyph_rows('7');
  for (int y = 0; y < 12; ++y) {
    for (int x = 0; x < 20; ++x) {
      const int gx = x - 1, gy = y - 2;
      const bool expected = gx >= 0 && gx < kGlyphWidthPx && gy >= 0 && gy < kGlyphHeightPx &&
                            ((rows[gy] >> (kGlyphWidthPx - 1 - gx)) & 1u);
      EXPECT_EQ(is_ink(c, x, y), expected) << x << "," << y;
    }
  }
  EXPECT_EQ(glyph_rows('a'), glyph_rows('A'));
  EXPECT_EQ(glyph_rows('~'), glyph_rows('?'));
  EXPECT_EQ(Canvas::text_width_px("ab"), 11);
  EXPECT_EQ(Canvas::text_width_px("ab", 2), 22);
}

TEST(ScatterPlot, VerticalTextRunsUpwards) {
  // "L": its left column becomes the bottom row, its bottom row the right column.
  Canvas c(10, 12, {255, 255, 255, 255});
  c.text_vertical(0, 10, "L", kInk);
  int ink = 0;
  for (int y = 0; y < 12; ++y) {
    for (int x = 0; x < 10; ++x) {
      const bool expected = (y == 10 && x <= 6) || (x == 6 && y >= 6 && y <= 10);
      EXPECT_EQ(is_ink(c, x, y), expected) << x << "," << y;
      ink += is_ink(c, x, y);
    }
  }
  EXPECT_EQ(ink, 11);
}

TEST(ScatterPlot, DrawsPointsAndRingsTheFront) {
  PlotSpec spec;
  spec.title = "T";
  spec.x_title = "X";
  spec.y_title = "Y";
  spec.series_names = {"A", "B"};
  spec.points = {{1.0, 3.0, "P1", 0, true}, {2.0, 1.0, "P2", 1, true}, {3.0, 2.0, "P3", 1, false}};
  spec.width_px = 400;
  spec.height_px = 300;
  const Canvas c = render_scatter_plot(spec);
  EXPECT_EQ(c.width(), 400);
  EXPECT_EQ(c.height(), 300);
  int pareto_red = 0;
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x) pareto_red += c.at(x, y).r == 220 && c.at(x, y).g == 30 && c.at(x, y).b == 30;
  EXPECT_GT(pareto_red, 100);  // two rings, the joining line and the legend ring

  PlotSpec empty = spec;
  empty.points.clear();
  EXPECT_THROW(render_scatter_plot(empty), Error);
  PlotSpec bad = spec;
  bad.points[0].y = std::numeric_limits<double>::infinity();
  EXPECT_THROW(render_scatter_plot(bad), Error);
  bad = spec;
  bad.points[0].series = 2;
  EXPECT_THROW(render_scatter_plot(bad), Error);
}

}  // namespace
}  // namespace ontile
