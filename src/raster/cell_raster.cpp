// Cell rasterization kernels (see cell_raster.h), compiled once per SIMD target by Highway's
// foreach_target and chosen at run time. Every kernel uses only IEEE add, multiply, divide and
// compare, never fused multiply-add, so each target produces the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/cell_raster.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/lane_bits-inl.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "raster/cell_raster.h"
#include "util/error.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Pixel column / row of each bit of a cell mask.
alignas(64) constexpr int32_t kCellLx[kCellPixels] = {
    0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7,
    0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7};
alignas(64) constexpr int32_t kCellLy[kCellPixels] = {
    0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3, 3,
    4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 5, 5, 5, 5, 5, 6, 6, 6, 6, 6, 6, 6, 6, 7, 7, 7, 7, 7, 7, 7, 7};

// Bit i set where e0[k] + a[k] * lx_i + b[k] * ly_i >= 0 for every edge k < kEdges, for bits in
// [first_bit, end_bit) (others may be set or not). The caller guarantees every partial sum
// fits int32. With whole rows per vector (8 or 16 lanes) the next vector's values are this
// vector's plus b rows: one add per edge instead of two multiplies, the same integers.
template <int kEdges>
uint64_t coverage_rows(const int32_t* e0, const int32_t* a, const int32_t* b, int first_bit, int end_bit) {
  const hn::ScalableTag<int32_t> d;
  const size_t n = hn::Lanes(d);
  uint64_t bits = 0;
  // Only the rows holding valid pixels (a small triangle touches a row or two of a cell).
  const size_t begin = static_cast<size_t>(first_bit) / n * n;
  const size_t end = std::min<size_t>((static_cast<size_t>(end_bit) + n - 1) / n * n, kCellPixels);
  const auto lx = hn::Load(d, kCellLx + begin);
  const auto ly = hn::Load(d, kCellLy + begin);
  hn::Vec<decltype(d)> e[kEdges], step[kEdges];
  for (int k = 0; k < kEdges; ++k) {
    e[k] = hn::Add(hn::Add(hn::Set(d, e0[k]), hn::Mul(hn::Set(d, a[k]), lx)), hn::Mul(hn::Set(d, b[k]), ly));
    step[k] = hn::Set(d, b[k] * static_cast<int32_t>(n / kCellSizePx));
  }
  for (size_t i = begin;;) {
    // The sign bit of the OR is set iff some edge value is negative.
    auto any_negative = e[0];
    for (int k = 1; k < kEdges; ++k) any_negative = hn::Or(any_negative, e[k]);
    bits |= mask_bits(d, hn::Gt(any_negative, hn::Set(d, -1))) << i;
    i += n;
    if (i >= end) break;
    for (int k = 0; k < kEdges; ++k) e[k] = hn::Add(e[k], step[k]);
  }
  return bits;
}

uint64_t CoverageKernel(const int32_t* e0, const int32_t* a, const int32_t* b, int edges,
                        int first_bit, int end_bit) {
  const hn::ScalableTag<int32_t> d;
  const size_t n = hn::Lanes(d);
  if (n % kCellSizePx == 0 && n <= kCellPixels) {
    switch (edges) {
      case 1: return coverage_rows<1>(e0, a, b, first_bit, end_bit);
      case 2: return coverage_rows<2>(e0, a, b, first_bit, end_bit);
      default: return coverage_rows<3>(e0, a, b, first_bit, end_bit);
    }
  }
  uint64_t bits = 0;
  const size_t begin = static_cast<size_t>(first_bit) / n * n;
  const size_t end = std::min<size_t>((static_cast<size_t>(end_bit) + n - 1) / n * n, kCellPixels);
  for (size_t i = begin; i < end; i += n) {
    const auto lx = hn::Load(d, kCellLx + i);
    const auto ly = hn::Load(d, kCellLy + i);
    auto any_negative = hn::Zero(d);
    for (int k = 0; k < edges; ++k) {
      const auto e = hn::Add(hn::Add(hn::Set(d, e0[k]), hn::Mul(hn::Set(d, a[k]), lx)),
                             hn::Mul(hn::Set(d, b[k]), ly));
      any_negative = hn::Or(any_negative, e);
    }
    bits |= mask_bits(d, hn::Gt(any_negative, hn::Set(d, -1))) << i;
  }
  return bits;
}

