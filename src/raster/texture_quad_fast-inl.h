// The common case of the SIMD quad sampler (texture_quad_simd.cpp): a trilinear RGBA8/sRGB8 read
// with repeat wrap on power-of-two levels. What the general path finds per quad (level facts,
// sizes, wraps, texel addresses) is found once per read and level pair, the texels of both levels
// are gathered on 8 lanes at once, and the trace's granules come from 32-bit texel indices.
// Compiled once per SIMD target: foreach_target re-includes this file from texture_quad_simd.cpp,
// hence the toggling guard instead of #pragma once.
#if defined(ONTILE_RASTER_TEXTURE_QUAD_FAST_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ONTILE_RASTER_TEXTURE_QUAD_FAST_INL_H_
#undef ONTILE_RASTER_TEXTURE_QUAD_FAST_INL_H_
#else
#define ONTILE_RASTER_TEXTURE_QUAD_FAST_INL_H_
#endif

#include <hwy/highway.h>

#include <cstddef>
#include <cstdint>
#include <limits>

#include "raster/texture_quad_filter-inl.h"
#include "raster/texture_quad_footprint-inl.h"
#include "raster/texture_quad_trace-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// A read's level pair (d, d + 1) prepared for sample_fast, per (level, lane) pair: level d in
// pairs 0-3, level d + 1 in pairs 4-7; or level d alone, in both halves (a single-level job on
// 8-lane vectors computes its footprints twice at no extra instruction).
struct FastLevelPair {
  const Texture2D::Level* first = nullptr;  // level d; null: nothing prepared yet
  bool usable = false;  // every condition of the fast path holds (see prepare)
  alignas(32) float width_f[kPairs], height_f[kPairs];
  alignas(32) int32_t width_mask[kPairs], height_mask[kPairs], width[kPairs];
  // Texel t of pair p's level is words[t + word_offset[p]]: level d + 1's texels addressed
  // from level d's, so one 8-lane gather serves both levels.
  alignas(32) int32_t word_offset[kPairs];
  const int32_t* words = nullptr;
  uint64_t granule_base[2] = {0, 0};  // address / 64 of each level's texel 0

  // Level `first` and, with kLevels 2, the one after it, for reads with repeat wrap on both
  // axes. Usable when the levels are uncompressed 4-byte texels of power-of-two sizes under 2^31
  // texels, start on a 64-byte granule (so texel t's granule is base + t / 16, and no granule
  // holds texels of both levels), and level d + 1's texels are 4-byte words within int32 reach
  // of level d's.
  template <int kLevels>
  void prepare(const Texture2D::Level* level, int levels_after, WrapMode wrap_u, WrapMode wrap_v) {
    first = level;
    usable = false;
    if (levels_after < kLevels - 1 || wrap_u != WrapMode::Repeat || wrap_v != WrapMode::Repeat) return;
    const Texture2D::Level* pair[2] = {level, level + (kLevels - 1)};
    for (const Texture2D::Level* l : pair) {
      const uint64_t texels = static_cast<uint64_t>(l->width) * static_cast<uint64_t>(l->height);
      if (l->memory_bytes_per_texel != 4 || l->block_bytes != 0 || texels >= (uint64_t{1} << 31) ||
          (l->width & (l->width - 1)) != 0 || (l->height & (l->height - 1)) != 0 || l->address % 64 != 0 ||
          reinterpret_cast<uintptr_t>(l->bytes8()) % alignof(int32_t) != 0) {
        return;
      }
    }
    const intptr_t offset_bytes = reinterpret_cast<intptr_t>(pair[1]->bytes8()) - reinterpret_cast<intptr_t>(pair[0]->bytes8());
    const int64_t offset_words = offset_bytes / 4;
    const int64_t texels1 = static_cast<int64_t>(pair[1]->width) * pair[1]->height;
    if (offset_bytes % 4 != 0 || offset_words < std::numeric_limits<int32_t>::min() ||
        offset_words + texels1 > std::numeric_limits<int32_t>::max()) {
      return;
    }
    for (int p = 0; p < kPairs; ++p) {
      const Texture2D::Level& l = *pair[p / kLanes];
      width_f[p] = static_cast<float>(l.width);
      height_f[p] = static_cast<float>(l.height);
      width_mask[p] = l.width - 1;
      height_mask[p] = l.height - 1;
      width[p] = l.width;
      word_offset[p] = p < kLanes ? 0 : static_cast<int32_t>(offset_words);
    }
    words = reinterpret_cast<const int32_t*>(pair[0]->bytes8());
    granule_base[0] = pair[0]->address / 64;
    granule_base[1] = pair[1]->address / 64;
    usable = true;
  }
};

