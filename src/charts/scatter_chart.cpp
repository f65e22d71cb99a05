// Scatter chart drawing (see scatter_chart.h).
#include "charts/scatter_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "charts/svg_writer.h"
#include "util/error.h"

namespace ontile {
namespace {

const char* const kPalette[] = {"#282828", "#1f77b4", "#ff7f0e", "#2ca02c",
                                "#9467bd", "#8c564b", "#17becf", "#bcbd22"};
const char* const kPareto = "#dc1e1e";
const char* const kGrid = "#e1e1e1";
constexpr double kLeftPx = 80, kRightPx = 190, kTopPx = 44, kBottomPx = 56;
constexpr double kLabelPx = 11;
// SVG cannot measure text before a browser lays it out; label placement assumes an average
// sans-serif advance of 0.6 em, wide enough that estimated boxes overlap before real ones do.
double text_width_px(const std::string& text, double size_px) { return 0.6 * size_px * text.size(); }

}  // namespace

std::string tick_text(double v, double step) {
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < step * 1e-6 ? 0.0 : v);
  return buf;
}

AxisTicks nice_axis(double lo, double hi, int ticks) {
  if (hi < lo) std::swap(lo, hi);
  if (hi == lo) {
    const double half = lo == 0.0 ? 0.5 : std::abs(lo) * 0.1;
    lo -= half;
    hi += half;
  }
  const double raw = (hi - lo) / std::max(1, ticks);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normalized = raw / magnitude;
  const double step = (normalized <= 1.0 ? 1.0 : normalized <= 2.0 ? 2.0 : normalized <= 5.0 ? 5.0 : 10.0) * magnitude;
  return {std::floor(lo / step) * step, std::ceil(hi / step) * step, step};
}

