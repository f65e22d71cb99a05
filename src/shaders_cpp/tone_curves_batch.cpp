// Batched tone curves (see tone_curves_batch.h), compiled per SIMD target by Highway's
// foreach_target: IEEE multiply, add, subtract, divide and compares only, in tone_curves.cpp's
// order (glm's vector operators, glm::clamp's (x < lo ? lo : x) then (hi < x ? hi : x)).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/tone_curves_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "shaders_cpp/tone_curves_batch.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using VF = hn::Vec<DF>;

// (k0 * x + k1 * y) + k2 * z, each product rounded: the scalar matrix rows.
HWY_INLINE VF row(DF df, float k0, VF x, float k1, VF y, float k2, VF z) {
  return hn::Add(hn::Add(hn::Mul(hn::Set(df, k0), x), hn::Mul(hn::Set(df, k1), y)), hn::Mul(hn::Set(df, k2), z));
}

// RRTAndODTFit of one channel: (v * (v + a0) - a1) / (v * (b0 * v + b1) + b2).
HWY_INLINE VF rrt_odt_fit(DF df, VF v) {
  const VF a = hn::Sub(hn::Mul(v, hn::Add(v, hn::Set(df, 0.0245786f))), hn::Set(df, 0.000090537f));
  const VF b = hn::Add(hn::Mul(v, hn::Add(hn::Mul(hn::Set(df, 0.983729f), v), hn::Set(df, 0.4329510f))),
                       hn::Set(df, 0.238081f));
  return hn::Div(a, b);
}

HWY_INLINE VF saturate(DF df, VF x) {
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const VF low = hn::IfThenElse(hn::Lt(x, zero), zero, x);  // glm::max(x, 0)
  return hn::IfThenElse(hn::Lt(one, low), one, low);        // glm::min(., 1)
}

void AcesFittedKernel(float (&rgba)[4][kBatchFragments], float exposure, int count) {
  const DF df;
  const VF scale = hn::Set(df, exposure);
  for (size_t f = 0; f < static_cast<size_t>(count); f += hn::Lanes(df)) {
    const VF cx = hn::Mul(hn::LoadU(df, rgba[0] + f), scale);
    const VF cy = hn::Mul(hn::LoadU(df, rgba[1] + f), scale);
    const VF cz = hn::Mul(hn::LoadU(df, rgba[2] + f), scale);
    const VF vx = row(df, 0.59719f, cx, 0.35458f, cy, 0.04823f, cz);
    const VF vy = row(df, 0.07600f, cx, 0.90834f, cy, 0.01566f, cz);
    const VF vz = row(df, 0.02840f, cx, 0.13383f, cy, 0.83777f, cz);
    const VF fx = rrt_odt_fit(df, vx), fy = rrt_odt_fit(df, vy), fz = rrt_odt_fit(df, vz);
    // 1.60475 fx - 0.53108 fy - 0.07367 fz and the other rows, as written (subtractions kept).
    const auto product = [&](float k, VF v) { return hn::Mul(hn::Set(df, k), v); };
    const VF ox = hn::Sub(hn::Sub(product(1.60475f, fx), product(0.53108f, fy)), product(0.07367f, fz));
    const VF oy = hn::Sub(hn::Add(product(-0.10208f, fx), product(1.10813f, fy)), product(0.00605f, fz));
    const VF oz = hn::Add(hn::Sub(product(-0.00327f, fx), product(0.07276f, fy)), product(1.07602f, fz));
    hn::StoreU(saturate(df, ox), df, rgba[0] + f);
    hn::StoreU(saturate(df, oy), df, rgba[1] + f);
    hn::StoreU(saturate(df, oz), df, rgba[2] + f);
    hn::StoreU(hn::Set(df, 1.0f), df, rgba[3] + f);
  }
}

void ReinhardKernel(float (&rgba)[4][kBatchFragments], float exposure, int count) {
  const DF df;
  const VF scale = hn::Set(df, exposure), zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  for (size_t f = 0; f < static_cast<size_t>(count); f += hn::Lanes(df)) {
    for (int c = 0; c < 3; ++c) {
      const VF x = hn::Mul(hn::LoadU(df, rgba[c] + f), scale);
      const VF positive = hn::IfThenElse(hn::Lt(x, zero), zero, x);  // glm::max(x, 0)
      hn::StoreU(hn::Div(positive, hn::Add(one, positive)), df, rgba[c] + f);
    }
    hn::StoreU(one, df, rgba[3] + f);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(AcesFittedKernel);
HWY_EXPORT(ReinhardKernel);

void tonemap_aces_fitted_batch(float (&rgba)[4][kBatchFragments], float exposure, int count) {
  HWY_DYNAMIC_DISPATCH(AcesFittedKernel)(rgba, exposure, count);
}

void tonemap_reinhard_batch(float (&rgba)[4][kBatchFragments], float exposure, int count) {
  HWY_DYNAMIC_DISPATCH(ReinhardKernel)(rgba, exposure, count);
}

}  // namespace ontile
#endif  // HWY_ONCE
