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

  std::span<const uint32_t> lights_at(int x_px, int y_px) const {
    const int cx = x_px / kCellSizePx, cy = y_px / kCellSizePx;
    if (cx < 0 || cy < 0 || cx >= cells_x || cy >= cells_y) return {};
    const size_t cell = static_cast<size_t>(cy) * cells_x + cx;
    return {light_indices.data() + cell_begin[cell], light_indices.data() + cell_begin[cell + 1]};
  }
};

}  // namespace ontile
