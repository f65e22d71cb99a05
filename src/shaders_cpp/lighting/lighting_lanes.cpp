// The batched lighting helpers of brdf.h and punctual_light.h on SIMD lanes, compiled per target
// by Highway's foreach_target: the per-fragment functions' IEEE multiply, add, subtract, divide,
// square root and compares in their order (no FMA), so every target gives their bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/lighting/lighting_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>

#include "shaders_cpp/lighting/brdf.h"
#include "shaders_cpp/lighting/punctual_light.h"
#include "shaders_cpp/lighting/schlick_power.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using VF = hn::Vec<DF>;
using MF = hn::Mask<DF>;

// Lanes i.. of [begin, end).
HWY_INLINE MF lanes_in(DF df, size_t i, int begin, int end) {
  const DI di;
  const auto index = hn::Add(hn::Iota(di, 0), hn::Set(di, static_cast<int32_t>(i)));
  const auto inside = hn::And(hn::Gt(index, hn::Set(di, begin - 1)), hn::Lt(index, hn::Set(di, end)));
  return hn::RebindMask(df, inside);
}

HWY_INLINE MF nonzero(DF df, const int32_t* flags, size_t i) {
  const DI di;
  return hn::RebindMask(df, hn::Ne(hn::LoadU(di, flags + i), hn::Zero(di)));
}

// a < b ? b : a, as std::max(a, b) with b the bound (NaN a stays NaN).
HWY_INLINE VF at_least(VF a, VF bound) { return hn::IfThenElse(hn::Lt(a, bound), bound, a); }

// x^5 as std::pow(x, 5.0f) returns it (schlick_power.h) for lanes i.. of x into out.
void SchlickPowerKernel(const float* x, int count, float* out) {
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> dh;  // half-width floats, one per double lane
  const hn::RebindToUnsigned<decltype(dd)> du;
  const size_t n = hn::Lanes(dd);
  const auto dropped_mask = hn::Set(du, (uint64_t{1} << kSchlickDroppedBits) - 1);
  const auto window_shift = hn::Set(du, (uint64_t{1} << (kSchlickDroppedBits - 1)) - kSchlickTieWindow);
  const auto window = hn::Set(du, 2 * kSchlickTieWindow);
  const auto smallest = hn::Set(dd, kSchlickSmallestNormal), largest = hn::Set(dd, kSchlickLargest);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto xd = hn::PromoteTo(dd, hn::LoadU(dh, x + i));
    const auto x2 = hn::Mul(xd, xd);
    const auto r = hn::Mul(hn::Mul(x2, x2), xd);
    hn::StoreU(hn::DemoteTo(dh, r), dh, out + i);
    // Lanes near a tie of the float rounding, or outside the normal floats: std::pow itself.
    const auto near_tie = hn::Lt(hn::Sub(hn::And(hn::BitCast(du, r), dropped_mask), window_shift), window);
    const auto magnitude = hn::Abs(r);
    const auto normal = hn::Or(hn::Eq(r, hn::Zero(dd)),
                               hn::And(hn::Ge(magnitude, smallest), hn::Lt(magnitude, largest)));
    const auto scalar = hn::Or(hn::RebindMask(dd, near_tie), hn::Not(normal));
    if (!hn::AllFalse(dd, scalar)) {
      for (size_t lane = 0; lane < n; ++lane) {
        if (!schlick_power_is_exact(static_cast<double>(x[i + lane]))) out[i + lane] = std::pow(x[i + lane], 5.0f);
      }
    }
  }
  for (; i < static_cast<size_t>(count); ++i) out[i] = schlick_power(x[i]);
}

