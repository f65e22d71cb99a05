// Batched Universal Lit lighting (see universal_lit_lighting.h) on SIMD lanes, compiled per
// target by Highway's foreach_target. Each step mirrors the scalar per-fragment code in its
// evaluation order (glm's vector operators per component, glm::dot as (x + y) + z of the
// products, glm::length its square root, branches as selects), with IEEE operations only and no
// FMA, so every target gives the same bits; the lights stay in registers across a vector of
// fragments. std::pow (a material exponent) is called per shaded lane as before.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipelines/universal/universal_lit_lighting.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <bit>
#include <cmath>
#include <limits>

#include "pipelines/universal/universal_lit_functors.h"
#include "pipelines/universal/universal_lit_lighting.h"
#include "raster/lane_bits.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using VF = hn::Vec<DF>;
using MF = hn::Mask<DF>;

// The bits of a mask's lanes (lane i: bit i).
HWY_INLINE uint32_t mask_bits(DF, MF m) {
  const DI di;
  return static_cast<uint32_t>(
      hn::GetLane(hn::SumOfLanes(di, hn::IfThenElseZero(hn::RebindMask(di, m), hn::LoadU(di, kLaneBit)))));
}

struct Surface {
  VF n[3], v[3], diffuse[3], specular[3];
  // Lanes whose term is +0 whatever the power when radiance x N.L is +0 in every channel (see
  // light_adds_nothing): v finite, n.n <= 1 + 2^-20, diffuse and specular in [+0, 2^126).
  MF zero_weight_adds_zero;
};

// Whether the light's term leaves every lit lane's colour unchanged, so the vector skips it:
// a lane not facing the light adds +0 (the select), a lane whose radiance x N.L is +0 in every
// channel adds +0 x (diffuse + specular x power) = +0 when that sum is finite and not negative:
// diffuse and specular in [+0, 2^126) and the power in [0, 2) (0 where needs_power skips it). The
// power is pow(n_dot_h, shininess) with shininess in [0, 2^16] (checked by the caller) and
// n_dot_h in [0, 1 + 2^-20], so at most about (1 + 2^-20)^(2^16) < 1.07: a facing lane with a +0
// weight has N.L finite, so n and l are finite; v is checked finite, so the half vector h is
// finite; with h.h = 0 (n_dot_h = 0), infinite (h / inf = 0) or at least 2^-100 (checked: a
// normal number, so h / |h| is within a few 2^-24 of unit length; a denormal h.h could put it far
// above) and n.n <= 1 + 2^-20 (checked: tiny interpolated normals normalise through a denormal
// length too), their dot is at most 1 + 2^-20. Adding +0 changes no colour
// except -0 (to +0; a NaN stays), so those lanes must not be -0. Unlit lanes are never stored.
HWY_INLINE bool light_adds_nothing(DF df, const Surface& s, const VF weight[3], VF half_squared, MF facing,
                                   MF lit, const VF colour[3]) {
  const DI di;
  const auto zero_bits = hn::Zero(di), minus_zero_bits = hn::Set(di, static_cast<int32_t>(0x80000000u));
  auto zero_weight = hn::Eq(hn::BitCast(di, weight[0]), zero_bits);
  auto plain_colour = hn::Ne(hn::BitCast(di, colour[0]), minus_zero_bits);
  for (int c = 1; c < 3; ++c) {
    zero_weight = hn::And(zero_weight, hn::Eq(hn::BitCast(di, weight[c]), zero_bits));
    plain_colour = hn::And(plain_colour, hn::Ne(hn::BitCast(di, colour[c]), minus_zero_bits));
  }
  const MF half_ok = hn::Or(hn::Eq(half_squared, hn::Zero(df)), hn::Ge(half_squared, hn::Set(df, 0x1p-100f)));
  const MF adds_zero =
      hn::Or(hn::Not(facing), hn::And(hn::And(hn::RebindMask(df, zero_weight), s.zero_weight_adds_zero), half_ok));
  return hn::AllTrue(df, hn::Or(hn::Not(lit), hn::And(adds_zero, hn::RebindMask(df, plain_colour))));
}

