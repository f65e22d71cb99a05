// decode_gbuffer_lanes (gbuffer_decode_lanes.h), compiled per SIMD target by Highway's
// foreach_target: IEEE multiply, add, subtract, divide and square root only, in the order of
// decode_gbuffer (glm's vector operators, glm::mix as x * (1 - a) + y * a) and of
// ViewReconstruction (glm's mat4 * vec4 as (m0 x + m1 y) + (m2 z + m3 w), normalize as
// v * (1 / sqrt(dot(v, v)))), so every target gives the scalar bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/deferred/gbuffer_decode_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/lane_bits-inl.h"

#include <cstring>

#include "shaders_cpp/deferred/gbuffer_decode_lanes.h"
#include "raster/lane_bits.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// World positions and view directions of fragments [0, count) on double lanes, rounded to float
// (lit or not: decode masks them).
void reconstruct_positions(const ViewReconstruction& view, const GBufferLanes& in, int count, BatchVec3& world,
                           BatchVec3& to_view) {
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const hn::Rebind<int32_t, decltype(dd)> di;
  const size_t n = hn::Lanes(dd);
  const auto one = hn::Set(dd, 1.0), two = hn::Set(dd, 2.0), half = hn::Set(dd, 0.5);
  const auto width = hn::Set(dd, static_cast<double>(view.width_px));
  const auto height = hn::Set(dd, static_cast<double>(view.height_px));
  const glm::dmat4& m = view.inverse_view_projection;
  for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
    const auto x = hn::PromoteTo(dd, hn::LoadU(di, in.x_px + f));
    const auto y = hn::PromoteTo(dd, hn::LoadU(di, in.y_px + f));
    const auto ndc_x = hn::Sub(hn::Mul(hn::Div(hn::Add(x, half), width), two), one);
    const auto ndc_y = hn::Sub(one, hn::Mul(hn::Div(hn::Add(y, half), height), two));
    const auto ndc_z = hn::PromoteTo(dd, hn::LoadU(df, in.depth + f));
    hn::Vec<decltype(dd)> w[4];
    for (int r = 0; r < 4; ++r) {
      const auto first = hn::Add(hn::Mul(hn::Set(dd, m[0][r]), ndc_x), hn::Mul(hn::Set(dd, m[1][r]), ndc_y));
      const auto second = hn::Add(hn::Mul(hn::Set(dd, m[2][r]), ndc_z), hn::Mul(hn::Set(dd, m[3][r]), one));
      w[r] = hn::Add(first, second);
    }
    hn::Vec<decltype(dd)> offset[3];
    for (int c = 0; c < 3; ++c) {
      const auto position = hn::Div(w[c], w[3]);
      hn::StoreU(hn::DemoteTo(df, position), df, world[c] + f);
      offset[c] = hn::Sub(hn::Set(dd, view.camera_position[c]), position);
    }
    const auto length2 = hn::Add(hn::Add(hn::Mul(offset[0], offset[0]), hn::Mul(offset[1], offset[1])),
                                 hn::Mul(offset[2], offset[2]));
    const auto inverse_length = hn::Div(one, hn::Sqrt(length2));
    for (int c = 0; c < 3; ++c) hn::StoreU(hn::DemoteTo(df, hn::Mul(offset[c], inverse_length)), df, to_view[c] + f);
  }
}

