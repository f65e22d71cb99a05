// The quad walk of a triangle in a tile (see tile_scratch.h): from the cells' coverage and
// early-depth masks to queued quads, row-major over the tile, with the whole-tile and
// whole-row shortcuts and a single-sample walk that works a cell's quad row at a time.
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>

#include "tiler/detail/tile_executor.h"
#include "tiler/detail/tile_scratch.h"

namespace ontile {
namespace {

std::atomic<bool> whole_quad_rows{true};
std::atomic<bool> whole_tiles{true};
std::atomic<uint64_t> whole_tiles_taken{0};

// The 4 lanes of the quad whose top-left pixel is bit (ly * 8 + lx) of a cell mask.
inline uint32_t quad_lanes(CellMask m, int lx, int ly) {
  const int bit = ly * kCellSizePx + lx;
  return static_cast<uint32_t>(((m >> bit) & 3u) | (((m >> (bit + kCellSizePx)) & 3u) << 2));
}

// Spreads the 4 lane bits of sample s to QuadCoverage bits (lane * kMaxSamples + s): a table
// of the 16 lane patterns for sample 0, shifted to sample s.
constexpr std::array<QuadCoverage, 16> kSpreadLanes = [] {
  std::array<QuadCoverage, 16> table{};
  for (uint32_t lanes = 0; lanes < 16; ++lanes) {
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if ((lanes >> lane) & 1u) table[lanes] |= QuadCoverage{1} << (lane * kMaxSamples);
    }
  }
  return table;
}();
inline QuadCoverage spread_lanes(uint32_t lanes, int s) { return kSpreadLanes[lanes & 0xFu] << s; }

// A pixel row's bit pairs moved from bit 2k to 4k (bits 0-7 to the nibbles' low halves), one
// entry per row pattern: a lookup where the shifts and masks cost ~7 instructions per row.
constexpr std::array<uint16_t, 256> kSpreadPairs = [] {
  std::array<uint16_t, 256> table{};
  for (uint32_t x = 0; x < 256; ++x) {
    uint32_t v = (x | (x << 4)) & 0x0F0Fu;
    table[x] = static_cast<uint16_t>((v | (v << 2)) & 0x3333u);
  }
  return table;
}();

// The quad lanes of a cell's quad row: `rows` holds its two pixel rows (bits 0-7 the upper,
// 8-15 the lower); nibble k of the result is quad_lanes of the quad at column 2k (lanes 0, 1
// from the upper row, 2, 3 from the lower).
inline uint32_t quad_row_lanes(uint32_t rows) {
  return kSpreadPairs[rows & 0xFFu] | (uint32_t{kSpreadPairs[(rows >> kCellSizePx) & 0xFFu]} << 2);
}

// Set bits of a 64-bit value, without the popcount instruction the baseline target lacks.
inline uint64_t bit_count64(uint64_t x) {
  x = x - ((x >> 1) & 0x5555555555555555u);
  x = (x & 0x3333333333333333u) + ((x >> 2) & 0x3333333333333333u);
  x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0Fu;
  return (x * 0x0101010101010101u) >> 56;
}

// True when the triangle covers every pixel of the tile at one sample and every pixel passed
// early depth, or has no depth test or write to come (full-screen triangles): every cell of the
// tile was visited for this triangle (the others hold an earlier triangle's state) and is
// covered and passing inside the tile.
bool covers_whole_tile(const TriangleContext& ctx, const TileCells& cells,
                       const TileScratch& scratch) {
  const TileRect& rect = ctx.rect;
  if (ctx.pattern.count != 1 || !ctx.whole_quads_pass_as_covered() ||
      scratch.touched.size() != static_cast<size_t>(cells.count())) {
    return false;
  }
  const int x1 = rect.x0 + rect.width, y1 = rect.y0 + rect.height;
  for (int cj = 0; cj < cells.cells_y; ++cj) {
    const int cy = cells.first_y + cj * kCellSizePx;
    for (int ci = 0; ci < cells.cells_x; ++ci) {
      const int cx = cells.first_x + ci * kCellSizePx;
      const CellState& st = scratch.cells[cj * cells.cells_x + ci];
      // Cells inside the tile (all of them for aligned tiles) need no mask of the tile's part.
      const bool whole_cell = cx >= rect.x0 && cy >= rect.y0 && cx + kCellSizePx <= x1 &&
                              cy + kCellSizePx <= y1;
      const CellMask inside = whole_cell ? ~CellMask{0}
                                         : cell_rect_mask(cx, cy, rect.x0, rect.y0, x1, y1);
      if (st.covered_any != inside || st.passing[0] != inside) return false;
    }
  }
  return true;
}

// The single-sample walk: quad row by quad row, the cells of the triangle's bounding box
// with covered pixels in it. A quad's lanes are its coverage (lanes_of of the spread bits); the
// early-depth rejections are counted per cell (its quads partition its covered pixels, and the
// walk visits every covered pixel once), as the per-quad sums.
[[gnu::noinline]] void queue_single_sample_quads(const TriangleContext& ctx, const TileCells& cells,
                                                 int y_begin, int y_end, int ci_begin, int ci_end,
                                                 bool whole_rows, TileCounters& counters,
                                                 TileScratch& scratch) {
  QuadBatcher& batcher = scratch.batcher;
  const CellState* const states = scratch.cells.data();
  const int cells_x = cells.cells_x;
  const bool early_z = !ctx.late_z;
  // Early Z drops a quad with no passing lane unless the IMR model records its accesses.
  const bool drop_failed = early_z && !ctx.fragments;
  uint64_t rejected = 0;
  if (early_z) {
    for (const int cell : scratch.touched) {
      const CellMask failed = states[cell].covered_any & ~states[cell].passing[0];
      if (failed) rejected += bit_count64(failed);
    }
  }
  for (int qy = y_begin; qy < y_end; qy += 2) {
    const int cj = (qy - cells.first_y) / kCellSizePx;
    const int shift = (qy & (kCellSizePx - 1)) * kCellSizePx;
    const int cy = cells.first_y + cj * kCellSizePx;
    for (int ci = ci_begin; ci <= ci_end; ++ci) {
      const int cell = cj * cells_x + ci;
      const CellState& st = states[cell];
      // Covered bits lie inside the tile and the bounding box (rasterize_cells' valid mask).
      const uint32_t rows = static_cast<uint32_t>(st.covered_any >> shift) & 0xFFFFu;
      if (!rows) continue;
      const uint32_t passing_rows = static_cast<uint32_t>(st.passing[0] >> shift) & 0xFFFFu;
      const int cx = cells.first_x + ci * kCellSizePx;
      if (whole_rows && rows == 0xFFFFu && passing_rows == 0xFFFFu) {
        // Every quad of the row covers and passes its 4 lanes: what the walk below queues
        // (coverage = passing = sample 0 of each lane, nothing rejected by depth).
        for (int lx = 0; lx < kCellSizePx; lx += 2) {
          batcher.add(cx + lx, qy, cell, cx, cy, kWholeQuadSample0, kWholeQuadSample0);
        }
        continue;
      }
      const uint32_t covered_lanes = quad_row_lanes(rows);
      const uint32_t passing_lanes = quad_row_lanes(passing_rows);
      // Nibble k non-zero: the quad at column 2k has a covered lane. Ascending x: the tile's
      // row-major quad order, without stepping over empty quads.
      uint32_t quads = covered_lanes | (covered_lanes >> 2);
      quads = (quads | (quads >> 1)) & 0x1111u;
      while (quads) {
        const int bit = std::countr_zero(quads);
        quads &= quads - 1;
        const uint32_t covered = (covered_lanes >> bit) & 0xFu;
        const uint32_t passes = (passing_lanes >> bit) & 0xFu;
        if (!passes && drop_failed) continue;
        batcher.add(cx + bit / 2, qy, cell, cx, cy, kSpreadLanes[covered], kSpreadLanes[passes]);
      }
    }
  }
  counters.fragments_depth_rejected += rejected;
}

}  // namespace