// The lanes whose std::pow call can change their term; the others keep power +0. A lane whose
// radiance x N.L is +0 in every channel adds +0 x (diffuse + specular x power) = +0 whatever the
// power, as long as that sum is +0 or positive and finite for every power the lane could have:
// diffuse and specular in [+0, 2^126) (sign bit clear, so their sum cannot overflow) and the
// power in [0, 1], which pow(n_dot_h, shininess) is for n_dot_h in [0, 1] (never below 0 here;
// NaN fails the test) and shininess = exp2(...) >= 0 or +inf (a NaN shininess skips nothing).
// Lights out of range and shadowed fragments are such lanes.
HWY_INLINE MF needs_power(DF df, const Surface& s, const VF weight[3], VF n_dot_h, float shininess) {
  if (std::isnan(shininess)) return hn::FirstN(df, hn::Lanes(df));
  const DI di;
  const auto below_2_126 = hn::Set(di, 0x7E800000);  // bits of 2^126; negative floats compare below 0
  const auto zero_bits = hn::Zero(di), minus_one = hn::Set(di, -1);
  MF unlit = hn::Le(n_dot_h, hn::Set(df, 1.0f));
  for (int c = 0; c < 3; ++c) {
    const auto weight_bits = hn::BitCast(di, weight[c]);
    const auto diffuse = hn::BitCast(di, s.diffuse[c]), specular = hn::BitCast(di, s.specular[c]);
    const auto ok = hn::And(hn::And(hn::Eq(weight_bits, zero_bits), hn::And(hn::Gt(diffuse, minus_one), hn::Lt(diffuse, below_2_126))),
                            hn::And(hn::Gt(specular, minus_one), hn::Lt(specular, below_2_126)));
    unlit = hn::And(unlit, hn::RebindMask(df, ok));
  }
  return hn::Not(unlit);
}

// rgb += blinn_phong(...) for one vector of fragments; `lit`: the fragments that may be shaded
// (the others add the term with a power of 0, as the scalar loop).
HWY_INLINE void add_blinn_phong(DF df, const Surface& s, const VF l[3], const VF radiance[3], float shininess,
                                bool may_skip, MF lit, VF rgb[3]) {
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const VF n_dot_l = hn::Add(hn::Add(hn::Mul(s.n[0], l[0]), hn::Mul(s.n[1], l[1])), hn::Mul(s.n[2], l[2]));
  const MF facing = hn::Gt(n_dot_l, zero);
  VF weight[3];  // radiance x N.L, the term's first product
  for (int c = 0; c < 3; ++c) weight[c] = hn::Mul(radiance[c], n_dot_l);
  const VF hx = hn::Add(l[0], s.v[0]), hy = hn::Add(l[1], s.v[1]), hz = hn::Add(l[2], s.v[2]);
  const VF half_squared = hn::Add(hn::Add(hn::Mul(hx, hx), hn::Mul(hy, hy)), hn::Mul(hz, hz));
  if (may_skip && light_adds_nothing(df, s, weight, half_squared, facing, lit, rgb)) return;
  const VF half_length = hn::Sqrt(half_squared);
  const MF has_length = hn::Gt(half_length, zero);
  const VF divisor = hn::IfThenElse(has_length, half_length, one);
  const VF d = hn::Add(hn::Add(hn::Mul(s.n[0], hn::Div(hx, divisor)), hn::Mul(s.n[1], hn::Div(hy, divisor))),
                       hn::Mul(s.n[2], hn::Div(hz, divisor)));
  const VF n_dot_h = hn::IfThenElseZero(has_length, hn::IfThenElse(hn::Lt(d, zero), zero, d));
  VF power = zero;
  const uint32_t shaded = mask_bits(df, hn::And(hn::And(lit, facing), needs_power(df, s, weight, n_dot_h, shininess)));
  if (shaded != 0) {
    alignas(64) float base[HWY_MAX_BYTES / sizeof(float)], raised[HWY_MAX_BYTES / sizeof(float)] = {};
    hn::Store(n_dot_h, df, base);
    for (uint32_t rest = shaded; rest != 0; rest &= rest - 1) {
      const int lane = std::countr_zero(rest);
      raised[lane] = std::pow(base[lane], shininess);
    }
    power = hn::Load(df, raised);
  }
  for (int c = 0; c < 3; ++c) {
    const VF term = hn::Mul(weight[c], hn::Add(s.diffuse[c], hn::Mul(s.specular[c], power)));
    rgb[c] = hn::Add(rgb[c], hn::IfThenElseZero(facing, term));
  }
}

