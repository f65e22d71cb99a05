// SIMD quad sampler (see texture_quad_simd.h), compiled per target by Highway's foreach_target.
// Only IEEE multiply, add, subtract, square root and floor: every target gives the bits of the
// scalar path.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/texture_quad_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/texture_quad_simd.h"
#include "raster/log2_exact.h"
#include "raster/texel_wrap.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

constexpr int kLanes = 4;
constexpr int kPairs = 2 * kLanes;  // (level, lane) pairs, laid out level * 4 + lane
constexpr float kMaxExactTexelCoord = 16777216.0f;  // as texture.cpp

// The two texel columns (or rows) of footprints starting at `first` along an axis whose last
// texel is `last` (per lane: a pair's level), wrapped as wrap_texel_index does: identity inside
// the level, a mask for repeat on power-of-two sizes (`pow2`: every level's), a clamp for
// clamp-to-edge. False when a lane needs another wrap (mirrored repeat, or repeat on another
// size, outside the level): the caller takes the scalar path.
template <class DI>
HWY_INLINE bool wrap_axis(DI di, hn::Vec<DI> first, hn::Vec<DI> last, WrapMode mode, bool pow2,
                          hn::Vec<DI>& lo, hn::Vec<DI>& hi) {
  const auto second = hn::Add(first, hn::Set(di, 1));
  if (mode == WrapMode::Repeat && pow2) {
    lo = hn::And(first, last);  // two's complement: i mod 2^k for negative i too
    hi = hn::And(second, last);
    return true;
  }
  if (mode == WrapMode::ClampToEdge) {
    lo = hn::Min(hn::Max(first, hn::Zero(di)), last);
    hi = hn::Min(hn::Max(second, hn::Zero(di)), last);
    return true;
  }
  const hn::RebindToUnsigned<DI> du;
  // Unsigned compare: a negative index wraps to a huge value and fails too.
  if (!hn::AllTrue(du, hn::Lt(hn::BitCast(du, first), hn::BitCast(du, last)))) return false;
  lo = first;
  hi = second;
  return true;
}


// What holds for a job's levels, found once for the jobs of a read that start at the same level
// rather than per job; a job without them (`{}`) checks its own levels.
struct LevelFacts {
  bool sizes_fit = false;  // fewer than 2^31 texels (texel indices are int32 lanes)
  bool plain = false;      // uncompressed 4-byte texels: texel t's granule is (address + 4 t) / 64
  bool pow2_u = false, pow2_v = false;  // power-of-two widths, heights

  static LevelFacts of(const Texture2D::Level* levels, int level_count) {
    LevelFacts facts{true, true, true, true};
    for (int l = 0; l < level_count; ++l) {
      const Texture2D::Level& level = levels[l];
      const uint64_t texels = static_cast<uint64_t>(level.width) * static_cast<uint64_t>(level.height);
      facts.sizes_fit &= texels < (uint64_t{1} << 31);
      facts.plain &= level.memory_bytes_per_texel == 4 && level.block_bytes == 0;
      facts.pow2_u &= (level.width & (level.width - 1)) == 0;
      facts.pow2_v &= (level.height & (level.height - 1)) == 0;
    }
    return facts;
  }
};

// Lanes i .. i + Lanes(d) of a (level, lane) vector holding `level0` in pairs 0-3 and `level1` in
// pairs 4-7: one blend where a vector holds both levels (8 lanes), else a broadcast.
template <class D, typename T>
HWY_INLINE hn::Vec<D> per_level(D d, size_t i, T level0, T level1) {
  if (hn::Lanes(d) > static_cast<size_t>(kLanes)) {
    return hn::IfThenElse(hn::FirstN(d, kLanes), hn::Set(d, level0), hn::Set(d, level1));
  }
  return hn::Set(d, i < static_cast<size_t>(kLanes) ? level0 : level1);
}

// The pairs a job with kLevels levels fills: both levels' lanes, or level 0's lanes and, where a
// vector holds 8 lanes anyway, a copy of them in level 1's (never used, but every gathered index
// valid and no lane of an 8-lane vector unwritten).
template <int kLevels, class D>
HWY_INLINE size_t used_pairs(D d) {
  return kLevels == 2 ? static_cast<size_t>(kPairs) : std::max(static_cast<size_t>(kLanes), hn::Lanes(d));
}

