// Interpolated normals made unit length on SIMD lanes, for the Highway kernels that need them
// (batch_unit_normals, the Universal DepthNormals encoding). foreach_target re-includes this
// file, hence the toggling guard instead of #pragma once.
#if defined(ONTILE_SHADERS_UNIT_NORMAL_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ONTILE_SHADERS_UNIT_NORMAL_LANES_INL_H_
#undef ONTILE_SHADERS_UNIT_NORMAL_LANES_INL_H_
#else
#define ONTILE_SHADERS_UNIT_NORMAL_LANES_INL_H_
#endif

#include <hwy/highway.h>

#include <cstddef>

#include "raster/shader_interface.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {

// (x, y, z) / glm::length((x, y, z)), or (0, 0, 1) where the length is not above 0 (zero, NaN):
// length sqrt((x x + y y) + z z), each component divided by it (by 1 where it is not used).
// IEEE multiply, add, divide, square root and compare only, in the scalar code's order, so every
// target gives toon_unit_normal's bits.
template <class DF>
HWY_INLINE void unit_lanes(DF df, hwy::HWY_NAMESPACE::Vec<DF>& x, hwy::HWY_NAMESPACE::Vec<DF>& y,
                           hwy::HWY_NAMESPACE::Vec<DF>& z) {
  namespace hn = hwy::HWY_NAMESPACE;
  const auto len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(x, x), hn::Mul(y, y)), hn::Mul(z, z)));
  const auto has_length = hn::Lt(hn::Zero(df), len);
  const auto divisor = hn::IfThenElse(has_length, len, hn::Set(df, 1.0f));
  x = hn::IfThenElseZero(has_length, hn::Div(x, divisor));
  y = hn::IfThenElseZero(has_length, hn::Div(y, divisor));
  z = hn::IfThenElse(has_length, hn::Div(z, divisor), hn::Set(df, 1.0f));
}

// Fragments [f, f + Lanes) of varyings [first, first + 3) made unit length and negated on back
// faces: toon_unit_normal per lane.
template <class DF>
HWY_INLINE void unit_normal_at(DF df, const FragmentBatch& batch, int first, size_t f,
                               hwy::HWY_NAMESPACE::Vec<DF>& x, hwy::HWY_NAMESPACE::Vec<DF>& y,
                               hwy::HWY_NAMESPACE::Vec<DF>& z) {
  namespace hn = hwy::HWY_NAMESPACE;
  x = hn::Load(df, batch.varyings[first] + f);
  y = hn::Load(df, batch.varyings[first + 1] + f);
  z = hn::Load(df, batch.varyings[first + 2] + f);
  unit_lanes(df, x, y, z);
  // Negated (the sign bit flipped, as toon_unit_normal's -n) rather than multiplied by -1: the
  // two differ only for NaN, whose sign x * -1 keeps, and GCC folds a multiplication by -1 into
  // a negation where clang does not, so the product gave NaN normals each compiler's sign.
  if (!batch.front_facing) {
    x = hn::Neg(x);
    y = hn::Neg(y);
    z = hn::Neg(z);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#endif  // ONTILE_SHADERS_UNIT_NORMAL_LANES_INL_H_