// z = clamp(origin + dx * fx + dy * fy, 0, 1) at every pixel of a cell, the sample offset folded
// into fx, fy. The clamp is compare-and-select so NaN is handled alike on every target.
// Only the vectors holding rows [first_row, end_row) are written (a small triangle covers a
// row or two of a cell); each lane's value depends on its pixel alone.
void CellDepthKernel(float origin, float dx, float dy, float off_x, float off_y, int first_row,
                     int end_row, float* out) {
  const hn::ScalableTag<float> d;
  const hn::RebindToSigned<decltype(d)> di;
  const size_t n = hn::Lanes(d);
  const auto zero = hn::Zero(d);
  const auto one = hn::Set(d, 1.0f);
  const size_t begin = static_cast<size_t>(first_row * kCellSizePx) / n * n;
  const size_t end = std::min<size_t>((static_cast<size_t>(end_row * kCellSizePx) + n - 1) / n * n, kCellPixels);
  for (size_t i = begin; i < end; i += n) {
    const auto fx = hn::Add(hn::ConvertTo(d, hn::Load(di, kCellLx + i)), hn::Set(d, off_x));
    const auto fy = hn::Add(hn::ConvertTo(d, hn::Load(di, kCellLy + i)), hn::Set(d, off_y));
    auto z = hn::Add(hn::Add(hn::Set(d, origin), hn::Mul(hn::Set(d, dx), fx)),
                     hn::Mul(hn::Set(d, dy), fy));
    z = hn::IfThenElse(hn::Lt(z, zero), zero, z);
    z = hn::IfThenElse(hn::Gt(z, one), one, z);
    hn::StoreU(z, d, out + i);
  }
}

template <class D, class V>
auto compare(D d, CompareOp op, V incoming, V stored) {
  switch (op) {
    case CompareOp::Never: return hn::FirstN(d, 0);
    case CompareOp::Less: return hn::Lt(incoming, stored);
    case CompareOp::LessEqual: return hn::Le(incoming, stored);
    case CompareOp::Equal: return hn::Eq(incoming, stored);
    case CompareOp::Greater: return hn::Gt(incoming, stored);
    case CompareOp::GreaterEqual: return hn::Ge(incoming, stored);
    case CompareOp::NotEqual: return hn::Not(hn::Eq(incoming, stored));
    case CompareOp::Always: break;
  }
  return hn::FirstN(d, hn::Lanes(d));
}

// DepthTestKernel on whole-width rows, the compare fixed at compile time (Always when not
// testing): one vector (or two) per row with candidates. With range_lo, the fold of
// depth_range_cell_rows over every row as it is after the writes, each lane starting from the
// first stored depth after its write (the value depth_range starts from).
template <CompareOp kOp>
CellMask depth_test_rows(bool write, const float* z, float* stored, int stride, int rows,
                         CellMask candidates, float* range_lo, float* range_hi) {
  const hn::CappedTag<float, kCellSizePx> d;
  const hn::RebindToSigned<decltype(d)> di;
  const size_t n = hn::Lanes(d);
  alignas(64) static constexpr int32_t kLaneBit[kCellSizePx] = {1, 2, 4, 8, 16, 32, 64, 128};
  CellMask passing = 0;
  const bool ranged = range_lo != nullptr;
  const float first = write && (candidates & 1u) && depth_compare_passes(kOp, z[0], stored[0]) ? z[0] : stored[0];
  auto vlo = hn::Set(d, first), vhi = vlo;
  for (int ly = 0; ly < rows; ++ly) {
    const uint32_t row_bits = static_cast<uint32_t>(candidates >> (ly * kCellSizePx)) & 0xFFu;
    float* row = stored + ly * stride;
    if (!row_bits) {
      if (!ranged) continue;
      for (size_t x = 0; x < kCellSizePx; x += n) {
        const auto now = hn::LoadU(d, row + x);
        vlo = hn::IfThenElse(hn::Lt(now, vlo), now, vlo);
        vhi = hn::IfThenElse(hn::Gt(now, vhi), now, vhi);
      }
      continue;
    }
    const auto row_mask = hn::Set(di, static_cast<int32_t>(row_bits));
    for (size_t x = 0; x < kCellSizePx; x += n) {
      const auto covered = hn::RebindMask(d, hn::Ne(hn::And(row_mask, hn::Load(di, kLaneBit + x)), hn::Zero(di)));
      const auto incoming = hn::LoadU(d, z + ly * kCellSizePx + x);
      const auto old = hn::LoadU(d, row + x);
      const auto pass = kOp == CompareOp::Always ? covered : hn::And(covered, compare(d, kOp, incoming, old));
      passing |= mask_bits(d, pass) << (ly * kCellSizePx + x);
      const auto now = write ? hn::IfThenElse(pass, incoming, old) : old;
      if (write) hn::StoreU(now, d, row + x);
      if (!ranged) continue;
      vlo = hn::IfThenElse(hn::Lt(now, vlo), now, vlo);
      vhi = hn::IfThenElse(hn::Gt(now, vhi), now, vhi);
    }
  }
  if (ranged) {
    *range_lo = hn::GetLane(hn::MinOfLanes(d, vlo));
    *range_hi = hn::GetLane(hn::MaxOfLanes(d, vhi));
  }
  return passing;
}

