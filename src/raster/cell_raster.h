// Hierarchical rasterization in 8x8-pixel screen cells (as llvmpipe and Larrabee do): each
// edge is trivially accepted or rejected for a whole cell from its corner values, and only the
// cells an edge crosses are evaluated per sample, on SIMD lanes (Highway, runtime dispatch) in
// 32-bit fixed point when the edge's slope allows it, 64-bit otherwise. Also the float plane
// equations (barycentrics, depth) the interpolation evaluates, anchored at each cell's origin.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "raster/sample_pattern.h"
#include "raster/triangle_setup.h"

namespace ontile {

// Cells are aligned to multiples of 8 pixels in render-target space, whatever the tile size,
// so every value computed from a cell's origin is the same in every pass and tile grid.
constexpr int kCellSizePx = 8;
constexpr int kCellPixels = kCellSizePx * kCellSizePx;

// Bit (ly * 8 + lx) of a cell mask is pixel (cell_x0 + lx, cell_y0 + ly).
using CellMask = uint64_t;

// The pixels of the cell at (cell_x0, cell_y0) inside the rectangle [x0, x1) x [y0, y1): the
// row's bits copied into every byte (a multiply by 0x0101...: a byte-wide value cannot carry),
// then the bytes of rows [ly0, ly1) kept. Inline: the tile loop asks once per cell and triangle.
inline CellMask cell_rect_mask(int cell_x0, int cell_y0, int x0, int y0, int x1, int y1) {
  const int lx0 = x0 - cell_x0 > 0 ? x0 - cell_x0 : 0, lx1 = x1 - cell_x0 < kCellSizePx ? x1 - cell_x0 : kCellSizePx;
  const int ly0 = y0 - cell_y0 > 0 ? y0 - cell_y0 : 0, ly1 = y1 - cell_y0 < kCellSizePx ? y1 - cell_y0 : kCellSizePx;
  if (lx0 >= lx1 || ly0 >= ly1) return 0;
  const uint64_t row = ((uint64_t{1} << (lx1 - lx0)) - 1) << lx0;
  const int row_count = ly1 - ly0;
  const uint64_t rows = (row_count == kCellSizePx ? ~uint64_t{0} : (uint64_t{1} << (row_count * kCellSizePx)) - 1)
                        << (ly0 * kCellSizePx);
  return (row * 0x0101010101010101u) & rows;
}

// A triangle's edges prepared once for cell_coverage of many cells: each edge's constant with
// the fill-rule bias folded in and its steps for the int32 lanes. A small triangle (most of a
// detailed scene's) has every edge value at every sample of the cells around its vertices in
// int32 range: those cells evaluate all three edges on int32 lanes with no per-edge trivial
// tests (an edge a test would accept is >= 0 at every sample and changes no bit), and no other
// cell holds a covered sample. Otherwise each edge's extreme offsets over a cell's sample span
// (trivial reject / accept) and whether its steps fit the int32 lanes.
struct CellEdges {
  explicit CellEdges(const TriangleSetup& t);
  const TriangleSetup* setup;
  int64_t c_biased[3];
  int32_t a_step[3], b_step[3];   // a and b per pixel (x 256), valid where int32_ok
  bool small;
  // Small triangles: pixel bounds [x0, x1) x [y0, y1) of the cells holding the vertices'
  // bounding box (multiples of 8).
  int32_t small_x0, small_y0, small_x1, small_y1;
  // Set only when !small.
  int64_t lowest[3], highest[3];  // min / max of a * dx + b * dy over dx, dy in [0, span]
  bool int32_ok[3];
};

// Coverage of the cell at (cell_x0, cell_y0), restricted to `valid` pixels: out[s] gets the
// pixels whose sample s is inside (top-left rule included). Returns the union over samples.
// Bit-exact with the scalar edge functions: this is integer arithmetic on every path.
CellMask cell_coverage(const CellEdges& edges, const SamplePattern& pattern, int cell_x0,
                       int cell_y0, CellMask valid, CellMask out[kMaxSamples]);
inline CellMask cell_coverage(const TriangleSetup& t, const SamplePattern& pattern, int cell_x0,
                              int cell_y0, CellMask valid, CellMask out[kMaxSamples]) {
  return cell_coverage(CellEdges(t), pattern, cell_x0, cell_y0, valid, out);
}

// True when cell_coverage's per-cell trivial accept holds for all three edges of every cell
// whose top-left pixel is (first_x + 8 i, first_y + 8 j), first_x <= first_x + 8 i <= last_x
// and likewise in y: each edge's lowest value over that block of cells is >= 0, and an edge is
// affine, so its lowest value over any one cell is too. cell_coverage then gives out[s] = valid
// for every such cell (full-screen triangles: one test per tile instead of one per cell).
bool cells_trivially_accepted(const TriangleSetup& t, int first_x, int first_y, int last_x, int last_y);

// An affine function of the pixel position, v(x, y) = origin + dx * (x - cell_x0) +
// dy * (y - cell_y0) with x, y at pixel-centre offsets, in float.
struct CellPlane {
  float origin = 0.0f, dx = 0.0f, dy = 0.0f;
};

// The screen-space barycentrics of vertices 1 and 2 and the depth (z/w) as plane equations of
// one triangle, exact in double and rounded to float per cell.
class TrianglePlanes {
 public:
  explicit TrianglePlanes(const TriangleSetup& t);
  // Planes anchored at the centre of the cell's top-left pixel: [0] lambda1, [1] lambda2,
  // [2] depth. Inline: the tile loop asks once per covered cell.
  void at_cell(int cell_x0, int cell_y0, CellPlane out[3]) const {
    const int64_t px = int64_t{cell_x0} * kSubpixelScale + kSubpixelScale / 2;
    const int64_t py = int64_t{cell_y0} * kSubpixelScale + kSubpixelScale / 2;
    const double l1 = static_cast<double>(t_.edge[1].at(px, py)) * t_.inv_area2;
    const double l2 = static_cast<double>(t_.edge[2].at(px, py)) * t_.inv_area2;
    const double z = t_.depth[0] + l1 * dz1_ + l2 * dz2_;
    out[0] = {static_cast<float>(l1), gradients_[0], gradients_[1]};
    out[1] = {static_cast<float>(l2), gradients_[2], gradients_[3]};
    out[2] = {static_cast<float>(z), gradients_[4], gradients_[5]};
  }

