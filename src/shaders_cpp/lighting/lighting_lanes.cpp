// direct_lighting (scene_lighting.h) on SIMD lanes, compiled per target by Highway's
// foreach_target: the per-fragment shade_ggx (brdf.h) and light_incidence (punctual_light.h)
// with their IEEE multiply, add, subtract, divide, square root and compares in their order (no
// FMA), so every target gives their bits; each light's incidence, GGX and Schlick power stay in
// registers.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/lighting/lighting_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <bit>
#include <cmath>

#include "raster/lane_bits.h"
#include "raster/lane_bits-inl.h"
#include "shaders_cpp/lighting/brdf.h"
#include "shaders_cpp/lighting/punctual_light.h"
#include "shaders_cpp/lighting/scene_lighting.h"
#include "shaders_cpp/lighting/schlick_power.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using VF = hn::Vec<DF>;
using MF = hn::Mask<DF>;

// Lanes i.. whose bit is set in `bits`.
HWY_INLINE MF lanes_of(DF df, uint64_t bits, size_t i) {
  const DI di;
  const auto word = hn::Set(di, static_cast<int32_t>((bits >> i) & 0xFFFFu));
  return hn::RebindMask(df, hn::Ne(hn::And(word, hn::LoadU(di, kLaneBit)), hn::Zero(di)));
}

// Lanes i.. of [begin, end).
HWY_INLINE MF lanes_in(DF df, size_t i, int begin, int end) {
  const DI di;
  const auto index = hn::Add(hn::Iota(di, 0), hn::Set(di, static_cast<int32_t>(i)));
  return hn::RebindMask(df, hn::And(hn::Gt(index, hn::Set(di, begin - 1)), hn::Lt(index, hn::Set(di, end))));
}

// a < bound ? bound : a, as std::max(a, bound) (NaN a stays NaN).
HWY_INLINE VF at_least(VF a, VF bound) { return hn::IfThenElse(hn::Lt(a, bound), bound, a); }
// bound < a ? bound : a, as std::min(a, bound) with the bound first (std::clamp's upper test).
HWY_INLINE VF at_most(VF a, VF bound) { return hn::IfThenElse(hn::Lt(bound, a), bound, a); }

// out[i] = schlick_power(x[i]) for i < count (at most 64); std::pow only where
// schlick_power_is_exact fails and the lane's bit is set in `wanted` (other lanes' results are
// never used).
// Inlined into ggx_terms, where it runs per light and vector of fragments: its constants are
// then hoisted and no call is made.
HWY_INLINE void power_lanes(const float* x, int count, uint64_t wanted, float* out) {
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> dh;  // half-width floats, one per double lane
  const hn::RebindToUnsigned<decltype(dd)> du;
  const size_t n = hn::Lanes(dd);
  const auto dropped_mask = hn::Set(du, (uint64_t{1} << kSchlickDroppedBits) - 1);
  const auto window_start = hn::Set(du, (uint64_t{1} << (kSchlickDroppedBits - 1)) - kSchlickTieWindow);
  const auto window = hn::Set(du, 2 * kSchlickTieWindow);
  const auto smallest = hn::Set(dd, kSchlickSmallestNormal), largest = hn::Set(dd, kSchlickLargest);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto xd = hn::PromoteTo(dd, hn::LoadU(dh, x + i));
    const auto x2 = hn::Mul(xd, xd);
    const auto r = hn::Mul(hn::Mul(x2, x2), xd);
    hn::StoreU(hn::DemoteTo(dh, r), dh, out + i);
    // Lanes near a tie of the float rounding, or outside the normal floats: std::pow itself.
    const auto near_tie = hn::Lt(hn::Sub(hn::And(hn::BitCast(du, r), dropped_mask), window_start), window);
    const auto magnitude = hn::Abs(r);
    const auto normal = hn::Or(hn::Eq(r, hn::Zero(dd)), hn::And(hn::Ge(magnitude, smallest), hn::Lt(magnitude, largest)));
    const auto scalar = hn::Or(hn::RebindMask(dd, near_tie), hn::Not(normal));
    if (hn::AllFalse(dd, scalar)) continue;
    for (size_t lane = 0; lane < n; ++lane) {
      if (((wanted >> (i + lane)) & 1u) && !schlick_power_is_exact(static_cast<double>(x[i + lane]))) {
        out[i + lane] = std::pow(x[i + lane], 5.0f);
      }
    }
  }
  for (; i < static_cast<size_t>(count); ++i) out[i] = schlick_power(x[i]);
}

