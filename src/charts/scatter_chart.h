// A scatter chart as SVG: axes with rounded ticks, one colour per series, a text label per
// point, a legend, and the Pareto-optimal points ringed and joined in x order.
#pragma once
#include <string>
#include <vector>

namespace ontile {

struct PlotPoint {
  double x = 0.0, y = 0.0;
  std::string label;
  int series = 0;       // index into PlotSpec::series_names
  bool pareto = false;  // ringed and joined to the other Pareto points
};

struct PlotSpec {
  std::string title, x_title, y_title;
  std::vector<std::string> series_names;
  std::vector<PlotPoint> points;
  int width_px = 960, height_px = 600;
};

// The chart as a standalone SVG file (or an inline <svg> element when standalone_file is false).
// Throws ontile::Error when there are no points, a coordinate is not finite, a point names a
// series that does not exist, or the size leaves no room for the plot area.
std::string scatter_chart_svg(const PlotSpec& spec, bool standalone_file = true);

// Axis range and tick step covering [lo, hi] with about `ticks` steps of 1, 2 or 5 x 10^k;
// the range starts and ends on a tick. lo == hi widens to a unit-sized range around them.
struct AxisTicks {
  double lo = 0.0, hi = 1.0, step = 0.1;
};
AxisTicks nice_axis(double lo, double hi, int ticks);

// Tick label for `value` with as many decimals as `step` needs ("0.05" -> 2 decimals).
std::string tick_text(double value, double step);

}  // namespace ontile
