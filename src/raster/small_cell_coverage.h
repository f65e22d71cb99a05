// cell_coverage for a small triangle (CellEdges::small) at one sample per pixel, inline for the
// tile loop: the edge values on int32 with a per-edge trivial reject and accept per cell, so
// only the edges that cross a cell reach the SIMD kernel (and none for an empty cell).
#pragma once
#include <algorithm>
#include <bit>
#include <cstdint>

#include "raster/cell_kernels.h"
#include "raster/cell_raster.h"

namespace ontile {

// A small triangle's edges at one sample position (sx, sy) per pixel. Every sample of every
// cell inside CellEdges' vertex box has each edge value in int32 (CellEdges), so the values at a
// cell's sample of pixel (0, 0) are computed modulo 2^32 (unsigned arithmetic) and are exact,
// and so are their extremes over the cell's 64 samples, which are values at its corner samples.
struct SmallCellCoverage {
  // Without trivial_tests only untested() may be asked (a triangle whose box is one cell: its
  // cell is rarely rejected or accepted, so the tests' set-up would not pay). `kernel`:
  // coverage_lanes_kernel() of the SIMD target in use.
  SmallCellCoverage(const CellEdges& edges, int32_t sx, int32_t sy, bool trivial_tests,
                    CoverageLanesKernel kernel) {
    prepare(edges, sx, sy, trivial_tests, kernel);
  }
  // Unprepared (nothing initialised, for a tile loop that prepares it for some triangles only).
  SmallCellCoverage() = default;
  void prepare(const CellEdges& edges, int32_t sx, int32_t sy, bool trivial_tests,
               CoverageLanesKernel kernel) {
    box = &edges;
    lanes_kernel = kernel;
    const TriangleSetup& t = *edges.setup;
    for (int k = 0; k < 3; ++k) {
      const EdgeFunction& e = t.edge[k];
      base[k] = static_cast<uint32_t>(edges.c_biased[k]) + static_cast<uint32_t>(e.a) * static_cast<uint32_t>(sx) +
                static_cast<uint32_t>(e.b) * static_cast<uint32_t>(sy);
      a_step[k] = edges.a_step[k];
      b_step[k] = edges.b_step[k];
    }
    if (!trivial_tests) return;
    for (int k = 0; k < 3; ++k) {
      // max(a, 0) + max(b, 0) = a + b - (min(a, 0) + min(b, 0)).
      lowest[k] = (std::min(a_step[k], 0) + std::min(b_step[k], 0)) * (kCellSizePx - 1);
      highest[k] = (a_step[k] + b_step[k]) * (kCellSizePx - 1) - lowest[k];
    }
  }
  // cell_coverage(*box, pattern, cell_x0, cell_y0, valid, out)[0] for the one-sample pattern at
  // (sx, sy): an edge negative at every sample of the cell leaves nothing covered, one >= 0 at
  // every sample changes no bit and is left out of the kernel.
  CellMask operator()(int cell_x0, int cell_y0, CellMask valid) const {
    if (!inside_box(cell_x0, cell_y0, valid)) return 0;
    int32_t e0[3], a[3], b[3];
    int edges = 0;
    for (int k = 0; k < 3; ++k) {
      const int32_t e = at_cell(k, cell_x0, cell_y0);
      if (e + highest[k] < 0) return 0;
      if (e + lowest[k] >= 0) continue;
      e0[edges] = e;
      a[edges] = a_step[k];
      b[edges++] = b_step[k];
    }
    if (edges == 0) return valid;
    return lanes(e0, a, b, edges, valid);
  }
  // The same with all three edges on the lanes.
  CellMask untested(int cell_x0, int cell_y0, CellMask valid) const {
    if (!inside_box(cell_x0, cell_y0, valid)) return 0;
    const int32_t e0[3] = {at_cell(0, cell_x0, cell_y0), at_cell(1, cell_x0, cell_y0), at_cell(2, cell_x0, cell_y0)};
    return lanes(e0, a_step, b_step, 3, valid);
  }

  // A covered sample lies in the vertices' box (and no value outside it need fit int32).
  bool inside_box(int cell_x0, int cell_y0, CellMask valid) const {
    return valid && cell_x0 >= box->small_x0 && cell_x0 < box->small_x1 && cell_y0 >= box->small_y0 &&
           cell_y0 < box->small_y1;
  }
  // Edge k at the sample of the cell's pixel (0, 0): c + a (256 x0 + sx) + b (256 y0 + sy).
  int32_t at_cell(int k, int cell_x0, int cell_y0) const {
    return static_cast<int32_t>(base[k] + static_cast<uint32_t>(a_step[k]) * static_cast<uint32_t>(cell_x0) +
                                static_cast<uint32_t>(b_step[k]) * static_cast<uint32_t>(cell_y0));
  }
  CellMask lanes(const int32_t* e0, const int32_t* a, const int32_t* b, int edges, CellMask valid) const {
    const int first_bit = std::countr_zero(valid) / kCellSizePx * kCellSizePx;
    const int end_bit = (kCellPixels - 1 - std::countl_zero(valid)) / kCellSizePx * kCellSizePx + kCellSizePx;
    return lanes_kernel(e0, a, b, edges, first_bit, end_bit) & valid;
  }

  const CellEdges* box;
  CoverageLanesKernel lanes_kernel;
  uint32_t base[3];
  int32_t a_step[3], b_step[3];
  int32_t lowest[3], highest[3];  // min / max of a_step * lx + b_step * ly over lx, ly in [0, 7]
};

}  // namespace ontile
