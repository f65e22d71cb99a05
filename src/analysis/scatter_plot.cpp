// Scatter plot rendering (see scatter_plot.h).
#include "analysis/scatter_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/bitmap_font.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr Rgba8 kWhite{255, 255, 255, 255}, kBlack{0, 0, 0, 255}, kGrid{225, 225, 225, 255},
    kLabel{60, 60, 60, 255}, kPareto{220, 30, 30, 255};
constexpr Rgba8 kPalette[] = {{40, 40, 40, 255},   {31, 119, 180, 255}, {255, 127, 14, 255},
                              {44, 160, 44, 255},  {148, 103, 189, 255}, {140, 86, 75, 255},
                              {23, 190, 207, 255}, {188, 189, 34, 255}};
constexpr int kLeftPx = 80, kRightPx = 170, kTopPx = 40, kBottomPx = 56;

std::string tick_text(double v, double step) {
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < step * 1e-6 ? 0.0 : v);
  return buf;
}

}  // namespace

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

Canvas render_scatter_plot(const PlotSpec& spec) {
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
  // 5 % padding so points never sit on the frame.
  const double x_pad = 0.05 * (x_max - x_min), y_pad = 0.05 * (y_max - y_min);
  const AxisTicks xa = nice_axis(x_min - x_pad, x_max + x_pad, 6);
  const AxisTicks ya = nice_axis(y_min - y_pad, y_max + y_pad, 6);

  Canvas c(spec.width_px, spec.height_px, kWhite);
  const int plot_w = spec.width_px - kLeftPx - kRightPx, plot_h = spec.height_px - kTopPx - kBottomPx;
  if (plot_w < 40 || plot_h < 40) throw Error("plot '" + spec.title + "': canvas too small");
  auto px = [&](double x) { return kLeftPx + static_cast<int>(std::lround((x - xa.lo) / (xa.hi - xa.lo) * plot_w)); };
  auto py = [&](double y) {
    return kTopPx + plot_h - static_cast<int>(std::lround((y - ya.lo) / (ya.hi - ya.lo) * plot_h));
  };

  // Grid and tick labels.
  for (int k = 0; xa.lo + k * xa.step <= xa.hi + xa.step * 1e-6; ++k) {
    const double v = xa.lo + k * xa.step;
    const int x = px(v);
    c.line(x, kTopPx, x, kTopPx + plot_h, kGrid);
    const std::string t = tick_text(v, xa.step);
    c.text(x - Canvas::text_width_px(t) / 2, kTopPx + plot_h + 6, t, kBlack);
  }
  for (int k = 0; ya.lo + k * ya.step <= ya.hi + ya.step * 1e-6; ++k) {
    const double v = ya.lo + k * ya.step;
    const int y = py(v);
    c.line(kLeftPx, y, kLeftPx + plot_w, y, kGrid);
    const std::string t = tick_text(v, ya.step);
    c.text(kLeftPx - 6 - Canvas::text_width_px(t), y - 3, t, kBlack);
  }
  c.line(kLeftPx, kTopPx, kLeftPx, kTopPx + plot_h, kBlack);
  c.line(kLeftPx, kTopPx + plot_h, kLeftPx + plot_w, kTopPx + plot_h, kBlack);
  c.line(kLeftPx + plot_w, kTopPx, kLeftPx + plot_w, kTopPx + plot_h, kBlack);
  c.line(kLeftPx, kTopPx, kLeftPx + plot_w, kTopPx, kBlack);
  c.text(kLeftPx, 12, spec.title, kBlack, 2);
  c.text(kLeftPx + (plot_w - Canvas::text_width_px(spec.x_title)) / 2, spec.height_px - 20, spec.x_title, kBlack);
  c.text_vertical(14, kTopPx + (plot_h + Canvas::text_width_px(spec.y_title)) / 2, spec.y_title, kBlack);

  // The front, joined in x order, under the points.
  std::vector<const PlotPoint*> front;
  for (const PlotPoint& p : spec.points) {
    if (p.pareto) front.push_back(&p);
  }
  std::stable_sort(front.begin(), front.end(), [](const PlotPoint* a, const PlotPoint* b) { return a->x < b->x; });
  for (size_t i = 1; i < front.size(); ++i) {
    c.line(px(front[i - 1]->x), py(front[i - 1]->y), px(front[i]->x), py(front[i]->y), kPareto, 2);
  }
  for (const PlotPoint& p : spec.points) {
    const Rgba8 colour = kPalette[p.series % std::size(kPalette)];
    if (p.pareto) c.ring(px(p.x), py(p.y), 8, 2, kPareto);
    c.disc(px(p.x), py(p.y), 4, colour);
  }
  // Labels right, left, above or below their point, whichever overlaps no earlier label;
  // a label with no free place is left out (the CSV names every point).
  struct Box {
    int x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
  };
  std::vector<Box> placed;
  for (const PlotPoint& p : spec.points) {
    const int x = px(p.x), y = py(p.y), w = Canvas::text_width_px(p.label);
    const int candidates[4][2] = {{x + 10, y - 3}, {x - 10 - w, y - 3}, {x - w / 2, y - 18}, {x - w / 2, y + 11}};
    for (const auto& [tx, ty] : candidates) {
      const Box box{tx - 1, ty - 1, tx + w, ty + kGlyphHeightPx};
      if (std::any_of(placed.begin(), placed.end(), [&](const Box& b) { return b.overlaps(box); })) continue;
      placed.push_back(box);
      c.text(tx, ty, p.label, kLabel);
      break;
    }
  }

  // Legend.
  const int lx = kLeftPx + plot_w + 16;
  int ly = kTopPx + 6;
  for (size_t s = 0; s < spec.series_names.size(); ++s) {
    c.disc(lx + 4, ly + 3, 4, kPalette[s % std::size(kPalette)]);
    c.text(lx + 14, ly, spec.series_names[s], kBlack);
    ly += 16;
  }
  c.ring(lx + 4, ly + 3, 8, 2, kPareto);
  c.text(lx + 14, ly, "PARETO FRONT", kBlack);
  return c;
}

}  // namespace ontile
