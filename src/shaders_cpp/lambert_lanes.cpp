// Lambert lighting on SIMD lanes (see lambert_lanes.h), compiled per SIMD target by Highway's
// foreach_target: IEEE multiply, add, divide, square root and compares only, never fused, in
// the scalar formula's order (the functor's loop this replaces ran 4 lanes, SSE2).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/lambert_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "shaders_cpp/lambert_lanes.h"
#include "shaders_cpp/unit_normal_lanes-inl.h"

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
  const VF zero = hn::Zero(df);
  const VF lx = hn::Set(df, k.to_light[0]), ly = hn::Set(df, k.to_light[1]), lz = hn::Set(df, k.to_light[2]);
  const bool back_face = k.facing < 0.0f;
  for (size_t f = 0; f < static_cast<size_t>(count); f += hn::Lanes(df)) {
    VF x = hn::LoadU(df, nx + f), y = hn::LoadU(df, ny + f), z = hn::LoadU(df, nz + f);
    unit_lanes(df, x, y, z);  // toon_unit_normal's operations (unit_normal_lanes-inl.h)
    // Negated on back faces; the scalar formula multiplies by -1, which differs only in the sign
    // of a NaN normal, whose N.L is clamped to 0 below either way.
    if (back_face) {
      x = hn::Neg(x);
      y = hn::Neg(y);
      z = hn::Neg(z);
    }
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