void DecodeGBufferKernel(const GBufferLayout& layout, const ViewReconstruction& view, const GBufferLanes& in,
                         int count, BrdfBatch& brdf, BatchVec3& normal, BatchVec3& world, BatchVec3& to_view) {
  reconstruct_positions(view, in, count, world, to_view);
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  using VF = hn::Vec<decltype(df)>;
  const size_t n = hn::Lanes(df);
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), two = hn::Set(df, 2.0f);
  const bool signed_normal = gbuffer_detail::is_float_format(layout.normal_format);
  const int normal_target = layout.has_specular ? 2 : 1;
  for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
    const auto bits = hn::Set(di, static_cast<int32_t>((in.lit >> f) & 0xFFFFu));
    const auto lit = hn::RebindMask(df, hn::Ne(hn::And(bits, hn::LoadU(di, kLaneBit)), hn::Zero(di)));
    const auto t = [&](int target, int c) { return hn::Load(df, in.targets[target][c] + f); };
    VF diffuse[3], f0[3], roughness;
    if (layout.has_specular) {
      for (int c = 0; c < 3; ++c) {
        diffuse[c] = t(0, c);
        f0[c] = t(1, c);
      }
      roughness = hn::Sub(one, t(1, 3));
    } else {
      // metallic_roughness_brdf(base = t0.rgb, metallic = t1.a, roughness = t0.a).
      const VF metallic = t(1, 3), one_minus_metallic = hn::Sub(one, metallic);
      for (int c = 0; c < 3; ++c) {
        diffuse[c] = hn::Mul(t(0, c), one_minus_metallic);
        f0[c] = hn::Add(hn::Mul(hn::Set(df, 0.04f), one_minus_metallic), hn::Mul(t(0, c), metallic));
      }
      roughness = t(0, 3);
    }
    // gbuffer_detail::decode_normal
    VF stored[3];
    for (int c = 0; c < 3; ++c) {
      stored[c] = signed_normal ? t(normal_target, c) : hn::Sub(hn::Mul(t(normal_target, c), two), one);
    }
    const VF length = hn::Sqrt(hn::Add(hn::Add(hn::Mul(stored[0], stored[0]), hn::Mul(stored[1], stored[1])),
                                       hn::Mul(stored[2], stored[2])));
    const auto unit = hn::Gt(length, zero);
    const VF fallback[3] = {zero, zero, one};
    for (int c = 0; c < 3; ++c) {
      const VF value = hn::IfThenElse(unit, hn::Div(stored[c], length), fallback[c]);
      hn::Store(hn::IfThenElseZero(lit, value), df, normal[c] + f);
      hn::Store(hn::IfThenElseZero(lit, diffuse[c]), df, brdf.diffuse_color[c] + f);
      hn::Store(hn::IfThenElseZero(lit, f0[c]), df, brdf.f0[c] + f);
      hn::Store(hn::IfThenElseZero(lit, hn::Load(df, world[c] + f)), df, world[c] + f);
      hn::Store(hn::IfThenElseZero(lit, hn::Load(df, to_view[c] + f)), df, to_view[c] + f);
    }
    hn::Store(hn::IfThenElseZero(lit, roughness), df, brdf.roughness + f);
  }
}

uint64_t InFrontOfFarPlaneKernel(const float* depth, int count) {
  const hn::ScalableTag<float> df;
  const size_t n = hn::Lanes(df);
  const auto one = hn::Set(df, 1.0f);
  uint64_t near = 0;
  size_t f = 0;
  for (; f + n <= static_cast<size_t>(count); f += n) {
    near |= mask_bits(df, hn::Lt(hn::LoadU(df, depth + f), one)) << f;
  }
  for (; f < static_cast<size_t>(count); ++f) near |= uint64_t{depth[f] < 1.0f} << f;
  return near;
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(DecodeGBufferKernel);
HWY_EXPORT(InFrontOfFarPlaneKernel);

uint64_t in_front_of_far_plane(const float* depth, int count) {
  return HWY_DYNAMIC_DISPATCH(InFrontOfFarPlaneKernel)(depth, count);
}

void decode_gbuffer_lanes(const GBufferLayout& layout, const ViewReconstruction& view, const GBufferLanes& in,
                          int count, BrdfBatch& brdf, BatchVec3& normal, BatchVec3& world, BatchVec3& to_view) {
  HWY_DYNAMIC_DISPATCH(DecodeGBufferKernel)(layout, view, in, count, brdf, normal, world, to_view);
}

}  // namespace ontile
#endif  // HWY_ONCE
