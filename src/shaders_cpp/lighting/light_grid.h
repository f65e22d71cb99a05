// Per-screen-cell light lists (tiled light culling, as Forward+ and tile-based deferred shading
// use): each 16x16-pixel cell of the render target lists, in ascending order, the lights whose
// range can reach a pixel of it, so a functor loops over a few lights instead of all of them.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

namespace ontile {

struct LightGrid {
  // Fixed in screen space, independent of the simulated tile size, so images do not change
  // with --tile.
  static constexpr int kCellSizePx = 16;
  int cells_x = 0, cells_y = 0;
  std::vector<uint32_t> cell_begin;     // cells_x * cells_y + 1 offsets into light_indices
  std::vector<uint32_t> light_indices;  // per cell, ascending

  // The cell holding pixel (x_px, y_px), or -1 outside the grid (no lights).
  int cell_at(int x_px, int y_px) const {
    const int cx = x_px / kCellSizePx, cy = y_px / kCellSizePx;
    if (cx < 0 || cy < 0 || cx >= cells_x || cy >= cells_y) return -1;
    return cy * cells_x + cx;
  }
  std::span<const uint32_t> lights_in(int cell) const {
    if (cell < 0) return {};
    return {light_indices.data() + cell_begin[cell], light_indices.data() + cell_begin[cell + 1]};
  }
  std::span<const uint32_t> lights_at(int x_px, int y_px) const { return lights_in(cell_at(x_px, y_px)); }
};

}  // namespace ontile
