// The bits of a SIMD mask as an integer (lane i -> bit i), for the Highway kernels compiled once
// per target (foreach_target re-includes this file, hence the toggling guard instead of #pragma
// once; Highway 1.0 has no public BitsFromMask).
#if defined(ONTILE_RASTER_LANE_BITS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ONTILE_RASTER_LANE_BITS_INL_H_
#undef ONTILE_RASTER_LANE_BITS_INL_H_
#else
#define ONTILE_RASTER_LANE_BITS_INL_H_
#endif

#include <hwy/highway.h>

#include <cstdint>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {

template <class D, class M>
HWY_INLINE uint64_t mask_bits(D d, M m) {
  uint8_t bytes[8] = {};
  hwy::HWY_NAMESPACE::StoreMaskBits(d, m, bytes);
  uint64_t bits = 0;
  std::memcpy(&bits, bytes, sizeof(bits));
  const size_t n = hwy::HWY_NAMESPACE::Lanes(d);
  return n >= 64 ? bits : bits & ((uint64_t{1} << n) - 1);
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#endif  // ONTILE_RASTER_LANE_BITS_INL_H_