// The footprints of a job's levels on (level, lane) lanes, both levels of a trilinear job on one
// 8-lane vector: x = u * size - 0.5, i0 = floor(x), a = x - i0 (OpenGL 4.6 eq. 8.10) per axis,
// then the texel indices t00, t10, t01, t11 (taps[t][pair]) bilinear_footprint selects.
// u, v: the quad's 4 coordinates twice (pairs). False, touching nothing the caller keeps, when
// |u| or |x| reach 2^24 (the scalar path reduces those first) or a level has 2^31 texels or more
// (texel indices are int32 lanes).
template <int kLevels>
HWY_INLINE bool footprints(const QuadSample8& in, const LevelFacts& facts, const float* u, const float* v,
                           float a_out[kPairs], float b_out[kPairs], int32_t taps[4][kPairs]) {
  const Texture2D::Level& level0 = *in.levels[0];
  const Texture2D::Level& level1 = *in.levels[kLevels - 1];  // level 0 again with one level
  if (!facts.sizes_fit && !LevelFacts::of(in.levels[0], 1).sizes_fit) return false;
  if (!facts.sizes_fit && !LevelFacts::of(in.levels[kLevels - 1], 1).sizes_fit) return false;
  const hn::CappedTag<float, kPairs> d;
  const hn::RebindToSigned<decltype(d)> di;
  const size_t n = hn::Lanes(d);
  const size_t pairs = used_pairs<kLevels>(d);
  const int w0 = level0.width, h0 = level0.height, w1 = level1.width, h1 = level1.height;
  const auto limit = hn::Set(d, kMaxExactTexelCoord);
  const auto half = hn::Set(d, 0.5f);
  alignas(32) int32_t i0[kPairs], j0[kPairs];
  for (size_t i = 0; i < pairs; i += n) {
    const auto uu = hn::LoadU(d, u + i), vv = hn::LoadU(d, v + i);
    // int -> float rounds to nearest, as static_cast<float> of the width does.
    const auto x = hn::Sub(hn::Mul(uu, hn::ConvertTo(d, per_level(di, i, w0, w1))), half);
    const auto y = hn::Sub(hn::Mul(vv, hn::ConvertTo(d, per_level(di, i, h0, h1))), half);
    const auto exact = hn::And(hn::And(hn::Lt(hn::Abs(uu), limit), hn::Lt(hn::Abs(x), limit)),
                               hn::And(hn::Lt(hn::Abs(vv), limit), hn::Lt(hn::Abs(y), limit)));
    if (!hn::AllTrue(d, exact)) return false;
    const auto x_floor = hn::Floor(x), y_floor = hn::Floor(y);
    hn::Store(hn::ConvertTo(di, x_floor), di, i0 + i);
    hn::Store(hn::ConvertTo(di, y_floor), di, j0 + i);
    hn::Store(hn::Sub(x, x_floor), d, a_out + i);
    hn::Store(hn::Sub(y, y_floor), d, b_out + i);
  }
  const bool pow2_u = facts.pow2_u || ((w0 & (w0 - 1)) | (w1 & (w1 - 1))) == 0;
  const bool pow2_v = facts.pow2_v || ((h0 & (h0 - 1)) | (h1 & (h1 - 1))) == 0;
  const auto one = hn::Set(di, 1);
  for (size_t i = 0; i < pairs; i += n) {
    const auto row = per_level(di, i, w0, w1);
    hn::Vec<decltype(di)> xa, xb, ya, yb;
    const auto last_row = hn::Sub(per_level(di, i, h0, h1), one);
    if (!wrap_axis(di, hn::Load(di, i0 + i), hn::Sub(row, one), in.wrap_u, pow2_u, xa, xb) ||
        !wrap_axis(di, hn::Load(di, j0 + i), last_row, in.wrap_v, pow2_v, ya, yb)) {
      for (size_t pair = 0; pair < pairs; ++pair) {
        const Texture2D::Level& level = pair < static_cast<size_t>(kLanes) ? level0 : level1;
        size_t t[4];
        bilinear_footprint(i0[pair], j0[pair], level.width, level.height, in.wrap_u, in.wrap_v, t);
        for (int k = 0; k < 4; ++k) taps[k][pair] = static_cast<int32_t>(t[k]);
      }
      return true;
    }
    const auto row_a = hn::Mul(ya, row), row_b = hn::Mul(yb, row);
    hn::Store(hn::Add(row_a, xa), di, taps[0] + i);
    hn::Store(hn::Add(row_a, xb), di, taps[1] + i);
    hn::Store(hn::Add(row_b, xa), di, taps[2] + i);
    hn::Store(hn::Add(row_b, xb), di, taps[3] + i);
  }
  return true;
}

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