// Appends a quad's granules when every footprint is regular: per level, each row's two texels
// share a granule and the two rows do not; with one level, no lane's first granule also repeats
// the lane before's last. Levels share no granule (prepare), so nothing merges across
// footprints, and the trace takes t00, t01 lane by lane, of level d then (kLevels 2) of level
// d + 1: texture_quad_trace-inl.h's regular case. top, bottom: per pair, the granule of t00 and
// of t01 relative to the pair's level base.
template <int kLevels>
HWY_INLINE void stage_regular(const FastLevelPair& pair, const int32_t top[kPairs], const int32_t bottom[kPairs],
                              std::vector<uint64_t>& trace, TraceStaging& staging) {
  if (staging.count > TraceStaging::kCapacity - TraceStaging::kMaxPerQuad) staging.flush(trace);
  const uint64_t first = pair.granule_base[0] + static_cast<uint32_t>(top[0]);
  const int kept_first = first != staging.last;
  // The first granule is written at the slot before the new ones (the last staged granule, or
  // the spare slot, holding that same value when it merges).
  uint64_t* const sequence = staging.granules + staging.count + kept_first;
  const hn::CappedTag<uint64_t, kLanes> d64;
  const hn::Rebind<int64_t, decltype(d64)> ds64;
  const hn::Rebind<int32_t, decltype(d64)> d32;
  const auto base0 = hn::Set(d64, pair.granule_base[0]), base1 = hn::Set(d64, pair.granule_base[1]);
  const auto granule = [&](const int32_t* relative, hn::Vec<decltype(d64)> base) {
    return hn::Add(base, hn::BitCast(d64, hn::PromoteTo(ds64, hn::LoadU(d32, relative))));
  };
  for (size_t i = 0; i < static_cast<size_t>(kLanes); i += hn::Lanes(d64)) {
    if constexpr (kLevels == 2) {
      hn::StoreInterleaved4(granule(top + i, base0), granule(bottom + i, base0), granule(top + kLanes + i, base1),
                            granule(bottom + kLanes + i, base1), d64, sequence + 4 * i);
    } else {
      hn::StoreInterleaved2(granule(top + i, base0), granule(bottom + i, base0), d64, sequence + 2 * i);
    }
  }
  constexpr int kCount = 2 * kLevels * kLanes;
  staging.count += kept_first + kCount - 1;
  staging.last = sequence[kCount - 1];
}

// Per footprint shape, how its 4 granules compact: shape bit k - 1 set when tap k's granule
// repeats tap k - 1's (taps t00, t10, t01, t11), bit 3 when t00 repeats the footprint before's
// last; words[shape] the 32-bit lane indices that move the kept 64-bit granules to the front,
// kept[shape] how many there are.
struct FootprintCompaction {
  int32_t words[16][8];
  int kept[16];
  constexpr FootprintCompaction() : words{}, kept{} {
    for (int shape = 0; shape < 16; ++shape) {
      int count = 0;
      for (int tap = 0; tap < 4; ++tap) {
        if ((shape >> (tap == 0 ? 3 : tap - 1)) & 1) continue;
        words[shape][2 * count] = 2 * tap;
        words[shape][2 * count + 1] = 2 * tap + 1;
        ++count;
      }
      kept[shape] = count;
      for (int lane = count; lane < 4; ++lane) {  // anything: overwritten or past the end
        words[shape][2 * lane] = 6;
        words[shape][2 * lane + 1] = 7;
      }
    }
  }
};
inline constexpr FootprintCompaction kFootprintCompaction{};

