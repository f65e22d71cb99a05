// A heatmap over a grid of cells (tiles) as SVG: the cells as one embedded PNG, one image pixel
// per cell scaled up unsmoothed, the cell grid drawn over it, a title and a colour-bar legend.
// The values travel in a data attribute so the page's script can show a cell's value on hover.
#pragma once
#include <string>
#include <vector>

#include "charts/svg_writer.h"

namespace ontile {

struct HeatmapSpec {
  std::string title;
  std::string unit;                // the legend's caption, e.g. "triangles per tile"
  int columns = 0, rows = 0;
  std::vector<double> values;      // row-major, columns x rows, finite and >= 0
  double cell_width_px = 8.0, cell_height_px = 8.0;  // drawn size of one cell
  std::string css_class = "heatmap";
  std::string id = "heatmap";      // the element's id, unique within the page (names its legend gradient)
};

// A perceptually ordered colour for t in [0, 1] (dark blue -> green -> yellow, the viridis
// control points linearly interpolated); t is clamped.
Rgb heat_color(double t);

// Throws ontile::Error when the grid is empty, values.size() != columns x rows, or a value is
// negative or not finite. All-zero maps draw in the lowest colour with a 0..1 legend.
std::string heatmap_svg(const HeatmapSpec& spec);

}  // namespace ontile