void SchlickPowerKernel(const float* x, int count, float* out) {
  for (int i = 0; i < count; i += 64) power_lanes(x + i, count - i < 64 ? count - i : 64, ~uint64_t{0}, out + i);
}

// One vector of fragments' surface, as shade_ggx reads it.
struct SurfaceVec {
  VF n[3], v[3];
  VF n_dot_v;  // max(N.V, 1e-4)
};

HWY_INLINE SurfaceVec load_surface(DF df, const BatchVec3& n, const BatchVec3& to_view, size_t i) {
  SurfaceVec s;
  for (int c = 0; c < 3; ++c) {
    s.n[c] = hn::Load(df, n[c] + i);
    s.v[c] = hn::Load(df, to_view[c] + i);
  }
  s.n_dot_v = at_least(hn::Add(hn::Add(hn::Mul(s.n[0], s.v[0]), hn::Mul(s.n[1], s.v[1])), hn::Mul(s.n[2], s.v[2])),
                       hn::Set(df, 1e-4f));
  return s;
}

// shade_ggx's terms for one vector of fragments i.. lit by (l, radiance) where `reached`
// (others: anything), term[c] = N.L > 0 ? radiance N.L (diffuse + specular) : 0.
HWY_INLINE void ggx_terms(DF df, const BrdfBatch& b, const SurfaceVec& s, const VF l[3], const VF radiance[3],
                          MF reached, size_t i, VF term[3]) {
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), pi = hn::Set(df, 3.14159265f);
  const VF ndl = hn::Add(hn::Add(hn::Mul(s.n[0], l[0]), hn::Mul(s.n[1], l[1])), hn::Mul(s.n[2], l[2]));
  const VF hx = hn::Add(l[0], s.v[0]), hy = hn::Add(l[1], s.v[1]), hz = hn::Add(l[2], s.v[2]);
  const VF half_length = hn::Sqrt(hn::Add(hn::Add(hn::Mul(hx, hx), hn::Mul(hy, hy)), hn::Mul(hz, hz)));
  const MF has_half = hn::Gt(half_length, zero);
  const VF divisor = hn::IfThenElse(has_half, half_length, one);
  const VF ux = hn::IfThenElse(has_half, hn::Div(hx, divisor), s.n[0]);
  const VF uy = hn::IfThenElse(has_half, hn::Div(hy, divisor), s.n[1]);
  const VF uz = hn::IfThenElse(has_half, hn::Div(hz, divisor), s.n[2]);
  const VF n_dot_h = at_least(hn::Add(hn::Add(hn::Mul(s.n[0], ux), hn::Mul(s.n[1], uy)), hn::Mul(s.n[2], uz)), zero);
  const VF v_dot_h = at_least(hn::Add(hn::Add(hn::Mul(s.v[0], ux), hn::Mul(s.v[1], uy)), hn::Mul(s.v[2], uz)), zero);
  const VF r = at_least(hn::Load(df, b.roughness + i), hn::Set(df, kMinPerceptualRoughness));
  const VF r2 = hn::Mul(r, r);
  const VF alpha2 = hn::Mul(r2, r2);
  const VF d_denominator = hn::Add(hn::Mul(hn::Mul(n_dot_h, n_dot_h), hn::Sub(alpha2, one)), one);
  const VF distribution = hn::Div(alpha2, hn::Mul(hn::Mul(pi, d_denominator), d_denominator));
  const VF one_minus_alpha2 = hn::Sub(one, alpha2);
  const VF smith_l = hn::Mul(s.n_dot_v, hn::Sqrt(hn::Add(hn::Mul(hn::Mul(ndl, ndl), one_minus_alpha2), alpha2)));
  const VF smith_v = hn::Mul(ndl, hn::Sqrt(hn::Add(hn::Mul(hn::Mul(s.n_dot_v, s.n_dot_v), one_minus_alpha2), alpha2)));
  const VF visibility = hn::Div(hn::Set(df, 0.5f), hn::Add(smith_l, smith_v));
  const VF specular_scale = hn::Mul(hn::Mul(distribution, visibility), pi);
  // The Schlick power where shade_ggx raises it (reached, N.L > 0), else 0.
  const MF facing = hn::Gt(ndl, zero);
  const MF wanted = hn::And(reached, facing);
  VF power = zero;
  if (!hn::AllFalse(df, wanted)) {
    alignas(64) float base[HWY_MAX_BYTES / sizeof(float)], raised[HWY_MAX_BYTES / sizeof(float)];
    hn::Store(hn::Sub(one, v_dot_h), df, base);
    power_lanes(base, static_cast<int>(hn::Lanes(df)), mask_bits(df, wanted), raised);
    power = hn::IfThenElseZero(wanted, hn::Load(df, raised));
  }
  for (int c = 0; c < 3; ++c) {
    const VF f0 = hn::Load(df, b.f0[c] + i);
    const VF fresnel = hn::Add(f0, hn::Mul(hn::Sub(one, f0), power));
    const VF specular = hn::Mul(fresnel, specular_scale);
    const VF reflected = hn::Mul(hn::Mul(radiance[c], ndl), hn::Add(hn::Load(df, b.diffuse_color[c] + i), specular));
    term[c] = hn::IfThenElseZero(facing, reflected);
  }
}

