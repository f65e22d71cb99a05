// SIMD quad sampler (see texture_quad_simd.h), compiled per target by Highway's foreach_target.
// Only IEEE multiply, add, subtract and floor: every target gives the bits of the scalar path.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/texture_quad_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/texture_quad_simd.h"
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
constexpr float kMaxExactTexelCoord = 16777216.0f;  // as texture.cpp

// Per level and lane: the top-left texel of the bilinear footprint and the weights a, b.
struct Footprints {
  int32_t i0[2][kLanes], j0[2][kLanes];
  float a[2][kLanes], b[2][kLanes];
};

// x = u * size - 0.5, i0 = floor(x), a = x - i0 (OpenGL 4.6 eq. 8.10), for one axis of one
// level. False when |u| or |x| reach 2^24 (the scalar path reduces those first).
template <class D>
bool axis(D d, const float* u, int size, int32_t* i0_out, float* a_out) {
  const hn::RebindToSigned<D> di;
  const size_t n = hn::Lanes(d);
  const auto limit = hn::Set(d, kMaxExactTexelCoord);
  for (size_t i = 0; i < kLanes; i += n) {
    const auto uu = hn::LoadU(d, u + i);
    const auto x = hn::Sub(hn::Mul(uu, hn::Set(d, static_cast<float>(size))), hn::Set(d, 0.5f));
    if (!hn::AllTrue(d, hn::And(hn::Lt(hn::Abs(uu), limit), hn::Lt(hn::Abs(x), limit)))) return false;
    const auto x_floor = hn::Floor(x);
    hn::StoreU(hn::ConvertTo(di, x_floor), di, i0_out + i);
    hn::StoreU(hn::Sub(x, x_floor), d, a_out + i);
  }
  return true;
}