void ShadeGgxKernel(const BrdfBatch& b, const BatchVec3& n, const BatchVec3& to_view, const BatchVec3& to_light,
                    const BatchVec3& radiance, const int32_t* reached, int begin, int end, bool accumulate,
                    BatchVec3& sum) {
  const DF df;
  const size_t lanes = hn::Lanes(df);
  const size_t first = static_cast<size_t>(begin) - static_cast<size_t>(begin) % lanes;
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), pi = hn::Set(df, 3.14159265f);
  alignas(64) float n_dot_l[kBatchFragments], one_minus_v_dot_h[kBatchFragments] = {};
  alignas(64) float specular_scale[kBatchFragments], schlick[kBatchFragments];
  alignas(64) int32_t wants_power[kBatchFragments];
  for (size_t i = first; i < static_cast<size_t>(end); i += lanes) {
    const VF nx = hn::Load(df, n[0] + i), ny = hn::Load(df, n[1] + i), nz = hn::Load(df, n[2] + i);
    const VF vx = hn::Load(df, to_view[0] + i), vy = hn::Load(df, to_view[1] + i), vz = hn::Load(df, to_view[2] + i);
    const VF lx = hn::Load(df, to_light[0] + i), ly = hn::Load(df, to_light[1] + i), lz = hn::Load(df, to_light[2] + i);
    const VF ndl = hn::Add(hn::Add(hn::Mul(nx, lx), hn::Mul(ny, ly)), hn::Mul(nz, lz));
    const VF n_dot_v = at_least(hn::Add(hn::Add(hn::Mul(nx, vx), hn::Mul(ny, vy)), hn::Mul(nz, vz)),
                                hn::Set(df, 1e-4f));
    const VF hx = hn::Add(lx, vx), hy = hn::Add(ly, vy), hz = hn::Add(lz, vz);
    const VF half_length = hn::Sqrt(hn::Add(hn::Add(hn::Mul(hx, hx), hn::Mul(hy, hy)), hn::Mul(hz, hz)));
    const MF has_half = hn::Gt(half_length, zero);
    const VF divisor = hn::IfThenElse(has_half, half_length, one);
    const VF ux = hn::IfThenElse(has_half, hn::Div(hx, divisor), nx);
    const VF uy = hn::IfThenElse(has_half, hn::Div(hy, divisor), ny);
    const VF uz = hn::IfThenElse(has_half, hn::Div(hz, divisor), nz);
    const VF n_dot_h = at_least(hn::Add(hn::Add(hn::Mul(nx, ux), hn::Mul(ny, uy)), hn::Mul(nz, uz)), zero);
    const VF v_dot_h = at_least(hn::Add(hn::Add(hn::Mul(vx, ux), hn::Mul(vy, uy)), hn::Mul(vz, uz)), zero);
    const VF r = at_least(hn::Load(df, b.roughness + i), hn::Set(df, kMinPerceptualRoughness));
    const VF r2 = hn::Mul(r, r);
    const VF alpha2 = hn::Mul(r2, r2);
    const VF d_denominator = hn::Add(hn::Mul(hn::Mul(n_dot_h, n_dot_h), hn::Sub(alpha2, one)), one);
    const VF distribution = hn::Div(alpha2, hn::Mul(hn::Mul(pi, d_denominator), d_denominator));
    const VF one_minus_alpha2 = hn::Sub(one, alpha2);
    const VF smith_l = hn::Mul(n_dot_v, hn::Sqrt(hn::Add(hn::Mul(hn::Mul(ndl, ndl), one_minus_alpha2), alpha2)));
    const VF smith_v = hn::Mul(ndl, hn::Sqrt(hn::Add(hn::Mul(hn::Mul(n_dot_v, n_dot_v), one_minus_alpha2), alpha2)));
    const VF visibility = hn::Div(hn::Set(df, 0.5f), hn::Add(smith_l, smith_v));
    hn::Store(hn::Mul(hn::Mul(distribution, visibility), pi), df, specular_scale + i);
    hn::Store(hn::Sub(one, v_dot_h), df, one_minus_v_dot_h + i);
    hn::Store(ndl, df, n_dot_l + i);
    const MF power = hn::And(hn::And(lanes_in(df, i, begin, end), nonzero(df, reached, i)), hn::Gt(ndl, zero));
    hn::Store(hn::IfThenElseZero(hn::RebindMask(DI(), power), hn::Set(DI(), 1)), DI(), wants_power + i);
  }
  // The power only where shade_ggx raises it (reached, N.L > 0), else 0.
  SchlickPowerKernel(one_minus_v_dot_h + first, end - static_cast<int>(first), schlick + first);
  for (size_t i = first; i < static_cast<size_t>(end); i += lanes) {
    const MF power = hn::RebindMask(df, hn::Ne(hn::Load(DI(), wants_power + i), hn::Zero(DI())));
    hn::Store(hn::IfThenElseZero(power, hn::Load(df, schlick + i)), df, schlick + i);
  }
  for (size_t i = first; i < static_cast<size_t>(end); i += lanes) {
    const MF write = hn::And(lanes_in(df, i, begin, end), nonzero(df, reached, i));
    const VF ndl = hn::Load(df, n_dot_l + i), power = hn::Load(df, schlick + i);
    const VF scale = hn::Load(df, specular_scale + i);
    const MF facing = hn::Gt(ndl, zero);
    for (int c = 0; c < 3; ++c) {
      const VF f0 = hn::Load(df, b.f0[c] + i);
      const VF fresnel = hn::Add(f0, hn::Mul(hn::Sub(one, f0), power));
      const VF specular = hn::Mul(fresnel, scale);
      const VF reflected = hn::Mul(hn::Mul(hn::Load(df, radiance[c] + i), ndl),
                                   hn::Add(hn::Load(df, b.diffuse_color[c] + i), specular));
      const VF term = hn::IfThenElseZero(facing, reflected);
      const VF old = hn::Load(df, sum[c] + i);
      const VF total = accumulate ? hn::Add(old, term) : term;
      hn::Store(hn::IfThenElse(write, total, old), df, sum[c] + i);
    }
  }
}