// Channel c (the byte at kShift) of the pairs' texels p: decoded through `table` on lanes, then
// filtered as texture.cpp does: top = t00 (1 - a) + t10 a, bottom = t01 (1 - a) + t11 a,
// top (1 - b) + bottom b.
template <int kShift, class D>
HWY_INLINE hn::Vec<D> filter_channel(D d, const float* table, const hn::Vec<hn::RebindToUnsigned<D>> p[4],
                                     hn::Vec<D> a, hn::Vec<D> one_a, hn::Vec<D> b, hn::Vec<D> one_b) {
  const hn::RebindToUnsigned<D> du;
  hn::Vec<D> tap[4];
  for (int t = 0; t < 4; ++t) {
    auto index = hn::ShiftRight<kShift>(p[t]);  // unsigned: the top byte needs no mask
    if (kShift < 24) index = hn::And(index, hn::Set(du, 0xFFu));
    tap[t] = hn::GatherIndex(d, table, hn::BitCast(hn::RebindToSigned<D>(), index));
  }
  const auto top = hn::Add(hn::Mul(tap[0], one_a), hn::Mul(tap[1], a));
  const auto bottom = hn::Add(hn::Mul(tap[2], one_a), hn::Mul(tap[3], a));
  return hn::Add(hn::Mul(top, one_b), hn::Mul(bottom, b));
}

// The quad's 4 channels from its pairs' texels packed[t][pair] and weights a, b: filtered per
// level, level 1 blended in with weight in.blend (two levels), channel c of lane i to out[c][i].
// Where one vector holds every pair (8 lanes), a channel stays in registers from the decode to
// the store, one channel at a time; elsewhere the filter runs on the pairs a vector at a time.
template <int kLevels, class D>
HWY_INLINE void filter_quad(D d8, const QuadSample8& in, size_t pairs, const int32_t packed[4][kPairs],
                            const float* a, const float* b, float* const out[4]) {
  const hn::RebindToUnsigned<D> du8;
  const auto one8 = hn::Set(d8, 1.0f);
#if HWY_TARGET != HWY_SCALAR  // (which has no UpperHalf)
  if constexpr (hn::MaxLanes(D()) >= static_cast<size_t>(kPairs)) {
    hn::Vec<decltype(du8)> p[4];
    for (int t = 0; t < 4; ++t) p[t] = hn::Load(du8, reinterpret_cast<const uint32_t*>(packed[t]));
    const auto wa = hn::Load(d8, a), wb = hn::Load(d8, b);
    const auto one_a = hn::Sub(one8, wa), one_b = hn::Sub(one8, wb);
    const hn::Half<D> dh;
    const auto w = hn::Set(dh, in.blend);
    const auto one_w = hn::Sub(hn::Set(dh, 1.0f), w);
    const auto store = [&](hn::Vec<D> filtered, float* row) {
      auto value = hn::LowerHalf(dh, filtered);
      if (kLevels == 2) value = hn::Add(hn::Mul(value, one_w), hn::Mul(hn::UpperHalf(dh, filtered), w));
      hn::StoreU(value, dh, row);
    };
    store(filter_channel<0>(d8, in.rgb_decode, p, wa, one_a, wb, one_b), out[0]);
    store(filter_channel<8>(d8, in.rgb_decode, p, wa, one_a, wb, one_b), out[1]);
    store(filter_channel<16>(d8, in.rgb_decode, p, wa, one_a, wb, one_b), out[2]);
    store(filter_channel<24>(d8, in.alpha_decode, p, wa, one_a, wb, one_b), out[3]);
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
        hn::StoreU(value, d, out[c] + i);
      }
    }
  }
}