std::string scatter_chart_svg(const PlotSpec& spec, bool standalone_file) {
  if (spec.points.empty()) throw Error("plot '" + spec.title + "': no points");
  double x_min = spec.points[0].x, x_max = x_min, y_min = spec.points[0].y, y_max = y_min;
  for (const PlotPoint& p : spec.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      throw Error("plot '" + spec.title + "': point '" + p.label + "' has a non-finite coordinate");
    }
    if (p.series < 0 || p.series >= static_cast<int>(spec.series_names.size())) {
      throw Error("plot '" + spec.title + "': point '" + p.label + "' names series " + std::to_string(p.series));
    }
    x_min = std::min(x_min, p.x);
    x_max = std::max(x_max, p.x);
    y_min = std::min(y_min, p.y);
    y_max = std::max(y_max, p.y);
  }
  const double plot_w = spec.width_px - kLeftPx - kRightPx, plot_h = spec.height_px - kTopPx - kBottomPx;
  if (plot_w < 40 || plot_h < 40) throw Error("plot '" + spec.title + "': size too small");
  // 5 % padding so points never sit on the frame.
  const double x_pad = 0.05 * (x_max - x_min), y_pad = 0.05 * (y_max - y_min);
  const AxisTicks xa = nice_axis(x_min - x_pad, x_max + x_pad, 6);
  const AxisTicks ya = nice_axis(y_min - y_pad, y_max + y_pad, 6);
  auto px = [&](double x) { return kLeftPx + (x - xa.lo) / (xa.hi - xa.lo) * plot_w; };
  auto py = [&](double y) { return kTopPx + plot_h - (y - ya.lo) / (ya.hi - ya.lo) * plot_h; };

  SvgWriter svg(spec.width_px, spec.height_px, "scatter-chart");
  svg.rect(0, 0, spec.width_px, spec.height_px, SvgStyle::filled("#ffffff"));
  const SvgStyle grid = SvgStyle::stroked(kGrid);
  SvgText tick;
  tick.size_px = 11;
  tick.anchor = TextAnchor::Middle;
  for (int k = 0; xa.lo + k * xa.step <= xa.hi + xa.step * 1e-6; ++k) {
    const double v = xa.lo + k * xa.step;
    svg.line(px(v), kTopPx, px(v), kTopPx + plot_h, grid);
    svg.text(px(v), kTopPx + plot_h + 16, tick_text(v, xa.step), tick);
  }
  tick.anchor = TextAnchor::End;
  for (int k = 0; ya.lo + k * ya.step <= ya.hi + ya.step * 1e-6; ++k) {
    const double v = ya.lo + k * ya.step;
    svg.line(kLeftPx, py(v), kLeftPx + plot_w, py(v), grid);
    svg.text(kLeftPx - 6, py(v) + 4, tick_text(v, ya.step), tick);
  }
  svg.rect(kLeftPx, kTopPx, plot_w, plot_h, SvgStyle::stroked("#000000"));
  SvgText title;
  title.size_px = 16;
  title.bold = true;
  svg.text(kLeftPx, 26, spec.title, title);
  SvgText axis_title;
  axis_title.size_px = 12;
  axis_title.anchor = TextAnchor::Middle;
  svg.text(kLeftPx + plot_w / 2, spec.height_px - 16, spec.x_title, axis_title);
  axis_title.rotate_deg = -90;
  svg.text(20, kTopPx + plot_h / 2, spec.y_title, axis_title);

  // The front, joined in x order, under the points.
  std::vector<const PlotPoint*> front;
  for (const PlotPoint& p : spec.points) {
    if (p.pareto) front.push_back(&p);
  }
  std::stable_sort(front.begin(), front.end(), [](const PlotPoint* a, const PlotPoint* b) { return a->x < b->x; });
  std::vector<std::pair<double, double>> front_line;
  for (const PlotPoint* p : front) front_line.emplace_back(px(p->x), py(p->y));
  if (front_line.size() > 1) svg.polyline(front_line, SvgStyle::stroked(kPareto, 2.0, "", "pareto-front"));
  for (const PlotPoint& p : spec.points) {
    svg.begin_group(p.label + ": " + tick_text(p.x, xa.step / 100) + ", " + tick_text(p.y, ya.step / 100), "point");
    if (p.pareto) svg.circle(px(p.x), py(p.y), 8, SvgStyle::stroked(kPareto, 2.0));
    svg.circle(px(p.x), py(p.y), 4, SvgStyle::filled(kPalette[p.series % std::size(kPalette)]));
    svg.end_group();
  }
  // Labels right, left, above or below their point, whichever overlaps no earlier label;
  // a label with no free place is left out (the CSV names every point, the tooltip too).
  struct Box {
    double x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
  };
  std::vector<Box> placed;
  SvgText label;
  label.size_px = kLabelPx;
  label.fill = "#3c3c3c";
  for (const PlotPoint& p : spec.points) {
    const double x = px(p.x), y = py(p.y), w = text_width_px(p.label, kLabelPx);
    // Candidate baselines; a label's box spans [baseline - size, baseline + 2].
    const double candidates[4][2] = {{x + 10, y + 4}, {x - 10 - w, y + 4}, {x - w / 2, y - 10}, {x - w / 2, y + 20}};
    for (const auto& [tx, ty] : candidates) {
      const Box box{tx - 1, ty - kLabelPx, tx + w, ty + 2};
      if (std::any_of(placed.begin(), placed.end(), [&](const Box& b) { return b.overlaps(box); })) continue;
      placed.push_back(box);
      svg.text(tx, ty, p.label, label);
      break;
    }
  }
  // Legend.
  const double lx = kLeftPx + plot_w + 16;
  double ly = kTopPx + 8;
  SvgText legend;
  legend.size_px = 12;
  for (size_t s = 0; s < spec.series_names.size(); ++s) {
    svg.circle(lx + 4, ly, 4, SvgStyle::filled(kPalette[s % std::size(kPalette)]));
    svg.text(lx + 14, ly + 4, spec.series_names[s], legend);
    ly += 18;
  }
  svg.circle(lx + 4, ly, 8, SvgStyle::stroked(kPareto, 2.0));
  svg.text(lx + 16, ly + 4, "Pareto front", legend);
  return svg.str(standalone_file);
}

}  // namespace ontile
