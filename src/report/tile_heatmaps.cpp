// Per-tile heatmaps (see tile_heatmaps.h).
#include "report/tile_heatmaps.h"

#include <algorithm>

#include "charts/heatmap_chart.h"

namespace ontile {

std::vector<std::string> tile_heatmaps_svg(const PassReport& p, size_t pass_index, double map_width_px) {
  if (p.tile_width_px <= 0 || p.tile_height_px <= 0 || p.width_px <= 0 || p.height_px <= 0) return {};
  const int columns = p.tiles_x(), rows = p.tiles_y();
  if (p.tile_stats.size() != static_cast<size_t>(columns) * rows) return {};
  HeatmapSpec triangles, overdraw, bytes;
  for (HeatmapSpec* spec : {&triangles, &overdraw, &bytes}) {
    spec->columns = columns;
    spec->rows = rows;
    // One pixel of the pass drawn as `scale` page pixels, so every map of the page has the
    // pass's aspect ratio and its tiles' shape.
    const double scale = std::min(1.0, map_width_px / p.width_px);
    spec->cell_width_px = p.tile_width_px * scale;
    spec->cell_height_px = p.tile_height_px * scale;
  }
  triangles.title = "triangles per tile";
  triangles.unit = "triangles in the tile's list";
  overdraw.title = "fragments per pixel (overdraw)";
  overdraw.unit = "fragments shaded / tile pixels";
  bytes.title = "bytes per tile";
  bytes.unit = "bytes loaded + stored + texture + parameter reads";
  const std::string prefix = "pass" + std::to_string(pass_index) + "-";
  triangles.id = prefix + "triangles";
  overdraw.id = prefix + "overdraw";
  bytes.id = prefix + "bytes";
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      const TileStats& t = p.tile_stats[static_cast<size_t>(r) * columns + c];
      // Edge tiles cover fewer pixels than a full tile.
      const int w = std::min(p.tile_width_px, p.width_px - c * p.tile_width_px);
      const int h = std::min(p.tile_height_px, p.height_px - r * p.tile_height_px);
      triangles.values.push_back(t.triangles);
      overdraw.values.push_back(static_cast<double>(t.fragments_shaded) / (static_cast<double>(w) * h));
      bytes.values.push_back(static_cast<double>(t.bytes_loaded + t.bytes_stored + t.texture_bytes_read +
                                                 t.parameter_bytes_read));
    }
  }
  return {heatmap_svg(triangles), heatmap_svg(overdraw), heatmap_svg(bytes)};
}

}  // namespace ontile