// An additional light's to_light and radiance for one vector of fragments at world positions p
// (the scalar loop's preamble: range_attenuation x spot_attenuation, light_to_surface = -l).
HWY_INLINE void additional_light(DF df, const AdditionalLight& light, const VF p[3], const VF normal[3], VF l[3],
                                 VF radiance[3]) {
  if (light.type == AdditionalLight::Type::Directional) {
    for (int c = 0; c < 3; ++c) {
      l[c] = hn::Set(df, -light.direction[c]);
      radiance[c] = hn::Set(df, light.intensity[c]);
    }
    return;
  }
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  VF o[3];
  for (int c = 0; c < 3; ++c) o[c] = hn::Sub(hn::Set(df, light.position[c]), p[c]);
  const VF distance_squared = hn::Add(hn::Add(hn::Mul(o[0], o[0]), hn::Mul(o[1], o[1])), hn::Mul(o[2], o[2]));
  const MF has_length = hn::Gt(distance_squared, zero);
  const VF length = hn::Sqrt(hn::IfThenElse(has_length, distance_squared, one));
  for (int c = 0; c < 3; ++c) l[c] = hn::IfThenElse(has_length, hn::Div(o[c], length), normal[c]);
  const VF d2 = hn::IfThenElse(hn::Lt(distance_squared, hn::Set(df, 1e-4f)), hn::Set(df, 1e-4f), distance_squared);
  VF range_factor;
  if (light.range <= 0.0f) {
    range_factor = hn::Div(one, d2);
  } else {
    const VF ratio2 = hn::Div(d2, hn::Set(df, light.range * light.range));
    const VF window_raw = hn::Sub(one, hn::Mul(ratio2, ratio2));
    const VF window_low = hn::IfThenElse(hn::Lt(window_raw, zero), zero, window_raw);
    const VF window = hn::IfThenElse(hn::Lt(one, window_low), one, window_low);
    range_factor = hn::Div(window, d2);
  }
  VF spot_factor = one;
  if (light.type == AdditionalLight::Type::Spot) {
    const VF cd = hn::Add(hn::Add(hn::Mul(hn::Set(df, light.direction.x), hn::Neg(l[0])),
                                  hn::Mul(hn::Set(df, light.direction.y), hn::Neg(l[1]))),
                          hn::Mul(hn::Set(df, light.direction.z), hn::Neg(l[2])));
    const VF a_raw = hn::Add(hn::Mul(cd, hn::Set(df, light.spot_scale)), hn::Set(df, light.spot_offset));
    const VF a_low = hn::IfThenElse(hn::Lt(a_raw, zero), zero, a_raw);
    const VF a = hn::IfThenElse(hn::Lt(one, a_low), one, a_low);
    spot_factor = hn::Mul(a, a);
  }
  const VF falloff = hn::Mul(range_factor, spot_factor);
  for (int c = 0; c < 3; ++c) radiance[c] = hn::Mul(hn::Set(df, light.intensity[c]), falloff);
}

