// SIMD quad sampler (see texture_quad_simd.h), compiled per target by Highway's foreach_target.
// Only IEEE multiply, add, subtract and floor: every target gives the bits of the scalar path.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/texture_quad_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/texture_quad_simd.h"
#include "raster/texel_wrap.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

constexpr int kLanes = 4;
constexpr float kMaxExactTexelCoord = 16777216.0f;  // as texture.cpp

// Per level and lane: the top-left texel of the bilinear footprint and the weights a, b.
struct Footprints {
  int32_t i0[2][kLanes], j0[2][kLanes];
  float a[2][kLanes], b[2][kLanes];
};

// x = u * size - 0.5, i0 = floor(x), a = x - i0 (OpenGL 4.6 eq. 8.10), for one axis of one
// level. False when |u| or |x| reach 2^24 (the scalar path reduces those first).
template <class D>
bool axis(D d, const float* u, int size, int32_t* i0_out, float* a_out) {
  const hn::RebindToSigned<D> di;
  const size_t n = hn::Lanes(d);
  const auto limit = hn::Set(d, kMaxExactTexelCoord);
  for (size_t i = 0; i < kLanes; i += n) {
    const auto uu = hn::LoadU(d, u + i);
    const auto x = hn::Sub(hn::Mul(uu, hn::Set(d, static_cast<float>(size))), hn::Set(d, 0.5f));
    if (!hn::AllTrue(d, hn::And(hn::Lt(hn::Abs(uu), limit), hn::Lt(hn::Abs(x), limit)))) return false;
    const auto x_floor = hn::Floor(x);
    hn::StoreU(hn::ConvertTo(di, x_floor), di, i0_out + i);
    hn::StoreU(hn::Sub(x, x_floor), d, a_out + i);
  }
  return true;
}

bool SampleQuad8Kernel(const QuadSample8& in, glm::vec4* out) {
  const hn::CappedTag<float, kLanes> d;
  const size_t n = hn::Lanes(d);
  float u[kLanes], v[kLanes];
  for (int lane = 0; lane < kLanes; ++lane) {
    u[lane] = in.uv[lane].x;
    v[lane] = in.uv[lane].y;
  }
  Footprints fp;
  for (int l = 0; l < in.level_count; ++l) {
    const Texture2D::Level& level = *in.levels[l];
    if (!axis(d, u, level.width, fp.i0[l], fp.a[l]) || !axis(d, v, level.height, fp.j0[l], fp.b[l])) {
      return false;
    }
  }
  // Texels lane by lane, level by level, each footprint as t00, t10, t01, t11: the scalar
  // sampler's order, so the trace (and the texture-cache counts) are the same.
  alignas(16) float texel[2][4][4][kLanes];  // [level][tap][channel][lane]
  uint64_t last = in.last_granule ? *in.last_granule : 0;
  for (int lane = 0; lane < kLanes; ++lane) {
    for (int l = 0; l < in.level_count; ++l) {
      const Texture2D::Level& level = *in.levels[l];
      size_t taps[4];
      bilinear_footprint(fp.i0[l][lane], fp.j0[l][lane], level.width, level.height, in.wrap_u,
                         in.wrap_v, taps);
      for (int t = 0; t < 4; ++t) {
        if (in.trace) {
          const uint64_t granule = (level.address + taps[t] * level.memory_bytes_per_texel) >> 6;
          if (granule != last) {
            in.trace->push_back(granule);
            last = granule;
          }
        }
        const uint8_t* p = level.texels8.data() + taps[t] * 4;
        texel[l][t][0][lane] = in.rgb_decode[p[0]];
        texel[l][t][1][lane] = in.rgb_decode[p[1]];
        texel[l][t][2][lane] = in.rgb_decode[p[2]];
        texel[l][t][3][lane] = in.alpha_decode[p[3]];
      }
    }
  }
  if (in.trace) *in.last_granule = last;
  alignas(16) float result[4][kLanes];
  const auto one = hn::Set(d, 1.0f);
  for (size_t i = 0; i < kLanes; i += n) {
    for (int c = 0; c < 4; ++c) {
      hn::Vec<decltype(d)> level_value[2];
      for (int l = 0; l < in.level_count; ++l) {
        const auto a = hn::LoadU(d, fp.a[l] + i), b = hn::LoadU(d, fp.b[l] + i);
        const auto one_a = hn::Sub(one, a), one_b = hn::Sub(one, b);
        const auto top = hn::Add(hn::Mul(hn::LoadU(d, texel[l][0][c] + i), one_a),
                                 hn::Mul(hn::LoadU(d, texel[l][1][c] + i), a));
        const auto bottom = hn::Add(hn::Mul(hn::LoadU(d, texel[l][2][c] + i), one_a),
                                    hn::Mul(hn::LoadU(d, texel[l][3][c] + i), a));
        level_value[l] = hn::Add(hn::Mul(top, one_b), hn::Mul(bottom, b));
      }
      auto value = level_value[0];
      if (in.level_count == 2) {
        const auto w = hn::Set(d, in.blend);
        value = hn::Add(hn::Mul(level_value[0], hn::Sub(one, w)), hn::Mul(level_value[1], w));
      }
      hn::StoreU(value, d, result[c] + i);
    }
  }
  for (int lane = 0; lane < kLanes; ++lane) {
    out[lane] = {result[0][lane], result[1][lane], result[2][lane], result[3][lane]};
  }
  return true;
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(SampleQuad8Kernel);

bool sample_quad8_simd(const QuadSample8& in, glm::vec4 out[4]) {
  return HWY_DYNAMIC_DISPATCH(SampleQuad8Kernel)(in, out);
}

}  // namespace ontile
#endif  // HWY_ONCE
