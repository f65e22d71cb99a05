// Vertex classification and snapping kernels (see vertex_kernels.h), compiled once per SIMD
// target by Highway's foreach_target and chosen at run time. Only IEEE add, subtract, multiply,
// divide, compare, truncation and conversions, no fused multiply-add, in the order the scalar
// clip_outcode() and snap_vertex() use: every target gives their bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tiler/detail/vertex_kernels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>

#include "tiler/detail/vertex_kernels.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Lanes of the widest double vector of any target (AVX-512: 8) are at most this.
constexpr size_t kMaxLanes = 16;
static_assert(HWY_LANES(double) <= kMaxLanes);

void ClassifySnapKernel(const float* xyzw, uint32_t count, const float* guard_xy,
                        int width_px, int height_px, int subpixel_bits, uint16_t* outcode,
                        SnappedVertex* snapped) {
  using namespace clip_plane;
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const hn::Rebind<int32_t, decltype(dd)> di;
  const size_t n = hn::Lanes(dd);
  const auto zero_f = hn::Zero(df);
  const auto g_x_max = hn::Set(df, guard_xy[0]), g_x_min = hn::Set(df, guard_xy[1]);
  const auto g_y_max = hn::Set(df, guard_xy[2]), g_y_min = hn::Set(df, guard_xy[3]);
  const auto min_w = hn::Set(df, kClipMinW);
  const auto half = hn::Set(dd, 0.5), one = hn::Set(dd, 1.0), minus_half = hn::Set(dd, -0.5);
  const auto width = hn::Set(dd, static_cast<double>(width_px));
  const auto height = hn::Set(dd, static_cast<double>(height_px));
  const auto snap_scale = hn::Set(dd, static_cast<double>(int64_t{1} << subpixel_bits));
  const auto grid_step = hn::Set(dd, static_cast<double>(kSubpixelScale >> subpixel_bits));
  // Nearest integer, halfway cases away from zero (round_half_away_from_zero): v - trunc(v)
  // is exact, so are the tie comparisons and the +-1.
  const auto round_half_away = [&](auto v) {
    const auto t = hn::Trunc(v);
    const auto f = hn::Sub(v, t);
    return hn::Sub(hn::Add(t, hn::IfThenElseZero(hn::Ge(f, half), one)),
                   hn::IfThenElseZero(hn::Le(f, minus_half), one));
  };
  alignas(64) float x[kMaxLanes], y[kMaxLanes], z[kMaxLanes], w[kMaxLanes];
  alignas(64) int32_t code[kMaxLanes], x_fp[kMaxLanes], y_fp[kMaxLanes];
  alignas(64) float depth[kMaxLanes], inv_w[kMaxLanes];
  for (uint32_t first = 0; first < count; first += static_cast<uint32_t>(n)) {
    const size_t lanes = std::min<size_t>(n, count - first);
    // Transpose to one array per component; lanes past the end get the harmless (0, 0, 0, 1).
    for (size_t i = 0; i < n; ++i) {
      const float* p = xyzw + 4 * (first + std::min(i, lanes - 1));
      const bool valid = i < lanes;
      x[i] = valid ? p[0] : 0.0f;
      y[i] = valid ? p[1] : 0.0f;
      z[i] = valid ? p[2] : 0.0f;
      w[i] = valid ? p[3] : 1.0f;
    }
    const auto vx = hn::Load(df, x), vy = hn::Load(df, y), vz = hn::Load(df, z),
               vw = hn::Load(df, w);
    // Outcodes in float, as clip_outcode(): bit set where the distance is not >= 0 (NaN too).
    auto bits = hn::Zero(di);
    const auto outside = [&](auto distance, int plane) {
      bits = hn::Or(bits, hn::IfThenZeroElse(hn::RebindMask(di, hn::Ge(distance, zero_f)),
                                             hn::Set(di, int32_t{1} << plane)));
    };
    outside(vz, kNear);
    outside(hn::Sub(vw, vz), kFar);
    outside(hn::Sub(vw, min_w), kPositiveW);
    outside(hn::Sub(hn::Mul(g_x_max, vw), vx), kGuardRight);
    outside(hn::Sub(vx, hn::Mul(g_x_min, vw)), kGuardLeft);
    outside(hn::Sub(vy, hn::Mul(g_y_min, vw)), kGuardBottom);
    outside(hn::Sub(hn::Mul(g_y_max, vw), vy), kGuardTop);
    outside(hn::Sub(vw, vx), kViewRight);
    outside(hn::Add(vx, vw), kViewLeft);
    outside(hn::Add(vy, vw), kViewBottom);
    outside(hn::Sub(vw, vy), kViewTop);
    // v - v is 0 exactly for finite v and NaN for NaN and Inf.
    const auto finite = hn::And(
        hn::And(hn::Eq(hn::Sub(vx, vx), zero_f), hn::Eq(hn::Sub(vy, vy), zero_f)),
        hn::And(hn::Eq(hn::Sub(vz, vz), zero_f), hn::Eq(hn::Sub(vw, vw), zero_f)));
    bits = hn::IfThenElse(hn::RebindMask(di, finite), bits, hn::Set(di, kNonFiniteVertex));
    hn::Store(bits, di, code);

    // Viewport transform and snapping in double, as snap_vertex().
    const auto inv = hn::Div(one, hn::PromoteTo(dd, vw));
    const auto ndc_x = hn::Mul(hn::PromoteTo(dd, vx), inv);
    const auto ndc_y = hn::Mul(hn::PromoteTo(dd, vy), inv);
    const auto sx = hn::Mul(hn::Add(hn::Mul(ndc_x, half), half), width);
    const auto sy = hn::Mul(hn::Sub(half, hn::Mul(ndc_y, half)), height);
    // NaN (a non-finite vertex, flagged above and dropped later) becomes 2^31 - 1 before the
    // conversion to int32, as on Highway's x86 targets, whose clamp (MINPD) returns the bound
    // for NaN. Its scalar EMU128 target would cast NaN to int, which is undefined behaviour
    // (found by UBSan, docs/robustness.md); the x86 results do not change.
    const auto int32_max = hn::Set(dd, 2147483647.0);
    const auto fixed_point = [&](auto v) { return hn::IfThenElse(hn::IsNaN(v), int32_max, v); };
    hn::Store(hn::DemoteTo(di, fixed_point(hn::Mul(round_half_away(hn::Mul(sx, snap_scale)), grid_step))), di,
              x_fp);
    hn::Store(hn::DemoteTo(di, fixed_point(hn::Mul(round_half_away(hn::Mul(sy, snap_scale)), grid_step))), di,
              y_fp);
    hn::Store(hn::DemoteTo(df, hn::Mul(hn::PromoteTo(dd, vz), inv)), df, depth);
    hn::Store(hn::DemoteTo(df, inv), df, inv_w);
    for (size_t i = 0; i < lanes; ++i) {
      outcode[first + i] = static_cast<uint16_t>(code[i]);
      snapped[first + i] = SnappedVertex{x_fp[i], y_fp[i], depth[i], inv_w[i]};
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(ClassifySnapKernel);

void classify_and_snap(const glm::vec4* position, uint32_t count, const GuardBand& guard,
                       int width_px, int height_px, int subpixel_bits, uint16_t* outcode,
                       SnappedVertex* snapped) {
  static_assert(sizeof(glm::vec4) == 4 * sizeof(float));
  const float guard_xy[4] = {guard.x_max, guard.x_min, guard.y_max, guard.y_min};
  HWY_DYNAMIC_DISPATCH(ClassifySnapKernel)(&position[0].x, count, guard_xy, width_px, height_px,
                                           subpixel_bits, outcode, snapped);
}

}  // namespace ontile
#endif  // HWY_ONCE