// light_incidence for one vector of fragments i.. at `surface`: l, radiance, and which lanes
// the light reaches (of those in `lit`).
HWY_INLINE MF incidence(DF df, const PunctualLight& light, const BatchVec3& surface, size_t i, MF lit, VF l[3],
                        VF radiance[3]) {
  if (light.type == PunctualLight::Type::Directional) {
    for (int c = 0; c < 3; ++c) {
      l[c] = hn::Set(df, -light.direction[c]);
      radiance[c] = hn::Set(df, light.intensity[c]);
    }
    return lit;
  }
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  VF offset[3];
  for (int c = 0; c < 3; ++c) offset[c] = hn::Sub(hn::Set(df, light.position[c]), hn::Load(df, surface[c] + i));
  const VF distance_squared =
      hn::Add(hn::Add(hn::Mul(offset[0], offset[0]), hn::Mul(offset[1], offset[1])), hn::Mul(offset[2], offset[2]));
  const VF length = hn::Sqrt(at_least(distance_squared, hn::Set(df, 1e-8f)));
  for (int c = 0; c < 3; ++c) l[c] = hn::Div(offset[c], length);
  // range_attenuation
  const VF d2 = at_least(distance_squared, hn::Set(df, 1e-4f));
  const VF range2 = hn::Set(df, light.range * light.range);
  VF falloff;
  if (light.range <= 0.0f) {
    falloff = hn::Div(one, d2);
  } else {
    const VF ratio2 = hn::Div(d2, range2);
    const VF window = at_most(at_least(hn::Sub(one, hn::Mul(ratio2, ratio2)), zero), one);
    falloff = hn::Div(window, d2);
  }
  // spot_attenuation with light_to_surface = -to_light
  if (light.type == PunctualLight::Type::Spot) {
    const VF cd = hn::Add(hn::Add(hn::Mul(hn::Set(df, light.direction.x), hn::Neg(l[0])),
                                  hn::Mul(hn::Set(df, light.direction.y), hn::Neg(l[1]))),
                          hn::Mul(hn::Set(df, light.direction.z), hn::Neg(l[2])));
    const VF a_raw = hn::Add(hn::Mul(cd, hn::Set(df, light.spot_scale)), hn::Set(df, light.spot_offset));
    const VF a = at_most(at_least(a_raw, zero), one);
    falloff = hn::Mul(falloff, hn::Mul(a, a));
  } else {
    falloff = hn::Mul(falloff, one);
  }
  for (int c = 0; c < 3; ++c) radiance[c] = hn::Mul(hn::Set(df, light.intensity[c]), falloff);
  MF reaches = hn::And(lit, hn::Gt(falloff, zero));
  if (light.range > 0.0f) reaches = hn::AndNot(hn::Ge(distance_squared, range2), reaches);
  return reaches;
}

