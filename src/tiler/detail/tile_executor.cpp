// Per-tile replay of the primitive list (see tile_executor.h). For each triangle: coverage and
// early depth per 8x8 cell (trivial reject/accept, SIMD edge evaluation, hierarchical Z), then
// the quad walk (quad_walk.cpp) queues the surviving quads in the tile's row-major quad order
// for shading in batches of up to 16 quads per functor call, blending and quantised writes
// (tiler/quad_batcher.h).
#include "tiler/detail/tile_executor.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

#include "raster/cell_kernels.h"
#include "raster/cell_raster.h"
#include "raster/small_cell_coverage.h"
#include "raster/texel_trace.h"
#include "tiler/detail/hierarchical_depth.h"
#include "tiler/detail/quad_batcher.h"
#include "tiler/detail/tile_fetch.h"
#include "tiler/detail/tile_load_store.h"
#include "tiler/detail/tile_scratch.h"
#include "util/error.h"

namespace ontile {

TileScratch& tile_scratch() {
  thread_local TileScratch scratch;
  return scratch;
}

namespace {

// Stored depth of cell `cell` as rows for HierarchicalDepth::refresh.
void refresh_hiz(HierarchicalDepth& hiz, const TileCells& cells, int cell, const TileRect& rect,
                 TileMemory& memory) {
  const int cx = cells.first_x + (cell % cells.cells_x) * kCellSizePx;
  const int cy = cells.first_y + (cell / cells.cells_x) * kCellSizePx;
  const int x0 = std::max(cx, rect.x0), x1 = std::min(cx + kCellSizePx, rect.x0 + rect.width);
  const int y0 = std::max(cy, rect.y0), y1 = std::min(cy + kCellSizePx, rect.y0 + rect.height);
  const float* first = memory.depth_plane() + memory.index(x0 - rect.x0, y0 - rect.y0, 0);
  hiz.refresh(cell, first, memory.width() * memory.samples(), (x1 - x0) * memory.samples(), y1 - y0);
}

// The depth test (and, for early Z, the write) of covered cell `cell` at every sample, for the
// cells the common case in rasterize_cells does not take (several samples, a fixed-point depth
// attachment, a cell cut by a tile not aligned to cells).
[[gnu::noinline]] void depth_test_cell_samples(const TriangleContext& ctx, const TileCells& cells,
                                               int cell, int cx, int cy, CellState& st,
                                               TileMemory& memory, TileScratch& scratch) {
  const TileRect& rect = ctx.rect;
  const int samples = ctx.pattern.count;
  // Depth at every sample position, then the depth test (and, for early Z, the write).
  const int cols = std::min(cx + kCellSizePx, rect.x0 + rect.width) - std::max(cx, rect.x0);
  const int rows = std::min(cy + kCellSizePx, rect.y0 + rect.height) - std::max(cy, rect.y0);
  float* z_all = scratch.cell_depth.data() + static_cast<size_t>(cell) * kMaxSamples * kCellPixels;
  bool wrote = false;
  for (int s = 0; s < samples; ++s) {
    float* z = z_all + s * kCellPixels;
    // Without a depth attachment nothing reads the depth: every covered sample passes.
    if (!ctx.has_depth || !st.covered[s]) {
      st.passing[s] = st.covered[s];
      continue;
    }
    // Only the rows with covered pixels: nothing reads the depth of others (the depth test
    // and the late depth write read covered pixels only).
    const int first_row = std::countr_zero(st.covered[s]) / kCellSizePx;
    const int end_row = (kCellPixels - 1 - std::countl_zero(st.covered[s])) / kCellSizePx + 1;
    // A tile narrower than a cell (budget-reduced tiles) starts inside it at (lx0, ly0).
    const int lx0 = std::max(cx, rect.x0) - cx, ly0 = std::max(cy, rect.y0) - cy;
    float* stored = memory.depth_plane() + memory.index(cx + lx0 - rect.x0, cy + ly0 - rect.y0, s);
    const int shift = ly0 * kCellSizePx + lx0;
    const bool write_now = ctx.depth_write && !ctx.late_z;
    if (samples == 1 && shift == 0 && cols == kCellSizePx && !ctx.depth_unorm_bits) {
      // The usual cell: interpolation and depth test in one call, as below.
      const bool range_now = write_now && ctx.hiz_tracked;
      float lo = 0.0f, hi = 0.0f;
      st.passing[s] = interpolate_and_test_cell_depth(
          st.planes[2], ctx.pattern.x[s], ctx.pattern.y[s], first_row, end_row, z,
          ctx.draw.raster.depth_compare, ctx.depth_test, write_now, stored, memory.width(), rows,
          st.covered[s], range_now ? &lo : nullptr, range_now ? &hi : nullptr);
      if (range_now && st.passing[s]) {
        scratch.hiz.set(cell, lo, hi);
        continue;
      }
      wrote = wrote || (write_now && st.passing[s]);
      continue;
    }
    interpolate_cell_depth(st.planes[2], ctx.pattern.x[s], ctx.pattern.y[s], z, first_row, end_row);
    if (ctx.depth_unorm_bits) {
      for (int i = first_row * kCellSizePx; i < end_row * kCellSizePx; ++i) z[i] = ctx.quantize_depth(z[i]);
    }
    if (samples == 1) {
      // A whole-width cell's new depth bounds come from the test's own pass over the rows.
      const bool range_now = write_now && ctx.hiz_tracked && cols == kCellSizePx;
      float lo = 0.0f, hi = 0.0f;
      st.passing[s] = depth_test_cell(ctx.draw.raster.depth_compare, ctx.depth_test, write_now,
                                      z + shift, stored, memory.width(), cols, rows,
                                      st.covered[s] >> shift, range_now ? &lo : nullptr,
                                      range_now ? &hi : nullptr) << shift;
      if (range_now && st.passing[s]) {
        scratch.hiz.set(cell, lo, hi);
        continue;  // the bounds are current: `wrote` stays false, no refresh below
      }
    } else {
      CellMask pass = 0;
      for (int ly = ly0; ly < ly0 + rows; ++ly) {
        for (int lx = lx0; lx < lx0 + cols; ++lx) {
          const int bit = ly * kCellSizePx + lx;
          if (!((st.covered[s] >> bit) & 1u)) continue;
          float& dst = memory.depth_plane()[memory.index(cx + lx - rect.x0, cy + ly - rect.y0, s)];
          if (ctx.depth_test && !depth_compare_passes(ctx.draw.raster.depth_compare, z[bit], dst)) continue;
          pass |= CellMask{1} << bit;
          if (write_now) dst = z[bit];
        }
      }
      st.passing[s] = pass;
    }
    wrote = wrote || (write_now && st.passing[s]);
  }
  if (wrote && ctx.hiz_tracked) refresh_hiz(scratch.hiz, cells, cell, rect, memory);
}

// cell_depth_bounds' min_out (lower) or max_out alone, by the same operations: hierarchical Z's
// test reads only one of them (the incoming minimum for Less and LessEqual, the maximum for
// Greater and GreaterEqual, the only compares it decides).
inline double cell_depth_bound(const CellPlane& z, int cell_x0, int cell_y0, int x0, int y0, int x1,
                               int y1, bool lower) {
  const double fx_lo = x0 - cell_x0 - 0.5, fx_hi = x1 - cell_x0 - 0.5;
  const double fy_lo = y0 - cell_y0 - 0.5, fy_hi = y1 - cell_y0 - 0.5;
  const double magnitude = std::abs(static_cast<double>(z.origin)) +
                           std::abs(static_cast<double>(z.dx)) * kCellSizePx +
                           std::abs(static_cast<double>(z.dy)) * kCellSizePx;
  const double margin = magnitude * 8.0 * 0x1p-24 + 0x1p-126;
  if (lower) {
    const double zx_lo = std::min(z.dx * fx_lo, z.dx * fx_hi);
    const double zy_lo = std::min(z.dy * fy_lo, z.dy * fy_hi);
    return z.origin + zx_lo + zy_lo - margin;
  }
  const double zx_hi = std::max(z.dx * fx_lo, z.dx * fx_hi);
  const double zy_hi = std::max(z.dy * fy_lo, z.dy * fy_hi);
  return z.origin + zx_hi + zy_hi + margin;
}

// What rasterize_cells calls per cell, looked up once per tile: the cell kernels of the SIMD
// target in use and sample 0's offset from the pixel centre (the depth kernel's input).
struct CellCalls {
  CoverageLanesKernel coverage_lanes;
  CellDepthTestKernelFn depth_test;
  float sample0_off_x, sample0_off_y;
};

// Coverage, hierarchical Z and (for early-Z draws) the depth test and write of every cell the
// triangle touches in this tile; fills scratch.cells for the quad pass.
void rasterize_cells(const TriangleContext& ctx, const TileCells& cells, const CellCalls& calls,
                     TileMemory& memory, TileCounters& counters, TileScratch& scratch) {
  const TriangleSetup& t = ctx.tri.setup;
  const TileRect& rect = ctx.rect;
  const int samples = ctx.pattern.count;
  const TrianglePlanes planes(t);
  const CellEdges edges(t);
  const int x_end = std::min(rect.x0 + rect.width, t.max_x + 1);
  const int y_end = std::min(rect.y0 + rect.height, t.max_y + 1);
  const int ci0 = (std::max(rect.x0, t.min_x) - cells.first_x) / kCellSizePx;
  const int cj0 = (std::max(rect.y0, t.min_y) - cells.first_y) / kCellSizePx;
  const int ci1 = (x_end - 1 - cells.first_x) / kCellSizePx;
  const int cj1 = (y_end - 1 - cells.first_y) / kCellSizePx;
  const int x_begin = std::max(rect.x0, t.min_x), y_begin = std::max(rect.y0, t.min_y);
  // Every cell inside all three edges (full-screen triangles): its coverage is its valid mask.
  // Not asked for a single cell, whose own trivial accept in cell_coverage gives the same.
  const bool all_inside =
      ci0 <= ci1 && cj0 <= cj1 && (ci0 != ci1 || cj0 != cj1) &&
      cells_trivially_accepted(t, cells.first_x + ci0 * kCellSizePx, cells.first_y + cj0 * kCellSizePx,
                               cells.first_x + ci1 * kCellSizePx, cells.first_y + cj1 * kCellSizePx);
  // Small triangles at one sample per pixel (most of a detailed scene's): the inline coverage,
  // what cell_coverage gives, with per-edge trivial tests when the triangle spans cells.
  const bool one_cell = ci0 == ci1 && cj0 == cj1;
  const bool small = samples == 1 && edges.small && !all_inside;
  SmallCellCoverage small_coverage;
  if (small) small_coverage.prepare(edges, ctx.pattern.x[0], ctx.pattern.y[0], !one_cell, calls.coverage_lanes);
  // The usual early-depth cell: one sample, a float depth attachment and a tile aligned to
  // cells, so every cell's top-left pixel and whole width lie in the tile. Its depth is
  // interpolated and tested in one call, as depth_test_cell_samples would
  // (interpolate_and_test_cell_depth: the kernel with the sample's offsets).
  const bool aligned_cells = rect.x0 % kCellSizePx == 0 && rect.y0 % kCellSizePx == 0 &&
                             rect.width % kCellSizePx == 0;
  const bool usual_depth = samples == 1 && ctx.has_depth && !ctx.depth_unorm_bits && aligned_cells;
  const bool write_now = ctx.depth_write && !ctx.late_z;
  const bool depth_test = ctx.depth_test;
  const CompareOp op = ctx.draw.raster.depth_compare;
  const bool hiz_enabled = ctx.hiz_enabled;
  const bool hiz_lower = op == CompareOp::Less || op == CompareOp::LessEqual;
  const int rect_y_end = rect.y0 + rect.height;
  for (int cj = cj0; cj <= cj1; ++cj) {
    for (int ci = ci0; ci <= ci1; ++ci) {
      const int cell = cj * cells.cells_x + ci;
      const int cx = cells.first_x + ci * kCellSizePx, cy = cells.first_y + cj * kCellSizePx;
      CellState& st = scratch.cells[cell];
      // Pixels of the cell inside both the tile and the triangle's bounding box (all of them
      // for a cell inside both, what cell_rect_mask gives).
      const bool whole_cell = cx >= x_begin && cy >= y_begin && cx + kCellSizePx <= x_end &&
                              cy + kCellSizePx <= y_end;
      const CellMask valid = whole_cell ? ~CellMask{0} : cell_rect_mask(cx, cy, x_begin, y_begin, x_end, y_end);
      if (all_inside) {
        for (int s = 0; s < samples; ++s) st.covered[s] = valid;
        st.covered_any = valid;
      } else if (small) {
        st.covered_any = st.covered[0] = one_cell ? small_coverage.untested(cx, cy, valid) : small_coverage(cx, cy, valid);
      } else {
        st.covered_any = cell_coverage(edges, ctx.pattern, cx, cy, valid, st.covered);
      }
      if (!st.covered_any) continue;
      scratch.touched.push_back(cell);
      ++counters.cells_rasterized;
      planes.at_cell(cx, cy, st.planes);
      if (hiz_enabled) {
        // The one bound the test reads, for both of its arguments.
        const float bound = ctx.quantize_depth(cell_depth_bound(
            st.planes[2], cx, cy, std::max(cx, rect.x0), std::max(cy, rect.y0),
            std::min(cx + kCellSizePx, x_end), std::min(cy + kCellSizePx, y_end), hiz_lower));
        if (scratch.hiz.rejects(cell, op, bound, bound)) {
          ++counters.cells_hiz_rejected;
          for (int s = 0; s < samples; ++s) st.passing[s] = 0;
          if (!ctx.fragments) {  // nothing to record: count the cell's pixels and skip its quads
            counters.fragments_depth_rejected += std::popcount(st.covered_any);
            st.covered_any = 0;
          }
          continue;
        }
      }
      if (!usual_depth) {
        if (ctx.has_depth) {
          depth_test_cell_samples(ctx, cells, cell, cx, cy, st, memory, scratch);
        } else {
          // No depth attachment (full-screen passes): nothing reads the depth, every covered
          // sample passes, as depth_test_cell_samples decides without the call.
          for (int s = 0; s < samples; ++s) st.passing[s] = st.covered[s];
        }
        continue;
      }
      // Only the rows with covered pixels: nothing reads the depth of others. With a write, the
      // cell's new depth bounds come from the test's own pass (the hierarchical Z refresh).
      const CellMask covered = st.covered[0];
      const int first_row = std::countr_zero(covered) / kCellSizePx;
      const int end_row = (kCellPixels - 1 - std::countl_zero(covered)) / kCellSizePx + 1;
      const int rows = std::min(cy + kCellSizePx, rect_y_end) - cy;
      float* z = scratch.cell_depth.data() + static_cast<size_t>(cell) * kMaxSamples * kCellPixels;
      float* stored = memory.depth_plane() + memory.index(cx - rect.x0, cy - rect.y0, 0);
      float lo = 0.0f, hi = 0.0f;
      const CellMask passing = calls.depth_test(
          st.planes[2], calls.sample0_off_x, calls.sample0_off_y, first_row, end_row, z, op,
          depth_test, write_now, stored, memory.width(), rows, covered, write_now ? &lo : nullptr,
          write_now ? &hi : nullptr);
      st.passing[0] = passing;
      if (write_now && passing) scratch.hiz.set(cell, lo, hi);
    }
  }
}

// shade_quads for a draw without a fragment shader (shadow maps, depth pre-passes) when no
// fragment accesses are recorded: nothing is shaded or written but depth, which early Z already
// wrote, so only the counters remain, taken per cell rather than per quad: samples written are
// the passing samples, and a pixel with a covered but no passing sample was rejected by depth
// (what write_back and shade_quads count quad by quad).
void count_unshaded_cells(const TriangleContext& ctx, const TileScratch& scratch,
                          TileCounters& counters) {
  for (const int cell : scratch.touched) {
    const CellState& st = scratch.cells[cell];
    if (!st.covered_any) continue;  // rejected whole by hierarchical Z (counted there)
    CellMask passing_pixels = 0;
    for (int s = 0; s < ctx.pattern.count; ++s) {
      counters.samples_written += static_cast<uint64_t>(std::popcount(st.passing[s]));
      passing_pixels |= st.passing[s];
    }
    counters.fragments_depth_rejected +=
        static_cast<uint64_t>(std::popcount(st.covered_any & ~passing_pixels));
  }
}

}  // namespace

void execute_tile(const RenderPassDesc& pass, const ParameterBuffer& params, int tile_index,
                  TileMemory& memory, TileCounters& counters, TileTrace& trace,
                  MemoryModel& external, bool hierarchical_z) {
  const bool record_fragment_accesses = external.records_fragments();
  const TexelTraceScope texel_trace(&trace.texture_granules);
  const TileGrid& grid = params.grid;
  TileRect rect;
  rect.x0 = (tile_index % grid.tiles_x()) * grid.tile_width_px;
  rect.y0 = (tile_index / grid.tiles_x()) * grid.tile_height_px;
  rect.width = std::min(grid.tile_width_px, grid.width_px - rect.x0);
  rect.height = std::min(grid.tile_height_px, grid.height_px - rect.y0);

  load_tile(pass, rect, memory);
  external.tile_loaded(tile_index, rect);
  const uint32_t begin = params.tile_offsets[tile_index];
  const uint32_t end = params.tile_offsets[tile_index + 1];
  if (begin != end) ++counters.tiles_executed;

  TileScratch& scratch = tile_scratch();
  const TileCells cells(rect);
  scratch.cells.resize(cells.count());
  scratch.cell_depth.resize(static_cast<size_t>(cells.count()) * kMaxSamples * kCellPixels);
  const bool has_depth = pass.depth_index >= 0;
  if (has_depth && begin != end) {
    scratch.hiz.prepare(cells.cells_x, cells.cells_y);
    for (int c = 0; c < cells.count(); ++c) refresh_hiz(scratch.hiz, cells, c, rect, memory);
  }
  const SamplePattern& pattern = *standard_sample_pattern(pass.samples);
  const CellCalls calls{coverage_lanes_kernel(), cell_depth_test_kernel(),
                        sample_centre_offset(pattern.x[0]), sample_centre_offset(pattern.y[0])};
  scratch.batcher.reset();
  scratch.fetches.clear();
  for (const SubpassDesc& subpass : pass.subpasses) {
    scratch.fetches.emplace_back(memory, rect, subpass.inputs, pass.depth_index);
  }
  // The draw's state, asked of its functors once per run of its triangles (virtual calls).
  const DrawCall* state_draw = nullptr;
  std::optional<DrawState> state;
  int n = 0;
  uint64_t triangle_bytes = 0;
  for (uint32_t e = begin; e < end; ++e) {
    const uint32_t ref = params.tile_entries[e];
    const BinnedTriangle& tri = params.triangle(ref);
    const SubpassDesc& subpass = pass.subpasses[tri.subpass];
    const DrawCall& draw = subpass.draws[tri.draw];
    if (&draw != state_draw) {
      state_draw = &draw;
      state.emplace(pass, subpass, draw);
      n = draw.vertex_shader->varying_count();
      triangle_bytes = kTileListEntryBytes + kPrimitiveRecordBytes +
                       3u * post_transform_vertex_bytes(n, params.vertex_output.varying_component_bytes);
    }
    counters.parameter_bytes_read += triangle_bytes;
    TriangleContext ctx(pass, subpass, draw, tri, params.varyings(ref, tri), n, pattern,
                              rect, &scratch.fetches[tri.subpass], ref,
                              record_fragment_accesses ? &trace.fragments : nullptr, *state);
    ctx.hiz_enabled = ctx.hiz_enabled && hierarchical_z;
    // Quads of earlier triangles still queued are shaded and written before anything of a
    // triangle that cannot join their batch happens.
    if (!scratch.batcher.continues(ctx)) scratch.batcher.flush();
    scratch.touched.clear();
    rasterize_cells(ctx, cells, calls, memory, counters, scratch);
    if (scratch.touched.empty()) continue;
    if (!draw.fragment_shader && !ctx.fragments) {
      count_unshaded_cells(ctx, scratch, counters);
    } else {
      shade_quads(ctx, cells, memory, counters, scratch);
    }
    // Late-Z draws wrote depth after shading: bring their cells' bounds up to date.
    if (ctx.late_z && ctx.depth_write && ctx.hiz_tracked) {
      for (int cell : scratch.touched) refresh_hiz(scratch.hiz, cells, cell, rect, memory);
    }
  }
  scratch.batcher.flush();
  store_tile(pass, rect, memory);
  external.tile_stored(tile_index, rect);
}

}  // namespace ontile
