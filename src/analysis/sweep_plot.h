// The sweep's plot: colour error (mean absolute sRGB8 error against the reference) over time
// per frame, one series per axis, Pareto-optimal settings (pareto_time) ringed and joined.
#pragma once
#include <string>

#include "analysis/sweep_run.h"
#include "charts/scatter_chart.h"

namespace ontile {

PlotSpec sweep_plot_spec(const SweepResult& result, const std::string& scene_name);

}  // namespace ontile