CellMask DepthTestKernel(CompareOp op, bool test, bool write, const float* z, float* stored,
                         int stride, int cols, int rows, CellMask candidates, float* range_lo,
                         float* range_hi) {
  CellMask passing = 0;
  if (cols != kCellSizePx) {  // a cell cut by a narrow tile or the target's edge: scalar, no range
    for (int ly = 0; ly < rows; ++ly) {
      for (int lx = 0; lx < cols; ++lx) {
        const int bit = ly * kCellSizePx + lx;
        if (!((candidates >> bit) & 1u)) continue;
        float& dst = stored[ly * stride + lx];
        if (test && !depth_compare_passes(op, z[bit], dst)) continue;
        passing |= CellMask{1} << bit;
        if (write) dst = z[bit];
      }
    }
    return passing;
  }
  const CompareOp tested = test ? op : CompareOp::Always;
  switch (tested) {
    case CompareOp::Never: return depth_test_rows<CompareOp::Never>(write, z, stored, stride, rows, candidates, range_lo, range_hi);
    case CompareOp::Less: return depth_test_rows<CompareOp::Less>(write, z, stored, stride, rows, candidates, range_lo, range_hi);
    case CompareOp::LessEqual: return depth_test_rows<CompareOp::LessEqual>(write, z, stored, stride, rows, candidates, range_lo, range_hi);
    case CompareOp::Equal: return depth_test_rows<CompareOp::Equal>(write, z, stored, stride, rows, candidates, range_lo, range_hi);
    case CompareOp::Greater: return depth_test_rows<CompareOp::Greater>(write, z, stored, stride, rows, candidates, range_lo, range_hi);
    case CompareOp::GreaterEqual: return depth_test_rows<CompareOp::GreaterEqual>(write, z, stored, stride, rows, candidates, range_lo, range_hi);
    case CompareOp::NotEqual: return depth_test_rows<CompareOp::NotEqual>(write, z, stored, stride, rows, candidates, range_lo, range_hi);
    case CompareOp::Always: break;
  }
  return depth_test_rows<CompareOp::Always>(write, z, stored, stride, rows, candidates, range_lo, range_hi);
}