// Appends a quad's granules, footprints in any shape: the scalar sampler's order (lane by lane,
// level d then, with `levels` 2, d + 1, taps t00, t10, t01, t11), repeats of the previous granule
// removed. Levels share no granule (prepare), so with two levels only taps of one footprint
// repeat each other; with one, a lane's t00 may also repeat the lane before's t11. The quad's
// first granule may repeat the trace's last. relative[t][pair]: tap t's granule relative to the
// pair's level base.
HWY_INLINE void stage_footprints(const FastLevelPair& pair, const int32_t relative[4][kPairs], int levels,
                                 std::vector<uint64_t>& trace, TraceStaging& staging) {
  if (staging.count > TraceStaging::kCapacity - TraceStaging::kMaxPerQuad) staging.flush(trace);
  const uint64_t first = pair.granule_base[0] + static_cast<uint32_t>(relative[0][0]);
  const int kept_first = first != staging.last;
  // As stage_regular: the first granule goes to the slot before the new ones.
  uint64_t* const sequence = staging.granules + staging.count + kept_first;
  int count = 0;
#if HWY_TARGET != HWY_SCALAR
  const hn::CappedTag<uint64_t, kLanes> d64;
  if constexpr (hn::MaxLanes(d64) == static_cast<size_t>(kLanes) &&
                hn::MaxLanes(hn::CappedTag<int32_t, kPairs>()) == static_cast<size_t>(kPairs)) {
    // A footprint's 4 granules on one vector: the kept ones moved to the front and stored whole,
    // the next footprint's store overwriting the rest (kMaxPerQuad leaves room for them).
    const hn::CappedTag<int32_t, kPairs> di;
    const hn::Repartition<uint32_t, decltype(d64)> du32;
    const hn::Rebind<int32_t, decltype(d64)> d32;
    const hn::Rebind<int64_t, decltype(d64)> ds64;
    const auto g00 = hn::Load(di, relative[0]), g10 = hn::Load(di, relative[1]);
    const auto g01 = hn::Load(di, relative[2]), g11 = hn::Load(di, relative[3]);
    alignas(32) int32_t shape[kPairs];
    alignas(32) int32_t footprint[kPairs][4];  // [pair][tap]
    auto shapes = hn::Or(hn::IfThenElseZero(hn::Eq(g10, g00), hn::Set(di, 1)),
                         hn::Or(hn::IfThenElseZero(hn::Eq(g01, g10), hn::Set(di, 2)),
                                hn::IfThenElseZero(hn::Eq(g11, g01), hn::Set(di, 4))));
    if (levels == 1) {
      // Lane k's t00 against lane k - 1's t11 (lane 0's against the trace: kept_first). The
      // load starts one element before relative[3], inside the same array.
      const auto lane_before_last = hn::LoadU(di, &relative[3][0] - 1);
      const auto merges = hn::AndNot(hn::RebindMask(di, hn::FirstN(di, 1)), hn::Eq(g00, lane_before_last));
      shapes = hn::Or(shapes, hn::IfThenElseZero(merges, hn::Set(di, 8)));
    }
    hn::Store(shapes, di, shape);
    hn::StoreInterleaved4(g00, g10, g01, g11, di, &footprint[0][0]);
    const hn::Vec<decltype(d64)> base[2] = {hn::Set(d64, pair.granule_base[0]), hn::Set(d64, pair.granule_base[1])};
    for (int lane = 0; lane < kLanes; ++lane) {
      for (int level = 0; level < levels; ++level) {
        const int p = level * kLanes + lane;
        const auto granules = hn::Add(base[level], hn::BitCast(d64, hn::PromoteTo(ds64, hn::Load(d32, footprint[p]))));
        const auto compact = hn::SetTableIndices(du32, kFootprintCompaction.words[shape[p]]);
        hn::StoreU(hn::BitCast(d64, hn::TableLookupLanes(hn::BitCast(du32, granules), compact)), d64, sequence + count);
        count += kFootprintCompaction.kept[shape[p]];
      }
    }
  } else
#endif
  {
    uint64_t last = first;
    for (int lane = 0; lane < kLanes; ++lane) {
      for (int level = 0; level < levels; ++level) {
        const uint64_t base = pair.granule_base[level];
        for (int t = 0; t < 4; ++t) {
          const uint64_t granule = base + static_cast<uint32_t>(relative[t][level * kLanes + lane]);
          sequence[count] = granule;
          count += granule != last || count == 0;
          last = granule;
        }
      }
    }
  }
  staging.count += kept_first + count - 1;
  staging.last = sequence[count - 1];
}

