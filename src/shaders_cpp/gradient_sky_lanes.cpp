// gradient_sky_batch (gradient_sky_lanes.h), compiled per target by Highway's foreach_target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/gradient_sky_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "shaders_cpp/gradient_sky_lanes.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void GradientSkyKernel(const float* dx, const float* dy, const float* dz, int n, const SkyColours& sky,
                       float (&colour)[4][kBatchFragments]) {
  const hn::ScalableTag<float> df;
  const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f), four = hn::Set(df, 4.0f);
  for (size_t f = 0; f < static_cast<size_t>(n); f += hn::Lanes(df)) {
    const auto x = hn::Load(df, dx + f), y = hn::Load(df, dy + f), z = hn::Load(df, dz + f);
    const auto len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(x, x), hn::Mul(y, y)), hn::Mul(z, z)));
    const auto has_length = hn::Lt(zero, len);
    const auto up = hn::IfThenElseZero(has_length, hn::Div(y, hn::IfThenElse(has_length, len, one)));
    const auto above = hn::Sqrt(up);  // NaN below the horizon, where it is not used
    const auto below_t = hn::Mul(hn::Neg(up), four);
    const auto below = hn::IfThenElse(hn::Lt(below_t, one), below_t, one);  // NaN -> 1, as `<`
    const auto is_above = hn::Ge(up, zero);
    const auto keep_above = hn::Sub(one, above), keep_below = hn::Sub(one, below);
    for (int c = 0; c < 3; ++c) {
      const auto horizon = hn::Set(df, sky.horizon[c]);
      const auto sky_c = hn::Add(hn::Mul(horizon, keep_above), hn::Mul(hn::Set(df, sky.zenith[c]), above));
      const auto earth = hn::Add(hn::Mul(horizon, keep_below), hn::Mul(hn::Set(df, sky.ground[c]), below));
      hn::Store(hn::IfThenElse(is_above, sky_c, earth), df, colour[c] + f);
    }
    hn::Store(one, df, colour[3] + f);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(GradientSkyKernel);

void gradient_sky_batch(const float* dx, const float* dy, const float* dz, int n, const SkyColours& sky,
                        float (&colour)[4][kBatchFragments]) {
  HWY_DYNAMIC_DISPATCH(GradientSkyKernel)(dx, dy, dz, n, sky, colour);
}

}  // namespace ontile
#endif  // HWY_ONCE