void shade_quads(const TriangleContext& ctx, const TileCells& cells, TileMemory& memory,
                 TileCounters& counters, TileScratch& scratch) {
  const TriangleSetup& t = ctx.tri.setup;
  const TileRect& rect = ctx.rect;
  const int samples = ctx.pattern.count;
  const int x_begin = std::max(rect.x0, t.min_x & ~1);
  const int y_begin = std::max(rect.y0, t.min_y & ~1);
  const int x_end = std::min(rect.x0 + rect.width, t.max_x + 1);
  const int y_end = std::min(rect.y0 + rect.height, t.max_y + 1);
  QuadBatcher& batcher = scratch.batcher;
  batcher.begin(ctx, memory, counters, scratch.cells.data(), scratch.cell_depth.data(),
                scratch.cells[scratch.touched[0]].planes);
  const int ci_begin = (x_begin - cells.first_x) / kCellSizePx;
  const int ci_end = (x_end - 1 - cells.first_x) / kCellSizePx;
  if (samples == 1) {
    const bool whole_rows = whole_quad_rows.load(std::memory_order_relaxed);
    if (whole_rows && whole_tiles.load(std::memory_order_relaxed) &&
        covers_whole_tile(ctx, cells, scratch) &&
        batcher.add_whole_rect(rect, cells.first_x, cells.first_y, cells.cells_x)) {
      whole_tiles_taken.fetch_add(1, std::memory_order_relaxed);
    } else {
      queue_single_sample_quads(ctx, cells, y_begin, y_end, ci_begin, ci_end, whole_rows, counters,
                                scratch);
    }
    batcher.end_triangle();
    return;
  }
  for (int qy = y_begin; qy < y_end; qy += 2) {
    const int cj = (qy - cells.first_y) / kCellSizePx;
    const int ly = qy & (kCellSizePx - 1);
    const int cy = cells.first_y + cj * kCellSizePx;
    for (int ci = ci_begin; ci <= ci_end; ++ci) {
      const int cell = cj * cells.cells_x + ci;
      const CellState& st = scratch.cells[cell];
      // The quads of this cell row with a covered lane, as bits at their even columns: visited
      // in ascending x (the tile's row-major quad order) without stepping over empty quads.
      const uint32_t rows = static_cast<uint32_t>(st.covered_any >> (ly * kCellSizePx)) & 0xFFFFu;
      const uint32_t either_row = (rows | (rows >> kCellSizePx)) & 0xFFu;
      uint32_t quads = (either_row | (either_row >> 1)) & 0x55u;
      const int cx = cells.first_x + ci * kCellSizePx;
      while (quads) {
        const int lx = std::countr_zero(quads);
        quads &= quads - 1;
        const int qx = cx + lx;
        QuadCoverage coverage = 0, passing = 0;
        for (int s = 0; s < samples; ++s) {
          coverage |= spread_lanes(quad_lanes(st.covered[s], lx, ly), s);
          passing |= spread_lanes(quad_lanes(st.passing[s], lx, ly), s);
        }
        if (!ctx.late_z) {
          counters.fragments_depth_rejected +=
              lane_count(lanes_of(coverage) & ~lanes_of(passing));
          // A quad that failed early depth is not shaded; the IMR model still sees its accesses.
          if (!passing && !ctx.fragments) continue;
        }
        batcher.add(qx, qy, cell, cx, cy, coverage, passing);
      }
    }
  }
  batcher.end_triangle();
}

void set_whole_quad_rows(bool enabled) { whole_quad_rows.store(enabled); }
void set_whole_tiles(bool enabled) { whole_tiles.store(enabled); }
uint64_t whole_tiles_shaded() { return whole_tiles_taken.load(); }

}  // namespace ontile
