// Lambert lighting on SIMD lanes (see lambert_lanes.h), compiled per SIMD target by Highway's
// foreach_target: IEEE multiply, add, divide, square root and compares only, never fused, in
// the scalar formula's order (the functor's loop this replaces ran 4 lanes, SSE2).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/lambert_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "shaders_cpp/lambert_lanes.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using VF = hn::Vec<DF>;

template <bool kAlbedoRows, bool kEmissiveRows>
void light_lanes(const float* nx, const float* ny, const float* nz, const LambertLaneConstants& k,
                 const float (*albedo)[kBatchFragments], const float (*emissive)[kBatchFragments],
                 float (*out)[kBatchFragments], int count) {
  const DF df;
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), facing = hn::Set(df, k.facing);
  const VF lx = hn::Set(df, k.to_light[0]), ly = hn::Set(df, k.to_light[1]), lz = hn::Set(df, k.to_light[2]);
  for (size_t f = 0; f < static_cast<size_t>(count); f += hn::Lanes(df)) {
    const VF x0 = hn::LoadU(df, nx + f), y0 = hn::LoadU(df, ny + f), z0 = hn::LoadU(df, nz + f);
    const VF len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(x0, x0), hn::Mul(y0, y0)), hn::Mul(z0, z0)));
    // Divide by 1 where the length is 0 (or NaN), then select the default normal there.
    const auto has_length = hn::Gt(len, zero);
    const VF divisor = hn::IfThenElse(has_length, len, one);
    const VF x = hn::Mul(hn::IfThenElse(has_length, hn::Div(x0, divisor), zero), facing);
    const VF y = hn::Mul(hn::IfThenElse(has_length, hn::Div(y0, divisor), zero), facing);
    const VF z = hn::Mul(hn::IfThenElse(has_length, hn::Div(z0, divisor), one), facing);
    const VF dot = hn::Add(hn::Add(hn::Mul(x, lx), hn::Mul(y, ly)), hn::Mul(z, lz));
    const VF n_dot_l = hn::IfThenElse(hn::Gt(dot, zero), dot, zero);
    for (int c = 0; c < 3; ++c) {
      const VF a = kAlbedoRows ? hn::Mul(hn::Set(df, k.base_color[c]), hn::LoadU(df, albedo[c] + f))
                               : hn::Set(df, k.base_color[c]);
      const VF e = kEmissiveRows ? hn::Mul(hn::Set(df, k.emission[c]), hn::LoadU(df, emissive[c] + f))
                                 : hn::Set(df, k.emission[c]);
      const VF light = hn::Add(hn::Set(df, k.ambient[c]), hn::Mul(hn::Set(df, k.radiance[c]), n_dot_l));
      hn::StoreU(hn::Add(hn::Mul(a, light), e), df, out[c] + f);
    }
    const VF alpha = kAlbedoRows ? hn::Mul(hn::Set(df, k.base_color[3]), hn::LoadU(df, albedo[3] + f))
                                 : hn::Set(df, k.base_color[3]);
    hn::StoreU(alpha, df, out[3] + f);
  }
}

void LambertLightKernel(const float* nx, const float* ny, const float* nz,
                        const LambertLaneConstants& k, const float (*albedo)[kBatchFragments],
                        const float (*emissive)[kBatchFragments], float (*out)[kBatchFragments],
                        int count) {
  if (albedo && emissive) return light_lanes<true, true>(nx, ny, nz, k, albedo, emissive, out, count);
  if (albedo) return light_lanes<true, false>(nx, ny, nz, k, albedo, emissive, out, count);
  if (emissive) return light_lanes<false, true>(nx, ny, nz, k, albedo, emissive, out, count);
  light_lanes<false, false>(nx, ny, nz, k, albedo, emissive, out, count);
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(LambertLightKernel);

void lambert_light_batch(const float* nx, const float* ny, const float* nz,
                         const LambertLaneConstants& k, const float (*albedo)[kBatchFragments],
                         const float (*emissive)[kBatchFragments], float (*out)[kBatchFragments],
                         int count) {
  HWY_DYNAMIC_DISPATCH(LambertLightKernel)(nx, ny, nz, k, albedo, emissive, out, count);
}

}  // namespace ontile
#endif  // HWY_ONCE