// Whether every coordinate of `count` lanes at u, v is below 2^23 texels of level 0: limit_u,
// limit_v are kTameLimit / width and / height of level 0 (as floats). Then so is every level's
// texel coordinate u * size - 0.5 (sizes only shrink), well inside the 2^24 that sample_fast
// checks per quad, so a block of quads checks once.
constexpr float kTameLimit = 8388608.0f;
HWY_INLINE bool coordinates_tame(const float* u, const float* v, size_t count, float limit_u, float limit_v) {
  const hn::CappedTag<float, 4 * kLanes> d;
  const auto limits_u = hn::Set(d, limit_u), limits_v = hn::Set(d, limit_v);
  const auto in_limits = [&](size_t i) {
    return hn::And(hn::Lt(hn::Abs(hn::Load(d, u + i)), limits_u), hn::Lt(hn::Abs(hn::Load(d, v + i)), limits_v));
  };
  auto tame = in_limits(0);
  for (size_t i = hn::Lanes(d); i < count; i += hn::Lanes(d)) tame = hn::And(tame, in_limits(i));
  return hn::AllTrue(d, tame);
}

// Pairs i .. i + Lanes(d) of the quad's coordinates `lanes` (4 floats, 16-byte aligned): the
// lanes' own, level after level, so an 8-lane vector takes them twice in one broadcast load.
template <class D>
HWY_INLINE hn::Vec<D> lane_coordinates(D d, const float* lanes, size_t i) {
#if HWY_TARGET != HWY_SCALAR
  if constexpr (hn::MaxLanes(D()) >= static_cast<size_t>(kPairs)) return hn::LoadDup128(d, lanes);
#endif
  return hn::LoadU(d, lanes + i % kLanes);
}