// Minimum and maximum of `rows` rows of `count` floats, `stride` apart, with the scalar
// semantics lo = x < lo ? x : lo (starting from first[0]), lane by lane: the same value whatever
// the order (up to the sign of a zero, which no depth compare can see).
// A whole cell row per row (count 8, the single-sample case): every row in one or two vectors of
// at most 8 lanes, no scalar tail, on every target (16-lane targets would otherwise go scalar).
void depth_range_cell_rows(const float* first, int stride, int rows, float* lo_out, float* hi_out) {
  const hn::CappedTag<float, kCellSizePx> d;
  const size_t n = hn::Lanes(d);
  auto vlo = hn::Set(d, first[0]), vhi = vlo;
  for (int r = 0; r < rows; ++r) {
    const float* row = first + static_cast<size_t>(r) * stride;
    for (size_t i = 0; i < kCellSizePx; i += n) {
      const auto x = hn::LoadU(d, row + i);
      vlo = hn::IfThenElse(hn::Lt(x, vlo), x, vlo);
      vhi = hn::IfThenElse(hn::Gt(x, vhi), x, vhi);
    }
  }
  // Every lane started from first[0]: all lanes are NaN when it is, none otherwise, so the
  // lanes' minimum and maximum (MinOfLanes / MaxOfLanes) are the scalar fold's values.
  *lo_out = hn::GetLane(hn::MinOfLanes(d, vlo));
  *hi_out = hn::GetLane(hn::MaxOfLanes(d, vhi));
}

void DepthRangeKernel(const float* first, int stride, int count, int rows, float* lo_out,
                      float* hi_out) {
  if (count == kCellSizePx) return depth_range_cell_rows(first, stride, rows, lo_out, hi_out);
  const hn::ScalableTag<float> d;
  const size_t n = hn::Lanes(d);
  float lo = first[0], hi = first[0];
  auto vlo = hn::Set(d, lo), vhi = hn::Set(d, hi);
  for (int r = 0; r < rows; ++r) {
    const float* row = first + static_cast<size_t>(r) * stride;
    size_t i = 0;
    for (; i + n <= static_cast<size_t>(count); i += n) {
      const auto x = hn::LoadU(d, row + i);
      vlo = hn::IfThenElse(hn::Lt(x, vlo), x, vlo);
      vhi = hn::IfThenElse(hn::Gt(x, vhi), x, vhi);
    }
    for (; i < static_cast<size_t>(count); ++i) {
      lo = row[i] < lo ? row[i] : lo;
      hi = row[i] > hi ? row[i] : hi;
    }
  }
  alignas(64) float lanes_lo[hn::MaxLanes(d)], lanes_hi[hn::MaxLanes(d)];
  hn::Store(vlo, d, lanes_lo);
  hn::Store(vhi, d, lanes_hi);
  for (size_t i = 0; i < n; ++i) {
    lo = lanes_lo[i] < lo ? lanes_lo[i] : lo;
    hi = lanes_hi[i] > hi ? lanes_hi[i] : hi;
  }
  *lo_out = lo;
  *hi_out = hi;
}

const char* TargetNameKernel() { return hwy::TargetName(HWY_TARGET); }

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(CoverageKernel);
HWY_EXPORT(CellDepthKernel);
HWY_EXPORT(DepthTestKernel);
HWY_EXPORT(DepthRangeKernel);
HWY_EXPORT(TargetNameKernel);

namespace {

// Edge span over a cell: sample positions lie within [0, 8 * 256 - 1] subpixels of its corner.
constexpr int64_t kCellSpanSubpx = kCellSizePx * kSubpixelScale - 1;
// An edge crossing a cell has |E| <= (|a| + |b|) * 2 * kCellSpanSubpx there, which fits int32
// when |a| + |b| <= 2^19 (edges shorter than 2048 px along each axis).
constexpr int64_t kMaxInt32EdgeSlope = int64_t{1} << 19;

// The 64-bit path for edges too steep for int32 lanes: the scalar edge functions as they are.
CellMask coverage_int64(const EdgeFunction* const* edges, int count, int64_t px0, int64_t py0,
                        int32_t sx, int32_t sy) {
  CellMask bits = 0;
  for (int bit = 0; bit < kCellPixels; ++bit) {
    const int64_t px = px0 + (bit % kCellSizePx) * kSubpixelScale + sx;
    const int64_t py = py0 + (bit / kCellSizePx) * kSubpixelScale + sy;
    bool inside = true;
    for (int k = 0; k < count && inside; ++k) inside = edges[k]->at(px, py) + edges[k]->bias >= 0;
    if (inside) bits |= CellMask{1} << bit;
  }
  return bits;
}

}  // namespace