void LightIncidenceKernel(const PunctualLight& light, const BatchVec3& surface, const int32_t* lit, int begin,
                          int end, BatchVec3& to_light, BatchVec3& radiance, int32_t* reached) {
  const DF df;
  const DI di;
  const size_t lanes = hn::Lanes(df);
  const size_t first = static_cast<size_t>(begin) - static_cast<size_t>(begin) % lanes;
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const bool directional = light.type == PunctualLight::Type::Directional;
  const bool has_range = light.range > 0.0f;
  const VF range2 = hn::Set(df, light.range * light.range);
  const bool spot = light.type == PunctualLight::Type::Spot;
  const VF px = hn::Set(df, light.position.x), py = hn::Set(df, light.position.y), pz = hn::Set(df, light.position.z);
  const VF dx = hn::Set(df, light.direction.x), dy = hn::Set(df, light.direction.y), dz = hn::Set(df, light.direction.z);
  for (size_t i = first; i < static_cast<size_t>(end); i += lanes) {
    const MF inside = lanes_in(df, i, begin, end);
    const auto lit_lanes = hn::LoadU(di, lit + i);
    VF l[3], falloff = one;
    MF reaches = hn::RebindMask(df, hn::Ne(lit_lanes, hn::Zero(di)));
    if (directional) {
      for (int c = 0; c < 3; ++c) l[c] = hn::Set(df, -light.direction[c]);
    } else {
      const VF ox = hn::Sub(px, hn::Load(df, surface[0] + i));
      const VF oy = hn::Sub(py, hn::Load(df, surface[1] + i));
      const VF oz = hn::Sub(pz, hn::Load(df, surface[2] + i));
      const VF distance_squared = hn::Add(hn::Add(hn::Mul(ox, ox), hn::Mul(oy, oy)), hn::Mul(oz, oz));
      const VF length = hn::Sqrt(at_least(distance_squared, hn::Set(df, 1e-8f)));
      l[0] = hn::Div(ox, length);
      l[1] = hn::Div(oy, length);
      l[2] = hn::Div(oz, length);
      // range_attenuation
      const VF d2 = at_least(distance_squared, hn::Set(df, 1e-4f));
      VF range_factor;
      if (!(light.range <= 0.0f)) {
        const VF ratio2 = hn::Div(d2, range2);
        const VF window_low = at_least(hn::Sub(one, hn::Mul(ratio2, ratio2)), zero);
        const VF window = hn::IfThenElse(hn::Lt(one, window_low), one, window_low);
        range_factor = hn::Div(window, d2);
      } else {
        range_factor = hn::Div(one, d2);
      }
      // spot_attenuation with light_to_surface = -to_light
      VF spot_factor = one;
      if (spot) {
        const VF cd = hn::Add(hn::Add(hn::Mul(dx, hn::Neg(l[0])), hn::Mul(dy, hn::Neg(l[1]))), hn::Mul(dz, hn::Neg(l[2])));
        const VF a_raw = hn::Add(hn::Mul(cd, hn::Set(df, light.spot_scale)), hn::Set(df, light.spot_offset));
        const VF a_low = at_least(a_raw, zero);
        const VF a = hn::IfThenElse(hn::Lt(one, a_low), one, a_low);
        spot_factor = hn::Mul(a, a);
      }
      falloff = hn::Mul(range_factor, spot_factor);
      if (has_range) reaches = hn::AndNot(hn::Ge(distance_squared, range2), reaches);
      reaches = hn::And(reaches, hn::Gt(falloff, zero));
    }
    for (int c = 0; c < 3; ++c) {
      hn::Store(hn::IfThenElse(inside, l[c], hn::Load(df, to_light[c] + i)), df, to_light[c] + i);
      const VF value = directional ? hn::Set(df, light.intensity[c]) : hn::Mul(hn::Set(df, light.intensity[c]), falloff);
      hn::Store(hn::IfThenElse(inside, value, hn::Load(df, radiance[c] + i)), df, radiance[c] + i);
    }
    const auto reached_lanes = hn::IfThenElseZero(hn::RebindMask(di, reaches), hn::Set(di, 1));
    hn::StoreU(hn::IfThenElse(hn::RebindMask(di, inside), reached_lanes, hn::LoadU(di, reached + i)), di, reached + i);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(SchlickPowerKernel);
HWY_EXPORT(ShadeGgxKernel);
HWY_EXPORT(LightIncidenceKernel);

void schlick_power_lanes(const float* x, int count, float* out) {
  HWY_DYNAMIC_DISPATCH(SchlickPowerKernel)(x, count, out);
}

void shade_ggx(const BrdfBatch& b, const BatchVec3& n, const BatchVec3& to_view, const BatchVec3& to_light,
               const BatchVec3& radiance, const int32_t* reached, int begin, int end, bool accumulate,
               BatchVec3& sum) {
  if (begin >= end) return;
  HWY_DYNAMIC_DISPATCH(ShadeGgxKernel)(b, n, to_view, to_light, radiance, reached, begin, end, accumulate, sum);
}

void light_incidence(const PunctualLight& light, const BatchVec3& surface, const int32_t* lit, int begin, int end,
                     BatchVec3& to_light, BatchVec3& radiance, int32_t* reached) {
  if (begin >= end) return;
  HWY_DYNAMIC_DISPATCH(LightIncidenceKernel)(light, surface, lit, begin, end, to_light, radiance, reached);
}

}  // namespace ontile
#endif  // HWY_ONCE