// One quad with kLevels levels: channel c of lane i to out[c][i]. False, touching nothing, when
// it needs the general path. u, v: the 4 lanes' finite coordinates, twice (pairs; in.uv is not
// read).
template <int kLevels>
HWY_INLINE bool sample_one(const QuadSample8& in, const LevelFacts& facts, const float* u, const float* v,
                           float* const out[4], TraceStaging* staging) {
  alignas(32) float a[kPairs], b[kPairs];
  alignas(32) int32_t taps[4][kPairs];  // [tap][level * 4 + lane] texel index in the level
  if (!footprints<kLevels>(in, facts, u, v, a, b, taps)) return false;
  if (in.trace) record_trace<kLevels>(in, facts.plain, taps, staging);
  // Texels: one 32-bit RGBA8 load per tap and pair, laid out [tap][level * 4 + lane] so that both
  // levels' bilinear filters run on the same 8 lanes (two 4-lane vectors on targets with 128-bit
  // vectors); each channel is decoded through its table on the lanes at once. A lane's
  // operations are those of the one-level filter, so every target gives the same bits.
  const hn::CappedTag<float, kPairs> d8;
  const hn::RebindToSigned<decltype(d8)> di8;
  const size_t n8 = hn::Lanes(d8);
  const size_t pairs = used_pairs<kLevels>(d8);
  alignas(32) int32_t packed[4][kPairs];
  const uint8_t* texels0 = in.levels[0]->bytes8();
  const uint8_t* texels1 = in.levels[kLevels - 1]->bytes8();
  if ((reinterpret_cast<uintptr_t>(texels0) | reinterpret_cast<uintptr_t>(texels1)) % alignof(int32_t) == 0) {
    // Texel t of a level is the int32 at index t: gathered on lanes, a level at a time.
    if (kLevels == 1) {
      const int32_t* words = reinterpret_cast<const int32_t*>(texels0);
      for (size_t i = 0; i < pairs; i += n8) {
        for (int t = 0; t < 4; ++t) {
          hn::Store(hn::GatherIndex(di8, words, hn::Load(di8, taps[t] + i)), di8, packed[t] + i);
        }
      }
    } else {
      const hn::CappedTag<int32_t, kLanes> di4;
      for (size_t i = 0; i < static_cast<size_t>(kPairs); i += hn::Lanes(di4)) {
        const uint8_t* texels = i < static_cast<size_t>(kLanes) ? texels0 : texels1;
        const int32_t* words = reinterpret_cast<const int32_t*>(texels);
        for (int t = 0; t < 4; ++t) {
          hn::Store(hn::GatherIndex(di4, words, hn::Load(di4, taps[t] + i)), di4, packed[t] + i);
        }
      }
    }
  } else {
    for (int t = 0; t < 4; ++t) {
      for (size_t pair = 0; pair < pairs; ++pair) {
        const uint8_t* texels = pair < static_cast<size_t>(kLanes) ? texels0 : texels1;
        std::memcpy(&packed[t][pair], texels + static_cast<size_t>(taps[t][pair]) * 4, 4);
      }
    }
  }
  filter_quad<kLevels>(d8, in, pairs, packed, a, b, out);
  return true;
}

// sample_one for the job's level count. facts: of every level of the job's read, or `{}`.
HWY_INLINE bool sample_job(const QuadSample8& in, const LevelFacts& facts, const float* u, const float* v,
                           float* const out[4], TraceStaging* staging) {
  return in.level_count == 2 ? sample_one<2>(in, facts, u, v, out, staging)
                             : sample_one<1>(in, facts, u, v, out, staging);
}

bool SampleQuad8Kernel(const QuadSample8& in, glm::vec4* out) {
  float u[kPairs], v[kPairs];  // the 4 lanes' coordinates, twice (pairs)
  for (int lane = 0; lane < kPairs; ++lane) {
    u[lane] = in.uv[lane % kLanes].x;
    v[lane] = in.uv[lane % kLanes].y;
  }
  alignas(16) float result[4][kLanes];
  float* const result_rows[4] = {result[0], result[1], result[2], result[3]};
  if (!sample_job(in, LevelFacts{}, u, v, result_rows, nullptr)) return false;
  for (int lane = 0; lane < kLanes; ++lane) {
    out[lane] = {result[0][lane], result[1][lane], result[2][lane], result[3][lane]};
  }
  return true;
}

