// What the tile executor keeps per thread across tiles (cell state, hierarchical Z, the quad
// batcher) and the cell grid of a tile, shared by the rasterization (tile_executor.cpp) and the
// quad walk that queues the covered quads (quad_walk.cpp).
#pragma once
#include <vector>

#include "raster/cell_raster.h"
#include "tiler/detail/hierarchical_depth.h"
#include "tiler/detail/quad_batcher.h"
#include "tiler/detail/tile_fetch.h"

namespace ontile {

// Scratch reused by every tile a thread runs (no allocation in the tile loop once warm).
struct TileScratch {
  HierarchicalDepth hiz;
  std::vector<CellState> cells;
  std::vector<float> cell_depth;  // per cell, per sample, 64 depths (row-major in the cell)
  std::vector<int> touched;       // cells the current triangle covered
  std::vector<TileFetch> fetches;  // per subpass of the current tile
  QuadBatcher batcher;
};

// The calling thread's scratch.
TileScratch& tile_scratch();

// The cells of a tile: cell (i, j) has its top-left pixel at (first_x + 8 i, first_y + 8 j).
struct TileCells {
  int first_x = 0, first_y = 0, cells_x = 0, cells_y = 0;
  explicit TileCells(const TileRect& r)
      : first_x(r.x0 & ~(kCellSizePx - 1)), first_y(r.y0 & ~(kCellSizePx - 1)),
        cells_x((r.x0 + r.width - first_x + kCellSizePx - 1) / kCellSizePx),
        cells_y((r.y0 + r.height - first_y + kCellSizePx - 1) / kCellSizePx) {}
  int count() const { return cells_x * cells_y; }
};

// Walks the triangle's covered quads in the tile's row-major order (the order the texture and
// IMR models replay) and hands the surviving ones to scratch.batcher, from the cell state
// rasterization left for the triangle (scratch.cells, scratch.touched non-empty).
void shade_quads(const TriangleContext& ctx, const TileCells& cells, TileMemory& memory,
                 TileCounters& counters, TileScratch& scratch);

}  // namespace ontile
