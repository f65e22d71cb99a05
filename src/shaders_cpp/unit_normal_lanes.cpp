// batch_unit_normals (batch_helpers.h) on SIMD lanes, compiled per target by Highway's
// foreach_target: every target gives the bits of the per-fragment toon_unit_normal.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/unit_normal_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/unit_normal_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void UnitNormalsKernel(const FragmentBatch& batch, int first, int n, BatchVec3& out) {
  const hn::ScalableTag<float> df;
  for (size_t f = 0; f < static_cast<size_t>(n); f += hn::Lanes(df)) {
    hn::Vec<decltype(df)> x, y, z;
    unit_normal_at(df, batch, first, f, x, y, z);
    hn::Store(x, df, out[0] + f);
    hn::Store(y, df, out[1] + f);
    hn::Store(z, df, out[2] + f);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(UnitNormalsKernel);

void batch_unit_normals(const FragmentBatch& batch, int first, int n, BatchVec3& out) {
  HWY_DYNAMIC_DISPATCH(UnitNormalsKernel)(batch, first, n, out);
}

}  // namespace ontile
#endif  // HWY_ONCE
