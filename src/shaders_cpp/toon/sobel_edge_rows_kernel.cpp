// find_edges_rows (sobel_edge_kernel.h): the edge tests of a full-screen batch of 16x4 pixels in
// quad order whose taps are each pixel's grid neighbours, on lanes that hold a run of one pixel
// row, so every tap is one load of a grid row instead of a gather; the same operations as
// find_edges (sobel_edge_math-inl.h), the results put back into quad order.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/toon/sobel_edge_rows_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/lane_bits-inl.h"
#include "shaders_cpp/toon/sobel_edge_math-inl.h"

#include <cstdint>

#include "shaders_cpp/toon/sobel_edge_kernel.h"

// Target-independent tables, once per translation unit (foreach_target includes this file per
// target).
#ifndef ONTILE_SOBEL_EDGE_ROWS_TABLES_
#define ONTILE_SOBEL_EDGE_ROWS_TABLES_
namespace ontile::sobel {
namespace {

// A batch of 64 fragments as 16x4 pixels: quads row by row (8 per quad row), each quad's lanes
// (0, 0), (1, 0), (0, 1), (1, 1) (raster/shader_interface.h).
constexpr int kRowPixels = 16;
constexpr int kGridWidth = kRowPixels + 2, kGridHeight = 4 + 2;
struct QuadOrder {
  alignas(64) int32_t column[kBatchFragments] = {};  // of fragment f
  alignas(64) int32_t row[kBatchFragments] = {};
  alignas(64) int32_t fragment[kBatchFragments] = {};  // of pixel r * 16 + c
  alignas(64) int32_t pixel[kBatchFragments] = {};     // of fragment f
  constexpr QuadOrder() {
    for (int f = 0; f < kBatchFragments; ++f) {
      const int quad = f / 4, lane = f % 4;
      column[f] = 2 * (quad % 8) + (lane & 1);
      row[f] = 2 * (quad / 8) + (lane >> 1);
      pixel[f] = row[f] * kRowPixels + column[f];
      fragment[pixel[f]] = f;
    }
  }
};
constexpr QuadOrder kQuadOrder;

// Row-major pixel bits (bit r * 16 + c) as fragment bits: per quad row, the 2-bit column pairs
// of its two pixel rows interleaved (pair g of the upper row at bits 4g, of the lower at 4g + 2).
uint64_t quad_order_bits(uint64_t pixel_bits) {
  const auto spread_pairs = [](uint64_t x) {
    x &= 0xFFFFu;
    x = (x | (x << 8)) & 0x00FF00FFu;
    x = (x | (x << 4)) & 0x0F0F0F0Fu;
    return (x | (x << 2)) & 0x33333333u;
  };
  uint64_t bits = 0;
  for (int quad_row = 0; quad_row < 2; ++quad_row) {
    const uint64_t upper = pixel_bits >> (32 * quad_row), lower = upper >> kRowPixels;
    bits |= (spread_pairs(upper) | (spread_pairs(lower) << 2)) << (32 * quad_row);
  }
  return bits;
}

}  // namespace
}  // namespace ontile::sobel
#endif  // ONTILE_SOBEL_EDGE_ROWS_TABLES_

HWY_BEFORE_NAMESPACE();
namespace ontile::sobel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using ontile::HWY_NAMESPACE::mask_bits;

