// The level of detail of the SIMD quad sampler (texture_quad_simd.cpp) for 4 quads at once:
// log2_exact on lanes (a libm-free log2 whose scalar form costs about 35 instructions per quad
// and read), so a block of quads pays for one evaluation per read.
// Compiled once per SIMD target: foreach_target re-includes this file from texture_quad_simd.cpp,
// hence the toggling guard instead of #pragma once.
#if defined(ONTILE_RASTER_TEXTURE_QUAD_LOD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ONTILE_RASTER_TEXTURE_QUAD_LOD_INL_H_
#undef ONTILE_RASTER_TEXTURE_QUAD_LOD_INL_H_
#else
#define ONTILE_RASTER_TEXTURE_QUAD_LOD_INL_H_
#endif

#include <hwy/highway.h>

#include <cstddef>
#include <cstdint>

#include "raster/log2_exact.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// out[i] = log2_exact(x[i]) + bias for i < 4, and true, where every x[i] is a normal positive
// float; else false, writing nothing (the caller takes log2_exact per quad). The scalar
// function's operations on double lanes, each an IEEE operation, so the same bits: the exponent
// split, the two table entries gathered, the polynomial with separate multiplies and adds, one
// rounding to float, then the float add of the bias.
HWY_INLINE bool log2_exact_lanes(const float* x, float bias, float* out) {
#if HWY_HAVE_FLOAT64
  using log2_exact_detail::kInvcLogc;
  using log2_exact_detail::kPoly;
  const hn::CappedTag<double, 4> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const hn::Rebind<uint32_t, decltype(dd)> du;
  const hn::Rebind<int32_t, decltype(dd)> di;
  const hn::RebindToSigned<decltype(dd)> di64;
  const size_t n = hn::Lanes(dd);
  for (size_t i = 0; i < 4; i += n) {
    const auto ix = hn::BitCast(du, hn::LoadU(df, x + i));
    // Unsigned: zero, subnormals, infinities, NaNs and negatives all land at or above the limit.
    const auto normal = hn::Lt(hn::Sub(ix, hn::Set(du, 0x00800000u)), hn::Set(du, 0x7f800000u - 0x00800000u));
    if (!hn::AllTrue(du, normal)) return false;
  }
  for (size_t i = 0; i < 4; i += n) {
    const auto ix = hn::BitCast(du, hn::LoadU(df, x + i));
    const auto tmp = hn::Sub(ix, hn::Set(du, 0x3f330000u));
    const auto entry = hn::And(hn::ShiftRight<19>(tmp), hn::Set(du, 15u));
    const auto iz = hn::Sub(ix, hn::And(tmp, hn::Set(du, 0xff800000u)));
    const auto k = hn::ShiftRight<23>(hn::BitCast(di, tmp));  // arithmetic, as int32 >> 23
    const auto offset = hn::ShiftLeft<1>(hn::PromoteTo(di64, hn::BitCast(di, entry)));
    const auto invc = hn::GatherIndex(dd, kInvcLogc, offset);
    const auto logc = hn::GatherIndex(dd, kInvcLogc + 1, offset);
    const auto r = hn::Sub(hn::Mul(hn::PromoteTo(dd, hn::BitCast(df, iz)), invc), hn::Set(dd, 1.0));
    const auto y0 = hn::Add(logc, hn::PromoteTo(dd, k));
    const auto r2 = hn::Mul(r, r);
    auto y = hn::Add(hn::Mul(hn::Set(dd, kPoly[1]), r), hn::Set(dd, kPoly[2]));
    y = hn::Add(hn::Mul(hn::Set(dd, kPoly[0]), r2), y);
    const auto p = hn::Add(hn::Mul(hn::Set(dd, kPoly[3]), r), y0);
    y = hn::Add(hn::Mul(y, r2), p);
    hn::StoreU(hn::Add(hn::DemoteTo(df, y), hn::Set(df, bias)), df, out + i);
  }
  return true;
#else
  (void)x;
  (void)bias;
  (void)out;
  return false;
#endif
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#endif  // ONTILE_RASTER_TEXTURE_QUAD_LOD_INL_H_