// Texture2D::sample_quads' jobs (quad q, read r) from position `first` = q * read_count + r on,
// in that order (texture.cpp's quad_lambda and linear8_job, operation for operation); returns
// the position of the first job that needs the general path, or quad_count * read_count.
// kAfterQuad: batch.after_quad traces after each quad (a separate instance, so batches without
// a hook pay nothing per quad).
template <bool kAfterQuad>
int sample_quad_batch(const QuadBatch8& batch, int first) {
  const hn::CappedTag<float, kLanes> d;
  QuadSample8 jobs[QuadBatch8::kMaxReads];
  // facts[r]: of read r's levels facts_level[r] and the one after it (when there is one).
  LevelFacts facts[QuadBatch8::kMaxReads];
  const Texture2D::Level* facts_level[QuadBatch8::kMaxReads];
  for (int r = 0; r < batch.read_count; ++r) {
    const BatchRead8& read = batch.reads[r];
    facts_level[r] = nullptr;
    jobs[r].wrap_u = read.wrap_u;
    jobs[r].wrap_v = read.wrap_v;
    jobs[r].rgb_decode = read.rgb_decode;
    jobs[r].alpha_decode = read.alpha_decode;
    jobs[r].trace = batch.trace;
    jobs[r].last_granule = batch.last_granule;
    jobs[r].trace_repeats = read.trace_repeats;
  }
  TraceStaging staging;
  if (batch.trace) staging.last = *batch.last_granule;
  // Before returning, the staged granules go to the trace (the general path appends after them).
  const auto finish = [&](int position) {
    if (batch.trace) {
      staging.flush(*batch.trace);
      *batch.last_granule = staging.last;
    }
    return position;
  };
  const int first_quad = first / batch.read_count;
  int first_read = first - first_quad * batch.read_count;
  const auto inf = hn::Set(d, std::numeric_limits<float>::infinity());
  // Quads a block of 4 at a time: the block's coordinates made finite (finite_or_zero on lanes:
  // |x| < inf is false for NaN and infinities), then quad_lambda's rho = max(|d(uv)/dx|,
  // |d(uv)/dy|) in texels of level 0 (OpenGL 4.6 eq. 8.7) for each read, one quad per lane: the
  // scalar operations on lanes, std::max as a compare and select.
  constexpr int kBlockQuads = kLanes;
  for (int block = first_quad; block < batch.quad_count; block += kBlockQuads) {
    const int quads = std::min(kBlockQuads, batch.quad_count - block);
    alignas(32) float block_u[kBlockQuads * kLanes], block_v[kBlockQuads * kLanes];  // [quad][lane]
    const float* raw_u = batch.u + block * kLanes;
    const float* raw_v = batch.v + block * kLanes;
    if (quads < kBlockQuads) {  // the last block: zeros after the batch's quads
      std::memset(block_u, 0, sizeof block_u);
      std::memset(block_v, 0, sizeof block_v);
      std::memcpy(block_u, raw_u, sizeof(float) * static_cast<size_t>(quads * kLanes));
      std::memcpy(block_v, raw_v, sizeof(float) * static_cast<size_t>(quads * kLanes));
      raw_u = block_u;
      raw_v = block_v;
    }
    for (size_t i = 0; i < static_cast<size_t>(kBlockQuads * kLanes); i += hn::Lanes(d)) {
      const auto uu = hn::LoadU(d, raw_u + i), vv = hn::LoadU(d, raw_v + i);
      hn::Store(hn::IfThenElseZero(hn::Lt(hn::Abs(uu), inf), uu), d, block_u + i);
      hn::Store(hn::IfThenElseZero(hn::Lt(hn::Abs(vv), inf), vv), d, block_v + i);
    }
    alignas(16) float rho[QuadBatch8::kMaxReads][kBlockQuads];  // [read][quad of the block]
    for (size_t i = 0; i < static_cast<size_t>(kBlockQuads); i += hn::Lanes(d)) {
      hn::Vec<decltype(d)> u0, u1, u2, u3, v0, v1, v2, v3;
      hn::LoadInterleaved4(d, block_u + i * kLanes, u0, u1, u2, u3);
      hn::LoadInterleaved4(d, block_v + i * kLanes, v0, v1, v2, v3);
      const auto du_dx = hn::Sub(u1, u0), dv_dx = hn::Sub(v1, v0);
      const auto du_dy = hn::Sub(u2, u0), dv_dy = hn::Sub(v2, v0);
      for (int r = 0; r < batch.read_count; ++r) {
        const auto width = hn::Set(d, static_cast<float>(batch.reads[r].levels[0].width));
        const auto height = hn::Set(d, static_cast<float>(batch.reads[r].levels[0].height));
        const auto dx_u = hn::Mul(du_dx, width), dx_v = hn::Mul(dv_dx, height);
        const auto dy_u = hn::Mul(du_dy, width), dy_v = hn::Mul(dv_dy, height);
        const auto rho_x = hn::Sqrt(hn::Add(hn::Mul(dx_u, dx_u), hn::Mul(dx_v, dx_v)));
        const auto rho_y = hn::Sqrt(hn::Add(hn::Mul(dy_u, dy_u), hn::Mul(dy_v, dy_v)));
        hn::Store(hn::IfThenElse(hn::Lt(rho_x, rho_y), rho_y, rho_x), d, rho[r] + i);
      }
    }
    for (int j = 0; j < quads; ++j, first_read = 0) {
      const int q = block + j;
      const int f0 = q * kLanes;
      // u, v: the 4 lanes' coordinates twice (pairs), as sample_one takes them.
      alignas(32) float u[kPairs], v[kPairs];
      for (size_t i = 0; i < kLanes; i += hn::Lanes(d)) {
        const auto finite_u = hn::Load(d, block_u + j * kLanes + i);
        const auto finite_v = hn::Load(d, block_v + j * kLanes + i);
        hn::Store(finite_u, d, u + i);
        hn::Store(finite_u, d, u + kLanes + i);
        hn::Store(finite_v, d, v + i);
        hn::Store(finite_v, d, v + kLanes + i);
      }
      for (int r = first_read; r < batch.read_count; ++r) {
        const BatchRead8& read = batch.reads[r];
        QuadSample8& job = jobs[r];
        float lambda = log2_exact(rho[r][j]) + read.lod_bias;
        // linear8_job's level selection.
        job.level_count = 1;
        job.blend = 0.0f;
        const bool base_only = !(lambda > 0.0f) || read.mipmap_mode == MipmapMode::None;
        if (!base_only) lambda = std::min(lambda, read.max_level);
        if (base_only) {
          job.levels[0] = &read.levels[0];
        } else if (read.mipmap_mode == MipmapMode::Nearest) {
          const int single_level = lambda <= 0.5f ? 0 : static_cast<int>(std::ceil(lambda + 0.5f)) - 1;
          job.levels[0] = &read.levels[single_level];
        } else {
          const float d1_float = std::floor(lambda);
          const float blend = lambda - d1_float;
          job.levels[0] = &read.levels[static_cast<int>(d1_float)];
          if (blend != 0.0f) {
            job.levels[1] = &read.levels[static_cast<int>(d1_float) + 1];
            job.level_count = 2;
            job.blend = blend;
          }
        }
        if (job.levels[0] != facts_level[r]) {
          facts_level[r] = job.levels[0];
          const int level = static_cast<int>(job.levels[0] - read.levels);
          facts[r] = LevelFacts::of(job.levels[0], std::min(2, static_cast<int>(read.max_level) - level + 1));
        }
        float* const out[4] = {read.out[0] + f0, read.out[1] + f0, read.out[2] + f0, read.out[3] + f0};
        if (!sample_job(job, facts[r], u, v, out, &staging)) return finish(q * batch.read_count + r);
      }
      if constexpr (kAfterQuad) {  // the shader's own reads of the quad, staged in order
        const Texture2D::QuadTraceHook& hook = *batch.after_quad;
        if (staging.count > TraceStaging::kCapacity - hook.max_granules) staging.flush(*batch.trace);
        staging.count += hook.append(hook.context, q, staging.granules + 1 + staging.count, staging.last);
      }
    }
  }
  return finish(batch.quad_count * batch.read_count);
}

int SampleQuadBatch8Kernel(const QuadBatch8& batch, int first) {
  return batch.after_quad && batch.trace ? sample_quad_batch<true>(batch, first)
                                         : sample_quad_batch<false>(batch, first);
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(SampleQuad8Kernel);
HWY_EXPORT(SampleQuadBatch8Kernel);

bool sample_quad8_simd(const QuadSample8& in, glm::vec4 out[4]) {
  return HWY_DYNAMIC_DISPATCH(SampleQuad8Kernel)(in, out);
}

int sample_quad_batch8_simd(const QuadBatch8& batch, int first) {
  return HWY_DYNAMIC_DISPATCH(SampleQuadBatch8Kernel)(batch, first);
}

}  // namespace ontile
#endif  // HWY_ONCE
