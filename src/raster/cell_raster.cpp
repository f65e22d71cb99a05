// Cell coverage kernels and the plane equations (see cell_raster.h), compiled once per SIMD
// target by Highway's foreach_target and chosen at run time. Integer edge arithmetic and IEEE
// add, multiply and divide for the planes, never fused: every target gives the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/cell_raster.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/lane_bits-inl.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "raster/cell_pixel_coords.h"
#include "raster/cell_raster.h"
#include "raster/cell_kernels.h"
#include "util/error.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;


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

const char* TargetNameKernel() { return hwy::TargetName(HWY_TARGET); }

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(CoverageKernel);
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
  // The cells holding the vertices' bounding box, in subpixels: a covered sample lies in the
  // triangle, inside that box. Every sample there is within (span_x - 1, span_y - 1) of each
  // vertex along each axis, and an edge's |a| <= span_y - 1, |b| <= span_x - 1 (differences of
  // vertices), so |E| <= 2 (span_x - 1) (span_y - 1) there, the bias adding at most 1 more.
  constexpr int kCellShift = kSubpixelBits + 3;
  static_assert(kCellSizePx == 1 << 3);
  const int32_t x0 = std::min({t.x_fp[0], t.x_fp[1], t.x_fp[2]}) >> kCellShift;
  const int32_t x1 = (std::max({t.x_fp[0], t.x_fp[1], t.x_fp[2]}) >> kCellShift) + 1;
  const int32_t y0 = std::min({t.y_fp[0], t.y_fp[1], t.y_fp[2]}) >> kCellShift;
  const int32_t y1 = (std::max({t.y_fp[0], t.y_fp[1], t.y_fp[2]}) >> kCellShift) + 1;
  const int64_t span_x = int64_t{x1 - x0} << kCellShift, span_y = int64_t{y1 - y0} << kCellShift;
  small = 2 * span_x * span_y < int64_t{1} << 31;
  small_x0 = x0 * kCellSizePx;
  small_y0 = y0 * kCellSizePx;
  small_x1 = x1 * kCellSizePx;
  small_y1 = y1 * kCellSizePx;
  for (int k = 0; k < 3; ++k) {
    const EdgeFunction& e = t.edge[k];
    c_biased[k] = e.c + e.bias;
    if (small) {
      a_step[k] = static_cast<int32_t>(e.a * kSubpixelScale);
      b_step[k] = static_cast<int32_t>(e.b * kSubpixelScale);
      continue;
    }
    // One multiply each: (min(a, 0) + min(b, 0)) * span is the same integer (no overflow).
    lowest[k] = (std::min<int64_t>(e.a, 0) + std::min<int64_t>(e.b, 0)) * kCellSpanSubpx;
    highest[k] = (std::max<int64_t>(e.a, 0) + std::max<int64_t>(e.b, 0)) * kCellSpanSubpx;
    int32_ok[k] = std::abs(e.a) + std::abs(e.b) <= kMaxInt32EdgeSlope;
    a_step[k] = int32_ok[k] ? static_cast<int32_t>(e.a * kSubpixelScale) : 0;
    b_step[k] = int32_ok[k] ? static_cast<int32_t>(e.b * kSubpixelScale) : 0;
  }
}

// The dispatch table's entry for the chosen target (before the first dispatch, the entry that
// chooses and then calls it: valid too).
CoverageLanesKernel coverage_lanes_kernel() { return &HWY_DYNAMIC_DISPATCH(CoverageKernel); }

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
  const int first_bit = std::countr_zero(valid) / kCellSizePx * kCellSizePx;
  const int end_bit = (kCellPixels - 1 - std::countl_zero(valid)) / kCellSizePx * kCellSizePx + kCellSizePx;
  if (edges.small) {
    if (cell_x0 < edges.small_x0 || cell_x0 >= edges.small_x1 || cell_y0 < edges.small_y0 ||
        cell_y0 >= edges.small_y1) {
      return nothing();
    }
    int64_t corner[3];
    for (int k = 0; k < 3; ++k) corner[k] = t.edge[k].a * px0 + t.edge[k].b * py0 + edges.c_biased[k];
    CellMask any = 0;
    for (int s = 0; s < pattern.count; ++s) {
      int32_t e0[3];
      for (int k = 0; k < 3; ++k) {
        e0[k] = static_cast<int32_t>(corner[k] + t.edge[k].a * pattern.x[s] + t.edge[k].b * pattern.y[s]);
      }
      out[s] = HWY_DYNAMIC_DISPATCH(CoverageKernel)(e0, edges.a_step, edges.b_step, 3, first_bit, end_bit) & valid;
      any |= out[s];
    }
    return any;
  }
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
  const double l1_dx = static_cast<double>(t.edge[1].a) * per_px;
  const double l1_dy = static_cast<double>(t.edge[1].b) * per_px;
  const double l2_dx = static_cast<double>(t.edge[2].a) * per_px;
  const double l2_dy = static_cast<double>(t.edge[2].b) * per_px;
  dz1_ = static_cast<double>(t.depth[1]) - t.depth[0];
  dz2_ = static_cast<double>(t.depth[2]) - t.depth[0];
  const double z_dx = l1_dx * dz1_ + l2_dx * dz2_;
  const double z_dy = l1_dy * dz1_ + l2_dy * dz2_;
  const double per_pixel[6] = {l1_dx, l1_dy, l2_dx, l2_dy, z_dx, z_dy};
  for (int i = 0; i < 6; ++i) gradients_[i] = static_cast<float>(per_pixel[i]);
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