// direct_lighting (scene_lighting.h) over fragments [0, count) whose cells are `cell`: the sun,
// then per run of one cell its lights in order, each fragment's sum in the scalar order.
void DirectLightingKernel(const SceneLighting& lighting, const BrdfBatch& b, const BatchVec3& n,
                          const BatchVec3& world, const BatchVec3& to_view, const int32_t* cell, int count,
                          uint64_t lit, BatchVec3& sum) {
  const DF df;
  const size_t lanes = hn::Lanes(df);
  VF sun_l[3], sun_radiance[3];
  for (int c = 0; c < 3; ++c) {
    sun_l[c] = hn::Set(df, lighting.sun_to_light[c]);
    sun_radiance[c] = hn::Set(df, lighting.sun_radiance[c]);
  }
  for (size_t i = 0; i < static_cast<size_t>(count); i += lanes) {
    const MF on = lanes_of(df, lit, i);
    const SurfaceVec s = load_surface(df, n, to_view, i);
    VF term[3];
    ggx_terms(df, b, s, sun_l, sun_radiance, on, i, term);
    for (int c = 0; c < 3; ++c) hn::Store(hn::IfThenElse(on, term[c], hn::Load(df, sum[c] + i)), df, sum[c] + i);
  }
  int begin = 0;
  while (begin < count) {
    int end = begin + 1;
    while (end < count && cell[end] == cell[begin]) ++end;
    const std::span<const uint32_t> lights = lighting.grid.lights_in(cell[begin]);
    if (!lights.empty()) {
      for (size_t i = static_cast<size_t>(begin) - static_cast<size_t>(begin) % lanes; i < static_cast<size_t>(end);
           i += lanes) {
        const MF on = hn::And(lanes_in(df, i, begin, end), lanes_of(df, lit, i));
        if (hn::AllFalse(df, on)) continue;
        const SurfaceVec s = load_surface(df, n, to_view, i);
        VF total[3];
        for (int c = 0; c < 3; ++c) total[c] = hn::Load(df, sum[c] + i);
        for (const uint32_t index : lights) {
          VF l[3], radiance[3], term[3];
          const MF reached = incidence(df, lighting.lights[index], world, i, on, l, radiance);
          ggx_terms(df, b, s, l, radiance, reached, i, term);
          for (int c = 0; c < 3; ++c) total[c] = hn::IfThenElse(reached, hn::Add(total[c], term[c]), total[c]);
        }
        for (int c = 0; c < 3; ++c) hn::Store(total[c], df, sum[c] + i);
      }
    }
    begin = end;
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(SchlickPowerKernel);
HWY_EXPORT(DirectLightingKernel);

void schlick_power_lanes(const float* x, int count, float* out) {
  HWY_DYNAMIC_DISPATCH(SchlickPowerKernel)(x, count, out);
}

void direct_lighting_lanes(const SceneLighting& lighting, const BrdfBatch& brdf, const BatchVec3& n,
                           const BatchVec3& world_position, const BatchVec3& to_view, const int32_t* cell, int count,
                           uint64_t lit, BatchVec3& sum) {
  HWY_DYNAMIC_DISPATCH(DirectLightingKernel)(lighting, brdf, n, world_position, to_view, cell, count, lit, sum);
}

}  // namespace ontile
#endif  // HWY_ONCE
