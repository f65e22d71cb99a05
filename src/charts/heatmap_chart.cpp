// Heatmap drawing (see heatmap_chart.h).
#include "charts/heatmap_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "charts/scatter_chart.h"
#include "io/image_io.h"
#include "util/error.h"

namespace ontile {
namespace {

// Viridis (matplotlib, CC0) at t = 0, 0.25, 0.5, 0.75, 1.
constexpr Rgb kStops[] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
constexpr double kTitlePx = 22, kLegendPx = 46;

std::string value_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, v == std::floor(v) && std::abs(v) < 1e15 ? "%.0f" : "%.3g", v);
  return buf;
}

}  // namespace

Rgb heat_color(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (std::size(kStops) - 1);
  const size_t i = std::min(static_cast<size_t>(t), std::size(kStops) - 2);
  const double f = t - static_cast<double>(i);
  auto mix = [&](uint8_t a, uint8_t b) { return static_cast<uint8_t>(std::lround(a + (b - a) * f)); };
  return {mix(kStops[i].r, kStops[i + 1].r), mix(kStops[i].g, kStops[i + 1].g), mix(kStops[i].b, kStops[i + 1].b)};
}

std::string heatmap_svg(const HeatmapSpec& spec) {
  if (spec.columns <= 0 || spec.rows <= 0) throw Error("heatmap '" + spec.title + "': empty grid");
  if (spec.values.size() != static_cast<size_t>(spec.columns) * spec.rows) {
    throw Error("heatmap '" + spec.title + "': " + std::to_string(spec.values.size()) + " values for " +
                std::to_string(spec.columns) + "x" + std::to_string(spec.rows) + " cells");
  }
  double max_value = 0.0;
  for (double v : spec.values) {
    if (!std::isfinite(v) || v < 0.0) throw Error("heatmap '" + spec.title + "': a value is negative or not finite");
    max_value = std::max(max_value, v);
  }
  const AxisTicks scale = nice_axis(0.0, max_value > 0.0 ? max_value : 1.0, 4);
  std::vector<uint8_t> rgba(spec.values.size() * 4, 255);
  for (size_t i = 0; i < spec.values.size(); ++i) {
    const Rgb c = heat_color(spec.values[i] / scale.hi);
    rgba[i * 4] = c.r, rgba[i * 4 + 1] = c.g, rgba[i * 4 + 2] = c.b;
  }
  const double map_w = spec.columns * spec.cell_width_px, map_h = spec.rows * spec.cell_height_px;
  const double width = std::max(map_w, 240.0), height = kTitlePx + map_h + kLegendPx;
  SvgWriter svg(width, height, spec.css_class);
  SvgText title;
  title.size_px = 13;
  title.bold = true;
  svg.text(0, 15, spec.title, title);
  svg.image(0, kTitlePx, map_w, map_h, png_data_uri(spec.columns, spec.rows, rgba));
  // The tile grid: thin enough not to hide cells a few pixels wide.
  const SvgStyle grid = SvgStyle::stroked("#ffffff", std::min(1.0, 0.15 * std::min(spec.cell_width_px, spec.cell_height_px)));
  for (int c = 0; c <= spec.columns; ++c) svg.line(c * spec.cell_width_px, kTitlePx, c * spec.cell_width_px, kTitlePx + map_h, grid);
  for (int r = 0; r <= spec.rows; ++r) svg.line(0, kTitlePx + r * spec.cell_height_px, map_w, kTitlePx + r * spec.cell_height_px, grid);
  // Legend: the colour bar from 0 to the rounded maximum, ticks on it, the unit under it.
  std::vector<Rgb> stops;
  for (int i = 0; i <= 16; ++i) stops.push_back(heat_color(i / 16.0));
  const std::string gradient = spec.id + "-legend";
  svg.linear_gradient(gradient, stops);
  const double bar_y = kTitlePx + map_h + 8, bar_w = std::min(width, 240.0);
  svg.rect(0, bar_y, bar_w, 10, SvgStyle::filled("url(#" + gradient + ")", "legend"));
  SvgText tick;
  tick.size_px = 10;
  tick.anchor = TextAnchor::Middle;
  for (double v = scale.lo; v <= scale.hi + scale.step * 1e-6; v += scale.step) {
    const double x = v / scale.hi * bar_w;
    svg.line(x, bar_y + 10, x, bar_y + 13, SvgStyle::stroked("#222222"));
    tick.anchor = v == scale.lo ? TextAnchor::Start : v + scale.step > scale.hi + scale.step * 1e-6 ? TextAnchor::End : TextAnchor::Middle;
    svg.text(x, bar_y + 23, tick_text(v, scale.step), tick);
  }
  tick.anchor = TextAnchor::Start;
  tick.fill = "#555";
  svg.text(0, bar_y + 36, spec.unit + " (max " + value_text(max_value) + ")", tick);
  std::string out = svg.str();
  // The values for the page's hover script, on the root element.
  std::string values = " id=\"" + xml_escape(spec.id) + "\" data-columns=\"" + std::to_string(spec.columns) + "\" data-cell=\"" +
                       svg_number(spec.cell_width_px) + "," + svg_number(spec.cell_height_px) + "," +
                       svg_number(kTitlePx) + "\" data-values=\"";
  for (size_t i = 0; i < spec.values.size(); ++i) values += (i ? "," : "") + value_text(spec.values[i]);
  values += "\"";
  out.insert(out.find('>'), values);
  return out;
}

}  // namespace ontile