// One quad on a prepared pair (a trilinear job) or level (in.level_count 1): channel c of lane i
// to out[c][offset + i], the trace staged. False, touching nothing the caller keeps, when |u|, |v| or a
// texel coordinate reaches 2^24 (the general path's limit, checked the same way; skipped when
// `tame`, coordinates_tame of the quad's block). `in`: the job (blend, decode tables, trace; its
// levels are pair's). u, v: the 4 lanes' coordinates (each level's pairs take them).
// One instance serves both: a single level runs the trilinear filter on its duplicated level
// with blend 0, which gives the single-level filter's bits (v (1 - 0) + w 0 = v for the finite,
// non-negative filtered values), so the hot loop carries one copy of the code.
HWY_INLINE bool sample_fast(const FastLevelPair& pair, const QuadSample8& in, bool tame, const float* u,
                            const float* v, float* const out[4], size_t offset, TraceStaging* staging) {
  const hn::CappedTag<float, kPairs> d;
  const hn::RebindToSigned<decltype(d)> di;
  const size_t n = hn::Lanes(d);
  const auto limit = hn::Set(d, kMaxExactTexelCoord);
  const auto half = hn::Set(d, 0.5f);
  const auto one = hn::Set(di, 1);
  alignas(32) float a[kPairs], b[kPairs];
  alignas(32) int32_t taps[4][kPairs];    // [tap][pair] texel index in the pair's level
  alignas(32) int32_t packed[4][kPairs];  // [tap][pair] RGBA8 texel
  alignas(32) int32_t relative[4][kPairs];  // [tap][pair] granule relative to the level's base
  bool regular = true;
  for (size_t i = 0; i < static_cast<size_t>(kPairs); i += n) {
    // footprints' operations (OpenGL 4.6 eq. 8.10), with wrap_axis' repeat on power-of-two sizes.
    const auto uu = lane_coordinates(d, u, i), vv = lane_coordinates(d, v, i);
    const auto x = hn::Sub(hn::Mul(uu, hn::Load(d, pair.width_f + i)), half);
    const auto y = hn::Sub(hn::Mul(vv, hn::Load(d, pair.height_f + i)), half);
    if (!tame) {
      const auto exact = hn::And(hn::And(hn::Lt(hn::Abs(uu), limit), hn::Lt(hn::Abs(x), limit)),
                                 hn::And(hn::Lt(hn::Abs(vv), limit), hn::Lt(hn::Abs(y), limit)));
      if (!hn::AllTrue(d, exact)) return false;
    }
    const auto x_floor = hn::Floor(x), y_floor = hn::Floor(y);
    hn::Store(hn::Sub(x, x_floor), d, a + i);
    hn::Store(hn::Sub(y, y_floor), d, b + i);
    const auto x0 = truncate_in_range(di, x_floor), y0 = truncate_in_range(di, y_floor);
    const auto width_mask = hn::Load(di, pair.width_mask + i), height_mask = hn::Load(di, pair.height_mask + i);
    const auto row = hn::Load(di, pair.width + i);
    const auto xa = hn::And(x0, width_mask), xb = hn::And(hn::Add(x0, one), width_mask);
    const auto row_a = hn::Mul(hn::And(y0, height_mask), row);
    const auto row_b = hn::Mul(hn::And(hn::Add(y0, one), height_mask), row);
    const hn::Vec<decltype(di)> tap[4] = {hn::Add(row_a, xa), hn::Add(row_a, xb), hn::Add(row_b, xa),
                                          hn::Add(row_b, xb)};
    const auto word_offset = hn::Load(di, pair.word_offset + i);
    for (int t = 0; t < 4; ++t) {
      hn::Store(tap[t], di, taps[t] + i);
      hn::Store(hn::GatherIndex(di, pair.words, hn::Add(tap[t], word_offset)), di, packed[t] + i);
    }
    if (in.trace) {
      // 16 texels to a granule: texel indices are non-negative, so the shift divides.
      const auto g00 = hn::ShiftRight<4>(tap[0]), g10 = hn::ShiftRight<4>(tap[1]);
      const auto g01 = hn::ShiftRight<4>(tap[2]), g11 = hn::ShiftRight<4>(tap[3]);
      regular &= hn::AllTrue(di, hn::AndNot(hn::Eq(g00, g01), hn::And(hn::Eq(g00, g10), hn::Eq(g01, g11))));
      hn::Store(g00, di, relative[0] + i);
      hn::Store(g10, di, relative[1] + i);
      hn::Store(g01, di, relative[2] + i);
      hn::Store(g11, di, relative[3] + i);
    }
  }
  if (in.trace) {
    if (in.trace_repeats != 1) {
      if (in.level_count == 2) {
        record_trace<2>(in, true, taps, staging);
      } else {
        record_trace<1>(in, true, taps, staging);
      }
    } else if (in.level_count == 2) {
      if (regular) {
        stage_regular<2>(pair, relative[0], relative[2], *in.trace, *staging);
      } else {
        stage_footprints(pair, relative, 2, *in.trace, *staging);
      }
    } else {
      // One level: a lane's first granule may repeat the lane before's last.
      for (int lane = 1; lane < kLanes; ++lane) regular &= relative[0][lane] != relative[3][lane - 1];
      if (regular) {
        stage_regular<1>(pair, relative[0], relative[2], *in.trace, *staging);
      } else {
        stage_footprints(pair, relative, 1, *in.trace, *staging);
      }
    }
  }
  filter_quad<2>(d, in, kPairs, packed, a, b, out, offset);
  return true;
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#endif  // ONTILE_RASTER_TEXTURE_QUAD_FAST_INL_H_
