// The bilinear/trilinear filter of the SIMD quad sampler (texture_quad_simd.cpp): texels decoded
// through their tables on lanes and weighted in the scalar sampler's operation order.
// Compiled once per SIMD target: foreach_target re-includes this file from texture_quad_simd.cpp,
// hence the toggling guard instead of #pragma once.
#if defined(ONTILE_RASTER_TEXTURE_QUAD_FILTER_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ONTILE_RASTER_TEXTURE_QUAD_FILTER_INL_H_
#undef ONTILE_RASTER_TEXTURE_QUAD_FILTER_INL_H_
#else
#define ONTILE_RASTER_TEXTURE_QUAD_FILTER_INL_H_
#endif

#include <hwy/highway.h>

#include <cstddef>
#include <cstdint>

#include "raster/texture_quad_footprint-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Channel c (the byte at kShift) of the pairs' texels p: decoded through `table` on lanes, then
// filtered as texture.cpp does: top = t00 (1 - a) + t10 a, bottom = t01 (1 - a) + t11 a,
// top (1 - b) + bottom b.
template <int kShift, class D>
HWY_INLINE hn::Vec<D> filter_channel(D d, const float* table, const hn::Vec<hn::RebindToUnsigned<D>> p[4],
                                     hn::Vec<D> a, hn::Vec<D> one_a, hn::Vec<D> b, hn::Vec<D> one_b) {
  const hn::RebindToUnsigned<D> du;
  hn::Vec<D> tap[4];
  for (int t = 0; t < 4; ++t) {
    hn::Vec<decltype(du)> index;
    if constexpr (kShift == 0) {
      index = hn::And(p[t], hn::Set(du, 0xFFu));
    } else if constexpr (kShift == 24) {
      index = hn::ShiftRight<24>(p[t]);  // unsigned: the top byte needs no mask
    } else {
#if HWY_TARGET == HWY_SCALAR
      index = hn::And(hn::ShiftRight<kShift>(p[t]), hn::Set(du, 0xFFu));
#else
      // The middle bytes in one byte shuffle: each lane takes its own byte kShift / 8 and three
      // zeros (an index with the top bit set), indices counted from the lane's 128-bit block.
      const auto own_byte = hn::ShiftLeft<2>(hn::And(hn::Iota(du, 0), hn::Set(du, 3u)));
      index = hn::TableLookupBytesOr0(p[t], hn::Or(own_byte, hn::Set(du, 0x80808000u | (kShift / 8))));
#endif
    }
    tap[t] = hn::GatherIndex(d, table, hn::BitCast(hn::RebindToSigned<D>(), index));
  }
  const auto top = hn::Add(hn::Mul(tap[0], one_a), hn::Mul(tap[1], a));
  const auto bottom = hn::Add(hn::Mul(tap[2], one_a), hn::Mul(tap[3], a));
  return hn::Add(hn::Mul(top, one_b), hn::Mul(bottom, b));
}

// The quad's 4 channels from its pairs' texels packed[t][pair] and weights a, b: filtered per
// level, level 1 blended in with weight in.blend (two levels), channel c of lane i to
// out[c][offset + i].
// Where one vector holds every pair (8 lanes), channels stay in registers from the decode to
// the store, two channels at a time; elsewhere the filter runs on the pairs a vector at a time.
template <int kLevels, class D>
HWY_INLINE void filter_quad(D d8, const QuadSample8& in, size_t pairs, const int32_t packed[4][kPairs],
                            const float* a, const float* b, float* const out[4], size_t offset) {
  const hn::RebindToUnsigned<D> du8;
  const auto one8 = hn::Set(d8, 1.0f);
#if HWY_TARGET != HWY_SCALAR  // (which has no UpperHalf)
  if constexpr (hn::MaxLanes(D()) >= static_cast<size_t>(kPairs)) {
    hn::Vec<decltype(du8)> p[4];
    for (int t = 0; t < 4; ++t) p[t] = hn::Load(du8, reinterpret_cast<const uint32_t*>(packed[t]));
    const auto wa = hn::Load(d8, a), wb = hn::Load(d8, b);
    const auto one_a = hn::Sub(one8, wa), one_b = hn::Sub(one8, wb);
    const hn::Half<D> dh;
    const auto w = hn::Set(d8, in.blend);
    const auto one_w = hn::Sub(one8, w);
    // Two channels at a time: with two levels, both channels' level d lanes on one vector and
    // their level d + 1 lanes on another, so one blend serves both (v (1 - w) + v' w per lane).
    const auto store = [&](hn::Vec<D> filtered0, hn::Vec<D> filtered1, float* row0, float* row1) {
      if (kLevels == 2) {
        const auto level0 = hn::ConcatLowerLower(d8, filtered1, filtered0);
        const auto level1 = hn::ConcatUpperUpper(d8, filtered1, filtered0);
        const auto value = hn::Add(hn::Mul(level0, one_w), hn::Mul(level1, w));
        hn::StoreU(hn::LowerHalf(dh, value), dh, row0 + offset);
        hn::StoreU(hn::UpperHalf(dh, value), dh, row1 + offset);
      } else {
        hn::StoreU(hn::LowerHalf(dh, filtered0), dh, row0 + offset);
        hn::StoreU(hn::LowerHalf(dh, filtered1), dh, row1 + offset);
      }
    };
    store(filter_channel<0>(d8, in.rgb_decode, p, wa, one_a, wb, one_b),
          filter_channel<8>(d8, in.rgb_decode, p, wa, one_a, wb, one_b), out[0], out[1]);
    store(filter_channel<16>(d8, in.rgb_decode, p, wa, one_a, wb, one_b),
          filter_channel<24>(d8, in.alpha_decode, p, wa, one_a, wb, one_b), out[2], out[3]);
    return;
  }
#endif
  {
    alignas(32) float filtered[4][kPairs];  // [channel][level * 4 + lane]
    for (size_t i = 0; i < pairs; i += hn::Lanes(d8)) {
      hn::Vec<decltype(du8)> p[4];
      for (int t = 0; t < 4; ++t) p[t] = hn::Load(du8, reinterpret_cast<const uint32_t*>(packed[t]) + i);
      const auto wa = hn::Load(d8, a + i), wb = hn::Load(d8, b + i);
      const auto one_a = hn::Sub(one8, wa), one_b = hn::Sub(one8, wb);
      hn::Store(filter_channel<0>(d8, in.rgb_decode, p, wa, one_a, wb, one_b), d8, filtered[0] + i);
      hn::Store(filter_channel<8>(d8, in.rgb_decode, p, wa, one_a, wb, one_b), d8, filtered[1] + i);
      hn::Store(filter_channel<16>(d8, in.rgb_decode, p, wa, one_a, wb, one_b), d8, filtered[2] + i);
      hn::Store(filter_channel<24>(d8, in.alpha_decode, p, wa, one_a, wb, one_b), d8, filtered[3] + i);
    }
    const hn::CappedTag<float, kLanes> d;
    const auto one = hn::Set(d, 1.0f);
    for (size_t i = 0; i < static_cast<size_t>(kLanes); i += hn::Lanes(d)) {
      for (int c = 0; c < 4; ++c) {
        auto value = hn::Load(d, filtered[c] + i);
        if (kLevels == 2) {
          const auto w = hn::Set(d, in.blend);
          value = hn::Add(hn::Mul(value, hn::Sub(one, w)), hn::Mul(hn::Load(d, filtered[c] + kLanes + i), w));
        }
        hn::StoreU(value, d, out[c] + offset + i);
      }
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#endif  // ONTILE_RASTER_TEXTURE_QUAD_FILTER_INL_H_
