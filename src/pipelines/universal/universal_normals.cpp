// Normals of the Universal functors on SIMD lanes (see universal_normals.h), compiled per target
// by Highway's foreach_target: IEEE multiply, add, divide, square root and compare only, in the
// scalar code's order, so every target gives its bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipelines/universal/universal_normals.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "pipelines/universal/universal_normals.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using VF = hn::Vec<DF>;

// (x, y, z) / glm::length((x, y, z)), or (0, 0, 1) where the length is not above 0 (zero, NaN):
// length sqrt((x x + y y) + z z), each component divided by it (by 1 where it is not used).
HWY_INLINE void unit_lanes(DF df, VF& x, VF& y, VF& z) {
  const VF len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(x, x), hn::Mul(y, y)), hn::Mul(z, z)));
  const auto has_length = hn::Lt(hn::Zero(df), len);
  const VF divisor = hn::IfThenElse(has_length, len, hn::Set(df, 1.0f));
  x = hn::IfThenElseZero(has_length, hn::Div(x, divisor));
  y = hn::IfThenElseZero(has_length, hn::Div(y, divisor));
  z = hn::IfThenElse(has_length, hn::Div(z, divisor), hn::Set(df, 1.0f));
}

// batch_unit_normals at fragment f: unit length, times the facing sign (x * -1 is exactly -x).
HWY_INLINE void unit_normal_at(DF df, const FragmentBatch& batch, int first, size_t f, VF& x, VF& y, VF& z) {
  x = hn::Load(df, batch.varyings[first] + f);
  y = hn::Load(df, batch.varyings[first + 1] + f);
  z = hn::Load(df, batch.varyings[first + 2] + f);
  unit_lanes(df, x, y, z);
  const VF facing = hn::Set(df, batch.front_facing ? 1.0f : -1.0f);
  x = hn::Mul(x, facing);
  y = hn::Mul(y, facing);
  z = hn::Mul(z, facing);
}

void UnitNormalsKernel(const FragmentBatch& batch, int first, int n, float (&out)[3][kBatchFragments]) {
  const DF df;
  for (size_t f = 0; f < static_cast<size_t>(n); f += hn::Lanes(df)) {
    VF x, y, z;
    unit_normal_at(df, batch, first, f, x, y, z);
    hn::Store(x, df, out[0] + f);
    hn::Store(y, df, out[1] + f);
    hn::Store(z, df, out[2] + f);
  }
}

void EncodedViewNormalsKernel(const FragmentBatch& batch, int first, const glm::mat3& m, int n,
                              float (&encoded)[4][kBatchFragments]) {
  const DF df;
  const VF half = hn::Set(df, 0.5f), one = hn::Set(df, 1.0f);
  // glm's mat3 x vec3: row r is (m[0][r] x + m[1][r] y) + m[2][r] z.
  VF row[3][3];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) row[r][c] = hn::Set(df, m[c][r]);
  }
  for (size_t f = 0; f < static_cast<size_t>(n); f += hn::Lanes(df)) {
    VF wx, wy, wz;
    unit_normal_at(df, batch, first, f, wx, wy, wz);
    VF v[3];
    for (int r = 0; r < 3; ++r) {
      v[r] = hn::Add(hn::Add(hn::Mul(row[r][0], wx), hn::Mul(row[r][1], wy)), hn::Mul(row[r][2], wz));
    }
    unit_lanes(df, v[0], v[1], v[2]);
    for (int c = 0; c < 3; ++c) hn::Store(hn::Add(hn::Mul(v[c], half), half), df, encoded[c] + f);
    hn::Store(one, df, encoded[3] + f);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(UnitNormalsKernel);
HWY_EXPORT(EncodedViewNormalsKernel);

void universal_unit_normals(const FragmentBatch& batch, int first, int n, float (&out)[3][kBatchFragments]) {
  HWY_DYNAMIC_DISPATCH(UnitNormalsKernel)(batch, first, n, out);
}

void universal_encoded_view_normals(const FragmentBatch& batch, int first, const glm::mat3& world_to_view,
                                    int n, float (&encoded)[4][kBatchFragments]) {
  HWY_DYNAMIC_DISPATCH(EncodedViewNormalsKernel)(batch, first, world_to_view, n, encoded);
}

}  // namespace ontile
#endif  // HWY_ONCE
