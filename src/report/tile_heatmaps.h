// A pass's per-tile heatmaps for the HTML report, from PassReport::tile_stats: triangles in
// each tile's list, fragments shaded per pixel of the tile (overdraw), and the external-memory
// bytes the tile moved (attachment loads and stores, texture and parameter-buffer reads).
#pragma once
#include <string>
#include <vector>

#include "tiler/pass_report.h"

namespace ontile {

// Three SVG heatmaps drawn about map_width_px wide; none when the pass has no per-tile
// statistics (tile_stats empty, e.g. an immediate-mode pass).
std::vector<std::string> tile_heatmaps_svg(const PassReport& pass, size_t pass_index, double map_width_px);

}  // namespace ontile