bool FindEdgeRowsKernel(const float* u, const float* v, int count, uint64_t active,
                        const FragmentTaps& taps, const NeighbourhoodGrid& grid,
                        const EdgeTest& test, FragmentEdges& edges) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  using VI = hn::Vec<decltype(di)>;
  const size_t n = hn::Lanes(df);
  if (count != kBatchFragments || active != ~uint64_t{0} || grid.width != kGridWidth ||
      grid.height != kGridHeight || n > static_cast<size_t>(kRowPixels)) {
    return false;
  }
  // Every fragment at its quad-order pixel of the grid's interior, its taps the neighbours.
  const VI one = hn::Set(di, 1);
  const VI origin_x = hn::Set(di, grid.x0 + 1), origin_y = hn::Set(di, grid.y0 + 1);
  VI misfit = hn::Zero(di);
  for (size_t f = 0; f < static_cast<size_t>(kBatchFragments); f += n) {
    const VI x = hn::Load(di, taps.x[1] + f), y = hn::Load(di, taps.y[1] + f);
    const auto at_pixel =
        hn::And(hn::Eq(x, hn::Add(origin_x, hn::Load(di, kQuadOrder.column + f))),
                hn::Eq(y, hn::Add(origin_y, hn::Load(di, kQuadOrder.row + f))));
    const auto columns = hn::And(hn::Eq(hn::Load(di, taps.x[0] + f), hn::Sub(x, one)),
                                 hn::Eq(hn::Load(di, taps.x[2] + f), hn::Add(x, one)));
    const auto rows = hn::And(hn::Eq(hn::Load(di, taps.y[0] + f), hn::Sub(y, one)),
                              hn::Eq(hn::Load(di, taps.y[2] + f), hn::Add(y, one)));
    misfit = hn::Or(misfit, hn::VecFromMask(di, hn::Not(hn::And(at_pixel, hn::And(columns, rows)))));
  }
  if (!hn::AllTrue(di, hn::Eq(misfit, hn::Zero(di)))) return false;
  // Pixel rows on lanes: tap (a, b) of pixel (c, r) is grid cell (c + a) + (r + b) * width.
  alignas(64) int32_t nearest_of_pixel[kBatchFragments];
  uint64_t depth_edge_pixels = 0, edge_pixels = 0;
  for (size_t i = 0; i < static_cast<size_t>(kBatchFragments); i += n) {
    // Tap k at a constant distance from the run's first tap in each array (one base register).
    const size_t first_cell = (i / kRowPixels) * kGridWidth + i % kRowPixels;
    const float* const linear_z = grid.linear_z + first_cell;
    const float* const depth = grid.depth + first_cell;
    const float* const normal[3] = {grid.normal[0] + first_cell, grid.normal[1] + first_cell,
                                    grid.normal[2] + first_cell};
    const auto cell = [](int k) { return (k / kTapsPerAxis) * kGridWidth + k % kTapsPerAxis; };
    const VI fragment = hn::Load(di, kQuadOrder.fragment + i);
    hn::Mask<decltype(df)> depth_edge, edge;
    VI nearest;
    edge_lanes(
        df, hn::GatherIndex(df, u, fragment), hn::GatherIndex(df, v, fragment), test,
        [&](int k) { return hn::LoadU(df, linear_z + cell(k)); },
        [&](int k) { return hn::LoadU(df, depth + cell(k)); },
        [&](int c, int k) { return hn::LoadU(df, normal[c] + cell(k)); }, depth_edge, edge,
        nearest);
    hn::Store(nearest, di, nearest_of_pixel + i);
    depth_edge_pixels |= mask_bits(df, depth_edge) << i;
    edge_pixels |= mask_bits(df, edge) << i;
  }
  for (size_t f = 0; f < static_cast<size_t>(kBatchFragments); f += n) {
    hn::Store(hn::GatherIndex(di, nearest_of_pixel, hn::Load(di, kQuadOrder.pixel + f)), di,
              edges.nearest_tap + f);
  }
  edges.depth_edge = quad_order_bits(depth_edge_pixels);
  edges.edge = quad_order_bits(edge_pixels);
  return true;
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile::sobel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile::sobel {

HWY_EXPORT(FindEdgeRowsKernel);

bool find_edges_rows(const float* u, const float* v, int count, uint64_t active,
                     const FragmentTaps& taps, const NeighbourhoodGrid& grid,
                     const EdgeTest& test, FragmentEdges& edges) {
  return HWY_DYNAMIC_DISPATCH(FindEdgeRowsKernel)(u, v, count, active, taps, grid, test, edges);
}

}  // namespace ontile::sobel
#endif  // HWY_ONCE
