// The sweep plot's points and titles (see sweep_plot.h).
#include "analysis/sweep_plot.h"

#include <algorithm>

namespace ontile {

PlotSpec sweep_plot_spec(const SweepResult& result, const std::string& scene_name) {
  PlotSpec spec;
  spec.title = scene_name + " " + std::to_string(result.width_px) + "x" + std::to_string(result.height_px) +
               " vs " + std::to_string(result.reference_spp) + "-spp reference";
  spec.x_title = "time per frame (ms, median)";
  spec.y_title = "mean absolute error (sRGB8 codes)";
  spec.series_names = sweep_axes();
  for (const SweepRow& r : result.rows) {
    const auto it = std::find(spec.series_names.begin(), spec.series_names.end(), r.setting.axis);
    const int series = static_cast<int>(it - spec.series_names.begin());
    if (it == spec.series_names.end()) spec.series_names.push_back(r.setting.axis);
    spec.points.push_back({r.time_ms_median, r.color.mean_abs, r.setting.label, series, r.pareto_time});
  }
  return spec;
}

}  // namespace ontile
