// The texel trace of the SIMD quad sampler (texture_quad_simd.cpp): a quad's granules in the scalar
// sampler's order, repeats of the previous granule removed, staged per batch call.
// Compiled once per SIMD target: foreach_target re-includes this file from texture_quad_simd.cpp,
// hence the toggling guard instead of #pragma once.
#if defined(ONTILE_RASTER_TEXTURE_QUAD_TRACE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ONTILE_RASTER_TEXTURE_QUAD_TRACE_INL_H_
#undef ONTILE_RASTER_TEXTURE_QUAD_TRACE_INL_H_
#else
#define ONTILE_RASTER_TEXTURE_QUAD_TRACE_INL_H_
#endif

#include <hwy/highway.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "raster/texture_quad_footprint-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Granules a batch call gathers before appending them to the trace at once (a vector insert per
// quad cost about 70 instructions): granules[1 .. count] in trace order, `last` the trace's last
// granule with them appended. granules[0] is a spare slot record_trace may write.
struct TraceStaging {
  static constexpr int kCapacity = 1024;
  static constexpr int kMaxPerQuad = 2 * 4 * kLanes + 2;  // every granule of a quad, and a spare
  uint64_t granules[1 + kCapacity];
  int count = 0;
  uint64_t last = 0;
  void flush(std::vector<uint64_t>& trace) {
    trace.insert(trace.end(), granules + 1, granules + 1 + count);
    count = 0;
  }
};