 private:
  const TriangleSetup& t_;
  double dz1_, dz2_;  // depth[1] - depth[0], depth[2] - depth[0]
  float gradients_[6];  // l1, l2, z per pixel along x and y, rounded to float
};

// Bounds of the depth plane `depth` (from at_cell for the cell at cell_x0, cell_y0) over the
// sample area of pixels [x0, x1) x [y0, y1), widened by the float evaluation's error bound
// (docs/rasterization.md): every depth interpolate_cell_depth() returns there lies in
// [min_out, max_out] before clamping. Inline: asked once per covered cell.
inline void cell_depth_bounds(const CellPlane& z, int cell_x0, int cell_y0, int x0, int y0, int x1,
                              int y1, double& min_out, double& max_out) {
  // Sample offsets from the top-left pixel centre span [x0 - cell_x0 - 0.5, x1 - cell_x0 - 0.5].
  const double fx_lo = x0 - cell_x0 - 0.5, fx_hi = x1 - cell_x0 - 0.5;
  const double fy_lo = y0 - cell_y0 - 0.5, fy_hi = y1 - cell_y0 - 0.5;
  const double zx_lo = std::min(z.dx * fx_lo, z.dx * fx_hi), zx_hi = std::max(z.dx * fx_lo, z.dx * fx_hi);
  const double zy_lo = std::min(z.dy * fy_lo, z.dy * fy_hi), zy_hi = std::max(z.dy * fy_lo, z.dy * fy_hi);
  // The float evaluation fl(fl(o + fl(dx fx)) + fl(dy fy)) of the float-rounded plane differs
  // from this (exactly evaluated) float plane by at most 3 roundings of the largest partial
  // magnitude; 8 units of 2^-24 is a safe margin (docs/rasterization.md).
  const double magnitude = std::abs(static_cast<double>(z.origin)) +
                           std::abs(static_cast<double>(z.dx)) * kCellSizePx +
                           std::abs(static_cast<double>(z.dy)) * kCellSizePx;
  const double margin = magnitude * 8.0 * 0x1p-24 + 0x1p-126;
  min_out = z.origin + zx_lo + zy_lo - margin;
  max_out = z.origin + zx_hi + zy_hi + margin;
}

// Depth of the plane at every pixel of a cell, at sample offset (sx, sy) in 1/256 px from the
// pixel's top-left corner, clamped to [0, 1] (Vulkan clamps before the depth test): out[64],
// row-major. Same bits on every SIMD target (no FMA, IEEE operations only). Only rows
// [first_row, end_row) are guaranteed written (others may be or not): a small triangle's rows.
void interpolate_cell_depth(const CellPlane& depth, int32_t sx, int32_t sy, float out[kCellPixels],
                            int first_row = 0, int end_row = kCellSizePx);

// Perspective-correct interpolation for `count` fragments (a multiple of 4, the quad lanes; it
// reads and writes nothing past them): fragment f sits at
// offset (fx[f], fy[f]) pixels from its cell's top-left pixel centre and uses that cell's planes
// (l1, l2, z per fragment). Writes depth[f] (clamped to [0, 1]) and, for each varying k,
// out_varyings[k * stride + f] = v0[k] + w1 (v1[k] - v0[k]) + w2 (v2[k] - v0[k]) with w_i the
// perspective weights (lambda_i / w_i normalised).
struct InterpolationInput {
  const float* fx;
  const float* fy;
  const float* l1_origin;
  const float* l2_origin;
  const float* z_origin;
  float l1_dx, l1_dy, l2_dx, l2_dy, z_dx, z_dy;
  float inv_w[3];
  const float* vertex_varyings[3];  // varying_count floats per vertex, setup slot order
  int varying_count;
  uint32_t varyings_written = ~uint32_t{0};  // bit k clear: varying k's output is left as it is
};
void interpolate_fragments(const InterpolationInput& in, int count, float* depth_out,
                           float* varyings_out, int varyings_stride);

// interpolate_fragments for whole quads, without per-fragment inputs: quad q's fragments
// 4q .. 4q + 3 (lanes (0,0), (1,0), (0,1), (1,1)) sit at offsets (ox[q] + (lane & 1),
// oy[q] + (lane >> 1)) pixels from its cell's top-left pixel centre and use its cell's plane
// origins l1[q], l2[q], z[q]. The results are bit for bit those of interpolate_fragments given
// those offsets (as floats) and origins per fragment; `in`'s per-fragment pointers are unused.
// Every per-quad array must be readable up to quad_count + kQuadOriginsPadding entries.
struct QuadOrigins {
  const int32_t* ox;
  const int32_t* oy;
  const float* l1;
  const float* l2;
  const float* z;
};
constexpr int kQuadOriginsPadding = 16;
void interpolate_whole_quads(const InterpolationInput& in, const QuadOrigins& quads,
                             int quad_count, float* depth_out, float* varyings_out,
                             int varyings_stride);

// Depth test of the covered pixels of one cell of single-sample tile memory whose rows are
// `stride` floats apart: stored[(ly * stride) + lx] for the cell's `cols` x `rows` pixels.
// Returns the candidates that pass `op` (all candidates when !test) and, when `write`, stores
// their depth. The caller passes only candidates inside cols x rows. With range_lo and
// range_hi, for a whole-width cell (cols == 8) only, also the minimum and maximum of the
// rows x 8 stored depths after the writes, as depth_range() gives them (hierarchical Z's
// refresh without a second pass over the cell).
CellMask depth_test_cell(CompareOp op, bool test, bool write, const float z[kCellPixels],
                         float* stored, int stride, int cols, int rows, CellMask candidates,
                         float* range_lo = nullptr, float* range_hi = nullptr);

// interpolate_cell_depth(depth, sx, sy, z, first_row, end_row) then depth_test_cell(op, test,
// write, z, stored, stride, 8, rows, candidates, range_lo, range_hi) in one call: a cell whose
// top-left pixel is in the tile and whose whole width is (the common single-sample case).
CellMask interpolate_and_test_cell_depth(const CellPlane& depth, int32_t sx, int32_t sy,
                                         int first_row, int end_row, float z[kCellPixels],
                                         CompareOp op, bool test, bool write, float* stored,
                                         int stride, int rows, CellMask candidates,
                                         float* range_lo = nullptr, float* range_hi = nullptr);

// The minimum and maximum of `rows` rows of `count` stored depths, `stride` floats apart (what
// hierarchical Z keeps per cell). A NaN is never chosen unless it is first[0].
void depth_range(const float* first, int stride, int count, int rows, float& lo, float& hi);

// Name of the SIMD target the dispatched functions run on now (for reports and tests).
const char* active_simd_target();
// The SIMD targets compiled in and supported by this CPU, best first (e.g. AVX2, SSE4, SSSE3,
// EMU128). force_simd_target(name) makes every kernel run on that target ("" = the best);
// throws Error for a name not in the list. Used by tests (same bits on every target) and the
// CLI's --simd option. Not thread-safe: call it between frames.
std::vector<std::string> simd_targets();
void force_simd_target(const std::string& name);

}  // namespace ontile