// Texel indices of the footprints of one level for the 4 lanes, as t00, t10, t01, t11 per lane.
// Footprints wholly inside the level (the common case) need no wrapping: rows and columns are
// consecutive. Others go through bilinear_footprint, the scalar sampler's own function.
// The two texel columns (or rows) of footprints starting at `first` along an axis of `size`
// texels, wrapped as wrap_texel_index does: identity inside the level, a mask for repeat on a
// power-of-two size, a clamp for clamp-to-edge. False when a lane needs another wrap (mirrored
// repeat, or repeat on another size, outside the level): the caller takes the scalar path.
template <class DI>
bool wrap_axis(DI di, hn::Vec<DI> first, int size, WrapMode mode, hn::Vec<DI>& lo, hn::Vec<DI>& hi) {
  const auto second = hn::Add(first, hn::Set(di, 1));
  const auto last = hn::Set(di, size - 1);
  if (mode == WrapMode::Repeat && (size & (size - 1)) == 0) {
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

// Texel indices of the footprints of one level for the 4 lanes, as t00, t10, t01, t11 per lane,
// with the texels bilinear_footprint (the scalar sampler's function) selects.
template <class DI>
HWY_INLINE void footprint_taps(DI di, const Texture2D::Level& level, const int32_t* i0, const int32_t* j0,
                    WrapMode wrap_u, WrapMode wrap_v, int32_t taps[4][kLanes]) {
  const size_t n = hn::Lanes(di);
  const auto row = hn::Set(di, level.width);
  for (size_t i = 0; i < kLanes; i += n) {
    hn::Vec<DI> xa, xb, ya, yb;
    if (!wrap_axis(di, hn::LoadU(di, i0 + i), level.width, wrap_u, xa, xb) ||
        !wrap_axis(di, hn::LoadU(di, j0 + i), level.height, wrap_v, ya, yb)) {
      for (int lane = 0; lane < kLanes; ++lane) {
        size_t t[4];
        bilinear_footprint(i0[lane], j0[lane], level.width, level.height, wrap_u, wrap_v, t);
        for (int k = 0; k < 4; ++k) taps[k][lane] = static_cast<int32_t>(t[k]);
      }
      return;
    }
    const auto row_a = hn::Mul(ya, row), row_b = hn::Mul(yb, row);
    hn::StoreU(hn::Add(row_a, xa), di, taps[0] + i);
    hn::StoreU(hn::Add(row_a, xb), di, taps[1] + i);
    hn::StoreU(hn::Add(row_b, xa), di, taps[2] + i);
    hn::StoreU(hn::Add(row_b, xb), di, taps[3] + i);
  }
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
// Granules are computed on 64-bit lanes for uncompressed 4-byte texels (every 8-bit texture not
// block-compressed); block-compressed levels map each texel to its block's address. staging:
// where a batch call gathers them, or null to append to in.trace.
void record_trace(const QuadSample8& in, const int32_t taps[2][4][kLanes], TraceStaging* staging) {
  alignas(32) uint64_t granule[2][4][kLanes];  // [level][tap][lane]
  const hn::CappedTag<uint64_t, kLanes> d64;
  const hn::Rebind<int64_t, decltype(d64)> ds64;
  const hn::Rebind<int32_t, decltype(d64)> d32;
  const size_t n = hn::Lanes(d64);
  const int levels = in.level_count;
  for (int l = 0; l < levels; ++l) {
    const Texture2D::Level& level = *in.levels[l];
    if (level.memory_bytes_per_texel == 4 && level.block_bytes == 0) {
      const auto base = hn::Set(d64, level.address);
      for (int t = 0; t < 4; ++t) {
        for (size_t i = 0; i < kLanes; i += n) {
          const auto texel = hn::BitCast(d64, hn::PromoteTo(ds64, hn::LoadU(d32, taps[l][t] + i)));
          hn::Store(hn::ShiftRight<6>(hn::Add(base, hn::ShiftLeft<2>(texel))), d64, granule[l][t] + i);
        }
      }
      continue;
    }
    for (int t = 0; t < 4; ++t) {
      for (int lane = 0; lane < kLanes; ++lane) {
        granule[l][t][lane] = level.texel_byte_address(static_cast<size_t>(taps[l][t][lane])) >> 6;
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
  const uint64_t first = in.levels[0]->texel_byte_address(static_cast<size_t>(taps[0][0][0])) >> 6;
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
  // compare at a time; checked here on lanes, footprint by footprint.
  bool regular = true;
  for (size_t i = 0; i < kLanes; i += n) {
    for (int l = 0; l < levels; ++l) {
      const auto t00 = hn::Load(d64, granule[l][0] + i), t10 = hn::Load(d64, granule[l][1] + i);
      const auto t01 = hn::Load(d64, granule[l][2] + i), t11 = hn::Load(d64, granule[l][3] + i);
      auto same_rows = hn::AndNot(hn::Eq(t00, t01), hn::And(hn::Eq(t00, t10), hn::Eq(t01, t11)));
      if (l == 1) same_rows = hn::AndNot(hn::Eq(t00, hn::Load(d64, granule[0][3] + i)), same_rows);
      regular = regular && hn::AllTrue(d64, same_rows);
    }
  }
  for (int lane = 1; lane < kLanes; ++lane) {
    regular = regular && granule[0][0][lane] != granule[levels - 1][3][lane - 1];
  }
  if (regular) {
    // sequence[0] is written again with the first granule, the same value.
    int count = 0;
    for (int lane = 0; lane < kLanes; ++lane) {
      for (int l = 0; l < levels; ++l) {
        sequence[count] = granule[l][0][lane];
        sequence[count + 1] = granule[l][2][lane];
        count += 2;
      }
    }
    last = sequence[count - 1];
    tail_count = count - 1;
  } else {
    for (int lane = 0; lane < kLanes; ++lane) {
      for (int l = 0; l < levels; ++l) {
        for (int t = 0; t < 4; ++t) {
          const uint64_t g = granule[l][t][lane];
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

// One quad: result[c][lane]. False, touching nothing, when it needs the general path.
// u, v: the 4 lanes' finite coordinates (in.uv is not read).
HWY_INLINE bool sample_one(const QuadSample8& in, const float* u, const float* v,
                           float result[4][kLanes], TraceStaging* staging) {
  const hn::CappedTag<float, kLanes> d;
  const hn::RebindToSigned<decltype(d)> di;
  // With one level, level 1's lanes are filtered too but not used: they are zeroed below (a
  // whole zero-initialisation per quad cost 34 instructions of `rep stos`).
  Footprints fp;
  alignas(16) int32_t taps[2][4][kLanes];  // [level][tap][lane] texel index in the level
  for (int l = 0; l < in.level_count; ++l) {
    const Texture2D::Level& level = *in.levels[l];
    // Texel indices are int32 lanes: a level of 2^31 texels or more (8 GiB) takes the scalar path.
    if (static_cast<uint64_t>(level.width) * static_cast<uint64_t>(level.height) >= (uint64_t{1} << 31)) {
      return false;
    }
    if (!axis(d, u, level.width, fp.i0[l], fp.a[l]) || !axis(d, v, level.height, fp.j0[l], fp.b[l])) {
      return false;
    }
    footprint_taps(di, level, fp.i0[l], fp.j0[l], in.wrap_u, in.wrap_v, taps[l]);
  }
  if (in.trace) record_trace(in, taps, staging);
  // Texels: one 32-bit RGBA8 load per tap, level and lane, laid out [tap][level * 4 + lane] so
  // that both levels' bilinear filters run on the same 8 lanes (two 4-lane vectors on targets
  // with 128-bit vectors); each channel is decoded through its table on the lanes at once. A
  // lane's operations are those of the one-level filter, so every target gives the same bits.
  constexpr int kPairs = 2 * kLanes;  // (level, lane)
  const size_t n = hn::Lanes(d);
  alignas(32) int32_t packed[4][kPairs];
  if (in.level_count == 1) {
    std::memset(fp.a[1], 0, sizeof fp.a[1]);
    std::memset(fp.b[1], 0, sizeof fp.b[1]);
    for (int t = 0; t < 4; ++t) std::memset(packed[t] + kLanes, 0, sizeof(int32_t) * kLanes);
  }
  for (int l = 0; l < in.level_count; ++l) {
    const uint8_t* texels = in.levels[l]->bytes8();
    if (reinterpret_cast<uintptr_t>(texels) % alignof(int32_t) == 0) {
      // Texel t of a level is the int32 at index t: gathered on lanes.
      const int32_t* words = reinterpret_cast<const int32_t*>(texels);
      for (int t = 0; t < 4; ++t) {
        for (size_t i = 0; i < kLanes; i += n) {
          hn::Store(hn::GatherIndex(di, words, hn::Load(di, taps[l][t] + i)), di,
                    packed[t] + l * kLanes + i);
        }
      }
      continue;
    }
    for (int t = 0; t < 4; ++t) {
      for (int lane = 0; lane < kLanes; ++lane) {
        std::memcpy(&packed[t][l * kLanes + lane], texels + static_cast<size_t>(taps[l][t][lane]) * 4, 4);
      }
    }
  }
  const hn::CappedTag<float, kPairs> d8;
  const hn::RebindToSigned<decltype(d8)> di8;
  const size_t n8 = hn::Lanes(d8);
  const auto byte_mask = hn::Set(di8, 0xFF);
  const auto one8 = hn::Set(d8, 1.0f);
  alignas(32) float filtered[4][kPairs];  // [channel][level * 4 + lane]
  // Both levels' lanes always (level 1's are zero with one level): no lane of `filtered` is left
  // unwritten, and 8-lane targets run this once either way.
  for (size_t i = 0; i < static_cast<size_t>(kPairs); i += n8) {
    hn::Vec<decltype(d8)> tap_value[4][4];  // [tap][channel]
    for (int t = 0; t < 4; ++t) {
      const auto p = hn::Load(di8, packed[t] + i);
      tap_value[t][0] = hn::GatherIndex(d8, in.rgb_decode, hn::And(p, byte_mask));
      tap_value[t][1] = hn::GatherIndex(d8, in.rgb_decode, hn::And(hn::ShiftRight<8>(p), byte_mask));
      tap_value[t][2] = hn::GatherIndex(d8, in.rgb_decode, hn::And(hn::ShiftRight<16>(p), byte_mask));
      tap_value[t][3] = hn::GatherIndex(d8, in.alpha_decode, hn::And(hn::ShiftRight<24>(p), byte_mask));
    }
    const auto a = hn::LoadU(d8, &fp.a[0][0] + i), b = hn::LoadU(d8, &fp.b[0][0] + i);
    const auto one_a = hn::Sub(one8, a), one_b = hn::Sub(one8, b);
    for (int c = 0; c < 4; ++c) {
      const auto top = hn::Add(hn::Mul(tap_value[0][c], one_a), hn::Mul(tap_value[1][c], a));
      const auto bottom = hn::Add(hn::Mul(tap_value[2][c], one_a), hn::Mul(tap_value[3][c], a));
      hn::Store(hn::Add(hn::Mul(top, one_b), hn::Mul(bottom, b)), d8, filtered[c] + i);
    }
  }
  const auto one = hn::Set(d, 1.0f);
  for (size_t i = 0; i < kLanes; i += n) {
    for (int c = 0; c < 4; ++c) {
      auto value = hn::Load(d, filtered[c] + i);
      if (in.level_count == 2) {
        const auto w = hn::Set(d, in.blend);
        value = hn::Add(hn::Mul(value, hn::Sub(one, w)), hn::Mul(hn::Load(d, filtered[c] + kLanes + i), w));
      }
      hn::StoreU(value, d, result[c] + i);
    }
  }
  return true;
}

bool SampleQuad8Kernel(const QuadSample8& in, glm::vec4* out) {
  float u[kLanes], v[kLanes];
  for (int lane = 0; lane < kLanes; ++lane) {
    u[lane] = in.uv[lane].x;
    v[lane] = in.uv[lane].y;
  }
  alignas(16) float result[4][kLanes];
  if (!sample_one(in, u, v, result, nullptr)) return false;
  for (int lane = 0; lane < kLanes; ++lane) {
    out[lane] = {result[0][lane], result[1][lane], result[2][lane], result[3][lane]};
  }
  return true;
}

// Texture2D::sample_quads' jobs (quad q, read r) from position `first` = q * read_count + r on,
// in that order (texture.cpp's quad_lambda and linear8_job, operation for operation); returns
// the position of the first job that needs the general path, or quad_count * read_count.
int SampleQuadBatch8Kernel(const QuadBatch8& batch, int first) {
  const hn::CappedTag<float, kLanes> d;
  QuadSample8 jobs[QuadBatch8::kMaxReads];
  for (int r = 0; r < batch.read_count; ++r) {
    const BatchRead8& read = batch.reads[r];
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
  for (int q = first_quad; q < batch.quad_count; ++q, first_read = 0) {
    const int f0 = q * kLanes;
    // finite_or_zero on lanes: |x| < inf is false for NaN and infinities.
    alignas(16) float u[kLanes], v[kLanes];
    const auto inf = hn::Set(d, std::numeric_limits<float>::infinity());
    for (size_t i = 0; i < kLanes; i += hn::Lanes(d)) {
      const auto raw_u = hn::LoadU(d, batch.u + f0 + i), raw_v = hn::LoadU(d, batch.v + f0 + i);
      hn::Store(hn::IfThenElseZero(hn::Lt(hn::Abs(raw_u), inf), raw_u), d, u + i);
      hn::Store(hn::IfThenElseZero(hn::Lt(hn::Abs(raw_v), inf), raw_v), d, v + i);
    }
    for (int r = first_read; r < batch.read_count; ++r) {
      const BatchRead8& read = batch.reads[r];
      QuadSample8& job = jobs[r];
      // quad_lambda: rho = max(|d(uv)/dx|, |d(uv)/dy|) in texels of level 0 (OpenGL 4.6 eq. 8.7).
      const float width = static_cast<float>(read.levels[0].width);
      const float height = static_cast<float>(read.levels[0].height);
      const float dx_u = (u[1] - u[0]) * width, dx_v = (v[1] - v[0]) * height;
      const float dy_u = (u[2] - u[0]) * width, dy_v = (v[2] - v[0]) * height;
      const float rho = std::max(std::sqrt(dx_u * dx_u + dx_v * dx_v), std::sqrt(dy_u * dy_u + dy_v * dy_v));
      float lambda = std::log2(rho) + read.lod_bias;
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
      alignas(16) float result[4][kLanes];
      if (!sample_one(job, u, v, result, &staging)) return finish(q * batch.read_count + r);
      for (int c = 0; c < 4; ++c) std::memcpy(read.out[c] + f0, result[c], sizeof result[c]);
    }
  }
  return finish(batch.quad_count * batch.read_count);
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
