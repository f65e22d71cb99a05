// The SVG writer: number formatting, escaping, element syntax and group balance.
#include <gtest/gtest.h>

#include <cmath>

#include "charts/svg_writer.h"
#include "util/error.h"

namespace ontile {
namespace {

TEST(SvgWriter, NumbersHaveAtMostTwoDecimalsAndNoTrailingZeros) {
  EXPECT_EQ(svg_number(12.0), "12");
  EXPECT_EQ(svg_number(3.5), "3.5");
  EXPECT_EQ(svg_number(-0.25), "-0.25");
  EXPECT_EQ(svg_number(1.0 / 3.0), "0.33");
  EXPECT_EQ(svg_number(-0.001), "0");
  EXPECT_THROW(svg_number(std::nan("")), Error);
}

TEST(SvgWriter, EscapesTextAndWritesElements) {
  EXPECT_EQ(xml_escape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  SvgWriter svg(100, 50, "chart");
  SvgStyle style = SvgStyle::stroked("#000000", 1.5, "2 2", "cell");
  style.fill = "#ff0000";
  svg.rect(1, 2, 3, 4, style, 2);
  svg.begin_group("tip <1>", "grp");
  svg.text(5, 6, "x & y");
  svg.end_group();
  svg.arrow(0, 0, 10, 0, SvgStyle::stroked("#333333"));
  svg.linear_gradient("g1", {{0, 0, 0}, {255, 255, 255}});
  const std::string s = svg.str();
  EXPECT_EQ(s.rfind("<svg width=\"100\" height=\"50\" viewBox=\"0 0 100 50\" class=\"chart\">\n<defs>", 0), 0u);
  EXPECT_NE(s.find("<rect x=\"1\" y=\"2\" width=\"3\" height=\"4\" rx=\"2\" fill=\"#ff0000\" stroke=\"#000000\" "
                   "stroke-width=\"1.5\" stroke-dasharray=\"2 2\" class=\"cell\"/>"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("<g class=\"grp\"><title>tip &lt;1&gt;</title>"), std::string::npos);
  EXPECT_NE(s.find(">x &amp; y</text>"), std::string::npos);
  EXPECT_NE(s.find("<polygon points=\"10,0 "), std::string::npos);  // the arrow's head at its end
  EXPECT_NE(s.find("<stop offset=\"1\" stop-color=\"#ffffff\"/>"), std::string::npos);
  EXPECT_EQ(s.substr(s.size() - 7), "</svg>\n");
}

TEST(SvgWriter, GroupsMustBalance) {
  SvgWriter svg(10, 10);
  EXPECT_THROW(svg.end_group(), Error);
  svg.begin_group();
  EXPECT_THROW(svg.str(), Error);
  EXPECT_THROW(SvgWriter(0, 10), Error);
}

}  // namespace
}  // namespace ontile
