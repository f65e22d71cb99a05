// Cel shading's per-fragment arithmetic: the shadow factor of one fragment, and the lit/shadow
// mix of a whole batch on SIMD lanes (compiled per target by Highway's foreach_target, with the
// scalar code's IEEE operations in its order, so every target gives its bits).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/toon/cel_shader.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>

#include "shaders_cpp/toon/cel_shader.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// cel_shadow_factor and glm::mix per lane: Ceil is exact on every target (SSE2's emulation
// included), Lt is false for NaN as `<` is, so NaN still gives 1.
void CelMixKernel(const BatchVec3& normal, const glm::vec3& to_light, int steps, float step_size,
                  const BatchVec4& lit, const BatchVec4& shadow, int n, BatchVec4& colour) {
  const hn::ScalableTag<float> df;
  const auto lx = hn::Set(df, to_light.x), ly = hn::Set(df, to_light.y), lz = hn::Set(df, to_light.z);
  const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const auto step = hn::Set(df, step_size), bands_per_shadow = hn::Set(df, static_cast<float>(steps));
  for (size_t f = 0; f < static_cast<size_t>(n); f += hn::Lanes(df)) {
    const auto n_dot_l = hn::Add(hn::Add(hn::Mul(hn::Load(df, normal[0] + f), lx), hn::Mul(hn::Load(df, normal[1] + f), ly)),
                                 hn::Mul(hn::Load(df, normal[2] + f), lz));  // glm::dot
    const auto bands = hn::Div(hn::Ceil(hn::Div(hn::Neg(n_dot_l), step)), bands_per_shadow);
    const auto t = hn::IfThenZeroElse(hn::Ge(n_dot_l, zero), hn::IfThenElse(hn::Lt(bands, one), bands, one));
    const auto keep = hn::Sub(one, t);
    for (int c = 0; c < 4; ++c) {
      const auto mixed = hn::Add(hn::Mul(hn::Load(df, lit[c] + f), keep), hn::Mul(hn::Load(df, shadow[c] + f), t));
      hn::Store(mixed, df, colour[c] + f);
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(CelMixKernel);

float cel_shadow_factor(float n_dot_l, int steps, float step_size) {
  if (n_dot_l >= 0.0f) return 0.0f;
  const float bands = std::ceil(-n_dot_l / step_size) / static_cast<float>(steps);
  return bands < 1.0f ? bands : 1.0f;  // also maps NaN to 1
}

void cel_mix_batch(const BatchVec3& normal, const glm::vec3& to_light, int steps, float step_size,
                   const BatchVec4& lit, const BatchVec4& shadow, int n, BatchVec4& colour) {
  HWY_DYNAMIC_DISPATCH(CelMixKernel)(normal, to_light, steps, step_size, lit, shadow, n, colour);
}

}  // namespace ontile
#endif  // HWY_ONCE