void UniversalLitLightingKernel(const UniversalLitParams& p, const FragmentBatch& batch,
                                const float (&normal)[3][kBatchFragments], const float (&albedo)[4][kBatchFragments],
                                const float* visibility, uint64_t lit, int count, float (&rgb)[3][kBatchFragments]) {
  const DF df;
  const DI di;
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const float* position[3] = {batch.varyings[MeshVertexShader::kWorldPos],
                              batch.varyings[MeshVertexShader::kWorldPos + 1],
                              batch.varyings[MeshVertexShader::kWorldPos + 2]};
  // diffuse = base x (1 - metallic); specular = glm::mix(vec3(0.04), base, metallic) =
  // 0.04 x (1 - metallic) + base x metallic; rgb = ambient x (diffuse + specular).
  const VF dielectric = hn::Set(df, 1.0f - p.metallic);
  const VF specular_floor = hn::Set(df, 0.04f * (1.0f - p.metallic));
  const VF metallic = hn::Set(df, p.metallic);
  const float shininess = std::exp2(10.0f * p.smoothness + 1.0f);
  const bool may_skip = shininess >= 0.0f && shininess <= 65536.0f;  // [0, 2^16]: light_adds_nothing
  const auto below_2_126 = hn::Set(di, 0x7E800000);  // bits of 2^126; negative floats compare below 0
  const auto minus_one = hn::Set(di, -1);
  const VF infinity = hn::Set(df, std::numeric_limits<float>::infinity());
  const VF unit_bound = hn::Set(df, 1.0f + 0x1p-20f);
  for (size_t f = 0; f < static_cast<size_t>(count); f += hn::Lanes(df)) {
    const MF on = hn::RebindMask(
        df, hn::Ne(hn::And(hn::Set(di, static_cast<int32_t>((lit >> f) & 0xFFFFu)), hn::LoadU(di, kLaneBit)),
                   hn::Zero(di)));
    Surface s;
    VF world[3];
    for (int c = 0; c < 3; ++c) {
      s.n[c] = hn::Load(df, normal[c] + f);
      world[c] = hn::Load(df, position[c] + f);
    }
    VF t[3];
    for (int c = 0; c < 3; ++c) t[c] = hn::Sub(hn::Set(df, p.camera_position[c]), world[c]);
    const VF camera_distance = hn::Sqrt(hn::Add(hn::Add(hn::Mul(t[0], t[0]), hn::Mul(t[1], t[1])), hn::Mul(t[2], t[2])));
    const MF has_distance = hn::Gt(camera_distance, zero);
    const VF divisor = hn::IfThenElse(has_distance, camera_distance, one);
    VF colour[3];
    for (int c = 0; c < 3; ++c) {
      s.v[c] = hn::IfThenElse(has_distance, hn::Div(t[c], divisor), s.n[c]);
      const VF base = hn::Load(df, albedo[c] + f);
      s.diffuse[c] = hn::Mul(base, dielectric);
      s.specular[c] = hn::Add(specular_floor, hn::Mul(base, metallic));
      colour[c] = hn::Mul(hn::Set(df, p.ambient[c]), hn::Add(s.diffuse[c], s.specular[c]));
    }
    MF bounded = hn::Le(hn::Add(hn::Add(hn::Mul(s.n[0], s.n[0]), hn::Mul(s.n[1], s.n[1])), hn::Mul(s.n[2], s.n[2])),
                        unit_bound);
    for (int c = 0; c < 3; ++c) bounded = hn::And(bounded, hn::Lt(hn::Abs(s.v[c]), infinity));
    auto in_range = hn::RebindMask(di, bounded);
    for (int c = 0; c < 3; ++c) {
      const auto diffuse = hn::BitCast(di, s.diffuse[c]), specular = hn::BitCast(di, s.specular[c]);
      in_range = hn::And(in_range, hn::And(hn::And(hn::Gt(diffuse, minus_one), hn::Lt(diffuse, below_2_126)),
                                           hn::And(hn::Gt(specular, minus_one), hn::Lt(specular, below_2_126))));
    }
    s.zero_weight_adds_zero = hn::RebindMask(df, in_range);
    VF l[3], radiance[3];
    for (int c = 0; c < 3; ++c) {
      l[c] = hn::Set(df, p.main_light.to_light[c]);
      const VF r = hn::Set(df, p.main_light.radiance[c]);
      radiance[c] = visibility ? hn::Mul(r, hn::LoadU(df, visibility + f)) : r;
    }
    add_blinn_phong(df, s, l, radiance, shininess, may_skip, on, colour);
    for (int i = 0; i < p.additional_light_count; ++i) {
      additional_light(df, p.additional_lights[i], world, s.n, l, radiance);
      add_blinn_phong(df, s, l, radiance, shininess, may_skip, on, colour);
    }
    for (int c = 0; c < 3; ++c) hn::Store(colour[c], df, rgb[c] + f);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(UniversalLitLightingKernel);

void universal_lit_lighting(const UniversalLitParams& p, const FragmentBatch& batch,
                            const float (&normal)[3][kBatchFragments], const float (&albedo)[4][kBatchFragments],
                            const float* visibility, uint64_t lit, int count, float (&rgb)[3][kBatchFragments]) {
  HWY_DYNAMIC_DISPATCH(UniversalLitLightingKernel)(p, batch, normal, albedo, visibility, lit, count, rgb);
}

}  // namespace ontile
#endif  // HWY_ONCE
