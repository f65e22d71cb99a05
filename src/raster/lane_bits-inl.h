// The bits of a SIMD mask as an integer (lane i -> bit i), and a table for the way back, for the
// Highway kernels compiled once per target (foreach_target re-includes this file, hence the
// toggling guard instead of #pragma once; Highway 1.0 has no public BitsFromMask).
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

// Bit i for lane i of 32-bit lanes (x86 vectors hold at most 16): And with a broadcast word of
// lane bits, compare with zero, and the word's bits are a mask.
alignas(64) constexpr uint32_t kLaneBit32[16] = {1u << 0, 1u << 1, 1u << 2,  1u << 3,
                                                 1u << 4, 1u << 5, 1u << 6,  1u << 7,
                                                 1u << 8, 1u << 9, 1u << 10, 1u << 11,
                                                 1u << 12, 1u << 13, 1u << 14, 1u << 15};

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
