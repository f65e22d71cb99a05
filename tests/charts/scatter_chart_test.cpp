// The SVG scatter chart: nice axis ranges, the chart's size, points, Pareto front and legend,
// and its input errors.
#include <gtest/gtest.h>

#include <limits>

#include "charts/scatter_chart.h"
#include "util/error.h"

namespace ontile {
namespace {

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

PlotSpec three_points() {
  PlotSpec spec;
  spec.title = "T <&> title";
  spec.x_title = "X";
  spec.y_title = "Y";
  spec.series_names = {"A", "B"};
  spec.points = {{1.0, 3.0, "P1", 0, true}, {2.0, 1.0, "P2", 1, true}, {3.0, 2.0, "P3", 1, false}};
  spec.width_px = 400;
  spec.height_px = 300;
  return spec;
}

TEST(ScatterChart, NiceAxisRangesStartAndEndOnTicks) {
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
  EXPECT_EQ(tick_text(0.1, 0.05), "0.10");
  EXPECT_EQ(tick_text(40.0, 20.0), "40");
}

TEST(ScatterChart, DrawsPointsTheFrontAndTheLegend) {
  const PlotSpec spec = three_points();
  const std::string svg = scatter_chart_svg(spec);
  EXPECT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("width=\"400\" height=\"300\" viewBox=\"0 0 400 300\""), std::string::npos);
  EXPECT_EQ(count(svg, "<g class=\"point\">"), 3u);
  EXPECT_EQ(count(svg, "class=\"pareto-front\""), 1u);  // P1 and P2 joined
  EXPECT_NE(svg.find("T &lt;&amp;&gt; title"), std::string::npos);  // text is escaped
  for (const char* label : {">P1<", ">P2<", ">P3<", ">A<", ">B<", ">Pareto front<"}) {
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  }
  // Inline (in an HTML page) the element needs no namespace and no XML declaration.
  const std::string inline_svg = scatter_chart_svg(spec, false);
  EXPECT_EQ(inline_svg.rfind("<svg width=", 0), 0u);
  EXPECT_EQ(inline_svg.find("http"), std::string::npos);
  EXPECT_EQ(scatter_chart_svg(spec), svg);  // the same bytes every time
}

TEST(ScatterChart, RefusesBadInput) {
  const PlotSpec spec = three_points();
  PlotSpec empty = spec;
  empty.points.clear();
  EXPECT_THROW(scatter_chart_svg(empty), Error);
  PlotSpec bad = spec;
  bad.points[0].y = std::numeric_limits<double>::infinity();
  EXPECT_THROW(scatter_chart_svg(bad), Error);
  bad = spec;
  bad.points[0].series = 2;
  EXPECT_THROW(scatter_chart_svg(bad), Error);
  bad = spec;
  bad.width_px = 200;  // no room left for the plot area
  EXPECT_THROW(scatter_chart_svg(bad), Error);
}

}  // namespace
}  // namespace ontile