// Appends the quad's texel granules to the trace in the scalar sampler's order: lane by lane,
// level by level, each footprint as t00, t10, t01, t11, repeats of the previous granule skipped.
// taps[t][pair]: footprints' texel indices (footprints). Granules are computed on 64-bit lanes
// for uncompressed 4-byte texels (every 8-bit texture not block-compressed); block-compressed
// levels map each texel to its block's address. staging: where a batch call gathers them, or
// null to append to in.trace.
template <int kLevels>
HWY_INLINE void record_trace(const QuadSample8& in, bool plain_levels, const int32_t taps[4][kPairs],
                             TraceStaging* staging) {
  constexpr size_t kUsed = static_cast<size_t>(kLanes * kLevels);
  constexpr int kLastLevel = kLanes * (kLevels - 1);  // pair of the last level's lane 0
  alignas(32) uint64_t granule[4][kPairs];  // [tap][level * 4 + lane]
  const hn::CappedTag<uint64_t, kLanes> d64;
  const hn::Rebind<int64_t, decltype(d64)> ds64;
  const hn::Rebind<int32_t, decltype(d64)> d32;
  const size_t n = hn::Lanes(d64);
  const Texture2D::Level& level0 = *in.levels[0];
  const Texture2D::Level& level1 = *in.levels[kLevels - 1];
  const auto plain = [](const Texture2D::Level& level) {
    return level.memory_bytes_per_texel == 4 && level.block_bytes == 0;
  };
  if (plain_levels || (plain(level0) && plain(level1))) {
    for (size_t i = 0; i < kUsed; i += n) {
      const auto base = hn::Set(d64, i < static_cast<size_t>(kLanes) ? level0.address : level1.address);
      for (int t = 0; t < 4; ++t) {
        const auto texel = hn::BitCast(d64, hn::PromoteTo(ds64, hn::LoadU(d32, taps[t] + i)));
        hn::Store(hn::ShiftRight<6>(hn::Add(base, hn::ShiftLeft<2>(texel))), d64, granule[t] + i);
      }
    }
  } else {
    for (int t = 0; t < 4; ++t) {
      for (size_t pair = 0; pair < kUsed; ++pair) {
        const Texture2D::Level& level = pair < static_cast<size_t>(kLanes) ? level0 : level1;
        granule[t][pair] = level.texel_byte_address(static_cast<size_t>(taps[t][pair])) >> 6;
      }
    }
  }
  // The footprint's first granule, then the tail: the rest with repeats of the previous one
  // merged. Only the first can merge with what the trace held before, so a repeated fetch
  // (trace_repeats) appends the same tail again. The sequence is written at `sequence`, the
  // first granule at sequence[0] and the tail after it. When staging, the tail goes straight
  // after the staged granules, and sequence[0] is the slot before it: a new slot when the first
  // granule is kept, else the last staged granule (or the spare slot), which already holds that
  // same value.
  const uint64_t first = granule[0][0];
  uint64_t local[1 + 2 * 4 * kLanes];
  uint64_t* sequence = local;
  int kept_first = 0;
  if (staging) {
    if (staging->count > TraceStaging::kCapacity - TraceStaging::kMaxPerQuad) staging->flush(*in.trace);
    kept_first = first != staging->last;
    sequence = staging->granules + staging->count + kept_first;
  }
  sequence[0] = first;
  uint64_t* const tail = sequence + 1;
  uint64_t last = first;
  int tail_count = 0;
  // The common footprint (most quads): each row's two texels share a granule, the two rows do
  // not, and no footprint starts in the granule the one before it ended in. Then the kept
  // granules are exactly t00 and t01 of every footprint, which the loop below would find one
  // compare at a time; checked on lanes, and written interleaved on lanes.
  bool regular = true;
  for (size_t i = 0; i < static_cast<size_t>(kLanes); i += n) {
    const auto t00 = hn::Load(d64, granule[0] + i), t10 = hn::Load(d64, granule[1] + i);
    const auto t01 = hn::Load(d64, granule[2] + i), t11 = hn::Load(d64, granule[3] + i);
    auto same_rows = hn::AndNot(hn::Eq(t00, t01), hn::And(hn::Eq(t00, t10), hn::Eq(t01, t11)));
    if (kLevels == 2) {
      const auto s00 = hn::Load(d64, granule[0] + kLanes + i), s10 = hn::Load(d64, granule[1] + kLanes + i);
      const auto s01 = hn::Load(d64, granule[2] + kLanes + i), s11 = hn::Load(d64, granule[3] + kLanes + i);
      const auto same_rows1 = hn::AndNot(hn::Eq(s00, s01), hn::And(hn::Eq(s00, s10), hn::Eq(s01, s11)));
      same_rows = hn::AndNot(hn::Eq(s00, t11), hn::And(same_rows, same_rows1));
    }
    regular &= hn::AllTrue(d64, same_rows);
  }
  // Lane k's first granule against lane k - 1's last (lane 0's is `first` itself, kept above);
  // lane 0's compare reads the slot before the last level's t11 row, defined here with one level.
  if (kLevels == 1) granule[2][kPairs - 1] = 0;
  for (size_t i = 0; i < static_cast<size_t>(kLanes); i += n) {
    const auto lane_before_last = hn::LoadU(d64, granule[3] + kLastLevel + i - 1);
    const auto merges = hn::Eq(hn::Load(d64, granule[0] + i), lane_before_last);
    regular &= hn::AllFalse(d64, i == 0 ? hn::AndNot(hn::FirstN(d64, 1), merges) : merges);
  }
  if (regular) {
    // sequence[0] is written again with the first granule, the same value.
    for (size_t i = 0; i < static_cast<size_t>(kLanes); i += n) {
      const auto t00 = hn::Load(d64, granule[0] + i), t01 = hn::Load(d64, granule[2] + i);
      if (kLevels == 2) {
        const auto s00 = hn::Load(d64, granule[0] + kLanes + i), s01 = hn::Load(d64, granule[2] + kLanes + i);
        hn::StoreInterleaved4(t00, t01, s00, s01, d64, sequence + 4 * i);
      } else {
        hn::StoreInterleaved2(t00, t01, d64, sequence + 2 * i);
      }
    }
    constexpr int kCount = 2 * kLanes * kLevels;
    last = sequence[kCount - 1];
    tail_count = kCount - 1;
  } else {
    for (int lane = 0; lane < kLanes; ++lane) {
      for (int l = 0; l < kLevels; ++l) {
        for (int t = 0; t < 4; ++t) {
          const uint64_t g = granule[t][l * kLanes + lane];
          tail[tail_count] = g;
          tail_count += g != last;
          last = g;
        }
      }
    }
  }
  if (staging) {
    staging->count += kept_first + tail_count;
    staging->last = last;
    // A repeated fetch: the first granule unless the trace ends in it, then the same tail. After
    // a flush the copy may overlap the tail's old place, hence memmove before writing `first`.
    const uint64_t* repeated_tail = tail;
    for (int repeat = 1; repeat < in.trace_repeats; ++repeat) {
      if (staging->count > TraceStaging::kCapacity - TraceStaging::kMaxPerQuad) staging->flush(*in.trace);
      const int kept = first != last;
      uint64_t* const copy = staging->granules + 1 + staging->count;
      std::memmove(copy + kept, repeated_tail, sizeof(uint64_t) * static_cast<size_t>(tail_count));
      if (kept) copy[0] = first;
      repeated_tail = copy + kept;
      staging->count += kept + tail_count;
    }
    return;
  }
  uint64_t previous = *in.last_granule;
  for (int repeat = 0; repeat < in.trace_repeats; ++repeat) {
    if (first != previous) in.trace->push_back(first);
    in.trace->insert(in.trace->end(), tail, tail + tail_count);
    previous = last;
  }
  *in.last_granule = last;
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#endif  // ONTILE_RASTER_TEXTURE_QUAD_TRACE_INL_H_
