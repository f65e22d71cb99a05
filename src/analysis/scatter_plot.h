// A scatter plot rasterised into a Canvas: axes with rounded ticks, one colour per series, a
// text label per point, a legend, and the Pareto-optimal points ringed and joined in x order.
#pragma once
#include <string>
#include <vector>

#include "analysis/canvas.h"

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

// Throws ontile::Error when there are no points, a coordinate is not finite, or a point names a
// series that does not exist.
Canvas render_scatter_plot(const PlotSpec& spec);

// Axis range and tick step covering [lo, hi] with about `ticks` steps of 1, 2 or 5 x 10^k;
// the range starts and ends on a tick. lo == hi widens to a unit-sized range around them.
struct AxisTicks {
  double lo = 0.0, hi = 1.0, step = 0.1;
};
AxisTicks nice_axis(double lo, double hi, int ticks);

}  // namespace ontile