CellEdges::CellEdges(const TriangleSetup& t) : setup(&t) {
  for (int k = 0; k < 3; ++k) {
    const EdgeFunction& e = t.edge[k];
    c_biased[k] = e.c + e.bias;
    // One multiply each: (min(a, 0) + min(b, 0)) * span is the same integer (no overflow).
    lowest[k] = (std::min<int64_t>(e.a, 0) + std::min<int64_t>(e.b, 0)) * kCellSpanSubpx;
    highest[k] = (std::max<int64_t>(e.a, 0) + std::max<int64_t>(e.b, 0)) * kCellSpanSubpx;
    int32_ok[k] = std::abs(e.a) + std::abs(e.b) <= kMaxInt32EdgeSlope;
    a_step[k] = int32_ok[k] ? static_cast<int32_t>(e.a * kSubpixelScale) : 0;
    b_step[k] = int32_ok[k] ? static_cast<int32_t>(e.b * kSubpixelScale) : 0;
  }
}

bool cells_trivially_accepted(const TriangleSetup& t, int first_x, int first_y, int last_x, int last_y) {
  const int64_t px0 = int64_t{first_x} * kSubpixelScale, py0 = int64_t{first_y} * kSubpixelScale;
  const int64_t span_x = int64_t{last_x - first_x} * kSubpixelScale + kCellSpanSubpx;
  const int64_t span_y = int64_t{last_y - first_y} * kSubpixelScale + kCellSpanSubpx;
  for (const EdgeFunction& e : t.edge) {
    // cell_coverage's lo at the first cell, with the block's spans for the cell's.
    const int64_t lo = e.at(px0, py0) + e.bias + std::min<int64_t>(e.a, 0) * span_x +
                       std::min<int64_t>(e.b, 0) * span_y;
    if (lo < 0) return false;
  }
  return true;
}

CellMask cell_coverage(const CellEdges& edges, const SamplePattern& pattern, int cell_x0,
                       int cell_y0, CellMask valid, CellMask out[kMaxSamples]) {
  const auto nothing = [&] {
    for (int s = 0; s < pattern.count; ++s) out[s] = 0;
    return CellMask{0};
  };
  if (!valid) return nothing();
  const TriangleSetup& t = *edges.setup;
  const int64_t px0 = int64_t{cell_x0} * kSubpixelScale;
  const int64_t py0 = int64_t{cell_y0} * kSubpixelScale;
  // Trivial reject / accept from each edge's extreme values over the cell.
  const EdgeFunction* partial[3];
  int32_t a[3], b[3];
  int64_t corner[3];
  int partial_count = 0;
  bool int32_ok = true;
  for (int k = 0; k < 3; ++k) {
    const int64_t at_corner = t.edge[k].a * px0 + t.edge[k].b * py0 + edges.c_biased[k];
    if (at_corner + edges.highest[k] < 0) return nothing();
    if (at_corner + edges.lowest[k] >= 0) continue;
    corner[partial_count] = at_corner;
    a[partial_count] = edges.a_step[k];
    b[partial_count] = edges.b_step[k];
    partial[partial_count++] = &t.edge[k];
    int32_ok = int32_ok && edges.int32_ok[k];
  }
  const int first_bit = std::countr_zero(valid) / kCellSizePx * kCellSizePx;
  const int end_bit = (kCellPixels - 1 - std::countl_zero(valid)) / kCellSizePx * kCellSizePx + kCellSizePx;
  CellMask any = 0;
  for (int s = 0; s < pattern.count; ++s) {
    CellMask bits = ~CellMask{0};
    if (partial_count > 0 && int32_ok) {
      int32_t e0[3];
      for (int k = 0; k < partial_count; ++k) {
        e0[k] = static_cast<int32_t>(corner[k] + partial[k]->a * pattern.x[s] + partial[k]->b * pattern.y[s]);
      }
      bits = HWY_DYNAMIC_DISPATCH(CoverageKernel)(e0, a, b, partial_count, first_bit, end_bit);
    } else if (partial_count > 0) {
      bits = coverage_int64(partial, partial_count, px0, py0, pattern.x[s], pattern.y[s]);
    }
    out[s] = bits & valid;
    any |= out[s];
  }
  return any;
}

