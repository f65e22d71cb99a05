// Footprints of the SIMD quad sampler (texture_quad_simd.cpp): per (level, lane) pair, the bilinear
// weights and the 4 wrapped texel indices, and the facts about a job's levels that select the fast ways.
// Compiled once per SIMD target: foreach_target re-includes this file from texture_quad_simd.cpp,
// hence the toggling guard instead of #pragma once.
#if defined(ONTILE_RASTER_TEXTURE_QUAD_FOOTPRINT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ONTILE_RASTER_TEXTURE_QUAD_FOOTPRINT_INL_H_
#undef ONTILE_RASTER_TEXTURE_QUAD_FOOTPRINT_INL_H_
#else
#define ONTILE_RASTER_TEXTURE_QUAD_FOOTPRINT_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "raster/texel_wrap.h"
#include "raster/texture_quad_simd.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

constexpr int kLanes = 4;
constexpr int kPairs = 2 * kLanes;  // (level, lane) pairs, laid out level * 4 + lane
constexpr float kMaxExactTexelCoord = 16777216.0f;  // as texture.cpp

// ConvertTo(di, v) for lanes known to be below 2^31 in magnitude (texel coordinates under 2^24):
// on x86 the bare truncating conversion, without the fix-up Highway adds for lanes that overflow
// (four more instructions a vector), so the same integers.
template <class DI, class VF>
HWY_INLINE hn::Vec<DI> truncate_in_range(DI di, VF v) {
#if HWY_ARCH_X86 && HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128
  if constexpr (sizeof(v.raw) == 32) {
    return hn::Vec<DI>{_mm256_cvttps_epi32(v.raw)};
  } else if constexpr (sizeof(v.raw) == 16) {
    return hn::Vec<DI>{_mm_cvttps_epi32(v.raw)};
  }
#endif
  return hn::ConvertTo(di, v);
}

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
    hn::Store(truncate_in_range(di, x_floor), di, i0 + i);
    hn::Store(truncate_in_range(di, y_floor), di, j0 + i);
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

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#endif  // ONTILE_RASTER_TEXTURE_QUAD_FOOTPRINT_INL_H_
