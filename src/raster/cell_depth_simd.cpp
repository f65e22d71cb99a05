// Cell depth kernels (see cell_raster.h): the depth plane evaluated at a cell's samples, the
// early depth test with its write and the min/max fold hierarchical Z keeps, compiled once per
// SIMD target by Highway's foreach_target. IEEE add, multiply and compare only, never fused.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/cell_depth_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/lane_bits-inl.h"

#include <algorithm>

#include "raster/cell_pixel_coords.h"
#include "raster/cell_kernels.h"
#include "raster/cell_raster.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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

// CellDepthKernel then DepthTestKernel of a whole-width cell in one dispatched call (the
// single-sample early-Z path runs both for every covered cell).
CellMask CellDepthTestKernel(const CellPlane& depth, float off_x, float off_y, int first_row,
                             int end_row, float* z, CompareOp op, bool test, bool write,
                             float* stored, int stride, int rows, CellMask candidates,
                             float* range_lo, float* range_hi) {
  CellDepthKernel(depth.origin, depth.dx, depth.dy, off_x, off_y, first_row, end_row, z);
  return DepthTestKernel(op, test, write, z, stored, stride, kCellSizePx, rows, candidates,
                         range_lo, range_hi);
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

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(CellDepthKernel);
HWY_EXPORT(DepthTestKernel);
HWY_EXPORT(DepthRangeKernel);
HWY_EXPORT(CellDepthTestKernel);

float sample_centre_offset(int32_t s) {
  return static_cast<float>(s - kSubpixelScale / 2) / static_cast<float>(kSubpixelScale);
}

CellDepthTestKernelFn cell_depth_test_kernel() { return &HWY_DYNAMIC_DISPATCH(CellDepthTestKernel); }

void interpolate_cell_depth(const CellPlane& depth, int32_t sx, int32_t sy, float out[kCellPixels],
                            int first_row, int end_row) {
  HWY_DYNAMIC_DISPATCH(CellDepthKernel)(depth.origin, depth.dx, depth.dy, sample_centre_offset(sx),
                                        sample_centre_offset(sy), first_row, end_row, out);
}

CellMask interpolate_and_test_cell_depth(const CellPlane& depth, int32_t sx, int32_t sy,
                                         int first_row, int end_row, float z[kCellPixels],
                                         CompareOp op, bool test, bool write, float* stored,
                                         int stride, int rows, CellMask candidates,
                                         float* range_lo, float* range_hi) {
  return HWY_DYNAMIC_DISPATCH(CellDepthTestKernel)(depth, sample_centre_offset(sx), sample_centre_offset(sy),
                                                   first_row, end_row, z, op, test, write, stored,
                                                   stride, rows, candidates, range_lo, range_hi);
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

}  // namespace ontile
#endif  // HWY_ONCE