TrianglePlanes::TrianglePlanes(const TriangleSetup& t) : t_(t) {
  const double per_px = static_cast<double>(kSubpixelScale) * t.inv_area2;
  l1_dx_ = static_cast<double>(t.edge[1].a) * per_px;
  l1_dy_ = static_cast<double>(t.edge[1].b) * per_px;
  l2_dx_ = static_cast<double>(t.edge[2].a) * per_px;
  l2_dy_ = static_cast<double>(t.edge[2].b) * per_px;
  const double dz1 = static_cast<double>(t.depth[1]) - t.depth[0];
  const double dz2 = static_cast<double>(t.depth[2]) - t.depth[0];
  z_dx_ = l1_dx_ * dz1 + l2_dx_ * dz2;
  z_dy_ = l1_dy_ * dz1 + l2_dy_ * dz2;
}

void TrianglePlanes::at_cell(int cell_x0, int cell_y0, CellPlane out[3]) const {
  const int64_t px = int64_t{cell_x0} * kSubpixelScale + kSubpixelScale / 2;
  const int64_t py = int64_t{cell_y0} * kSubpixelScale + kSubpixelScale / 2;
  const double l1 = static_cast<double>(t_.edge[1].at(px, py)) * t_.inv_area2;
  const double l2 = static_cast<double>(t_.edge[2].at(px, py)) * t_.inv_area2;
  const double z = t_.depth[0] + l1 * (static_cast<double>(t_.depth[1]) - t_.depth[0]) +
                   l2 * (static_cast<double>(t_.depth[2]) - t_.depth[0]);
  out[0] = {static_cast<float>(l1), static_cast<float>(l1_dx_), static_cast<float>(l1_dy_)};
  out[1] = {static_cast<float>(l2), static_cast<float>(l2_dx_), static_cast<float>(l2_dy_)};
  out[2] = {static_cast<float>(z), static_cast<float>(z_dx_), static_cast<float>(z_dy_)};
}

void cell_depth_bounds(const CellPlane& z, int cell_x0, int cell_y0, int x0, int y0, int x1,
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

void interpolate_cell_depth(const CellPlane& depth, int32_t sx, int32_t sy, float out[kCellPixels],
                            int first_row, int end_row) {
  const float off_x = static_cast<float>(sx - kSubpixelScale / 2) / static_cast<float>(kSubpixelScale);
  const float off_y = static_cast<float>(sy - kSubpixelScale / 2) / static_cast<float>(kSubpixelScale);
  HWY_DYNAMIC_DISPATCH(CellDepthKernel)(depth.origin, depth.dx, depth.dy, off_x, off_y, first_row,
                                        end_row, out);
}

CellMask depth_test_cell(CompareOp op, bool test, bool write, const float z[kCellPixels],
                         float* stored, int stride, int cols, int rows, CellMask candidates,
                         float* range_lo, float* range_hi) {
  return HWY_DYNAMIC_DISPATCH(DepthTestKernel)(op, test, write, z, stored, stride, cols, rows,
                                               candidates, range_lo, range_hi);
}

void depth_range(const float* first, int stride, int count, int rows, float& lo, float& hi) {
  HWY_DYNAMIC_DISPATCH(DepthRangeKernel)(first, stride, count, rows, &lo, &hi);
}

const char* active_simd_target() { return HWY_DYNAMIC_DISPATCH(TargetNameKernel)(); }

std::vector<std::string> simd_targets() {
  std::vector<std::string> names;
  // SupportedAndGeneratedTargets lists lowest bit first, which is the best target on x86.
  for (int64_t target : hwy::SupportedAndGeneratedTargets()) names.push_back(hwy::TargetName(target));
  return names;
}

void force_simd_target(const std::string& name) {
  hwy::SetSupportedTargetsForTest(0);
  if (name.empty()) return;
  for (int64_t target : hwy::SupportedAndGeneratedTargets()) {
    if (name == hwy::TargetName(target)) {
      hwy::SetSupportedTargetsForTest(target);
      return;
    }
  }
  std::string known;
  for (const std::string& n : simd_targets()) known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown SIMD target '" + name + "' (this machine: " + known + ")");
}

}  // namespace ontile
#endif  // HWY_ONCE
