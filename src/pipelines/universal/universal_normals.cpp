// Normals of the Universal functors on SIMD lanes (see universal_normals.h), compiled per target
// by Highway's foreach_target: IEEE multiply, add, divide, square root and compare only, in the
// scalar code's order, so every target gives its bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipelines/universal/universal_normals.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "pipelines/universal/universal_normals.h"
#include "shaders_cpp/unit_normal_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using VF = hn::Vec<DF>;

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

HWY_EXPORT(EncodedViewNormalsKernel);

void universal_encoded_view_normals(const FragmentBatch& batch, int first, const glm::mat3& world_to_view,
                                    int n, float (&encoded)[4][kBatchFragments]) {
  HWY_DYNAMIC_DISPATCH(EncodedViewNormalsKernel)(batch, first, world_to_view, n, encoded);
}

}  // namespace ontile
#endif  // HWY_ONCE
