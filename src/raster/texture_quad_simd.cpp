// SIMD quad sampler (see texture_quad_simd.h), compiled per target by Highway's foreach_target:
// the batch driver (level of detail and level selection per block of quads, then each job on
// the fast path of texture_quad_fast-inl.h or the general one below). Only IEEE multiply, add,
// subtract, square root and floor: every target gives the bits of the scalar path.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/texture_quad_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/texture_quad_footprint-inl.h"
#include "raster/texture_quad_trace-inl.h"
#include "raster/texture_quad_filter-inl.h"
#include "raster/texture_quad_fast-inl.h"
#include "raster/texture_quad_lod-inl.h"

#include "raster/log2_exact.h"
#include "raster/texture_quad_simd.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <new>

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
  filter_quad<kLevels>(d8, in, pairs, packed, a, b, out, 0);
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

// What the batch driver keeps per read. Each thread keeps kMaxReads of them from one batch call to
// the next (thread_read_states): a shader's consecutive batches mostly read the same textures, and
// a call (about 14 quads in the atrium frame) prepared its level pairs anew, about 120
// instructions each, more than a quad's driver work.
struct ReadState {
  const BatchRead8* source = nullptr;  // the batch call's read
  QuadSample8 job;
  // The level pair of the read's last trilinear job and the level of its last single-level
  // job, prepared for sample_fast.
  FastLevelPair fast_pair, fast_single;
  // Of the levels facts_level and the one after it (when there is one).
  LevelFacts facts;
  const Texture2D::Level* facts_level = nullptr;
  // What the prepared pairs and facts depend on: the read's texture (its levels, told apart from
  // a later texture at the same place by the first level's address, unique to a texture for the
  // process's life), its level count and its wraps. Level 0's size as floats, for the LOD and
  // coordinates_tame.
  const Texture2D::Level* levels = nullptr;
  uint64_t address = 0;
  float max_level = 0.0f;
  WrapMode wrap_u = WrapMode::Repeat, wrap_v = WrapMode::Repeat;
  float width = 0.0f, height = 0.0f;
  float limit_u = 0.0f, limit_v = 0.0f;  // coordinates_tame's limits
  // The block's quads (kLanes of them): lambda, level d, weight of level d + 1 (see
  // sample_quad_batch).
  alignas(16) float lambda[kLanes];
  alignas(16) int32_t level[kLanes];
  alignas(16) float blend[kLanes];
  bool tame = false;  // coordinates_tame of the block

  // Takes the batch call's read: keeps what it prepared for the same texture and wraps. Not
  // inlined: the loop over reads around it was vectorised with alias checks (about 380
  // instructions a call).
  HWY_NOINLINE void take(const BatchRead8& read, const QuadBatch8& batch) {
    source = &read;
    job.wrap_u = read.wrap_u;
    job.wrap_v = read.wrap_v;
    job.rgb_decode = read.rgb_decode;
    job.alpha_decode = read.alpha_decode;
    job.trace = batch.trace;
    job.last_granule = batch.last_granule;
    job.trace_repeats = read.trace_repeats;
    if (levels == read.levels && address == read.levels[0].address && max_level == read.max_level &&
        wrap_u == read.wrap_u && wrap_v == read.wrap_v) {
      return;
    }
    levels = read.levels;
    address = read.levels[0].address;
    max_level = read.max_level;
    wrap_u = read.wrap_u;
    wrap_v = read.wrap_v;
    fast_pair.first = nullptr;
    fast_single.first = nullptr;
    facts_level = nullptr;
    width = static_cast<float>(read.levels[0].width);
    height = static_cast<float>(read.levels[0].height);
    limit_u = kTameLimit / width;
    limit_v = kTameLimit / height;
  }
};

// The calling thread's read states. A batch call runs no other batch call on its thread
// (after_quad hooks only trace), so one set serves. Not constinit: ReadState leaves its lane
// arrays to be written before use, which clang rejects in a constant initializer (they start
// zeroed as every thread_local does). Not inlined: inlined, the thread-local address was
// computed again in the block loop, a call to the TLS resolver with the vector registers saved
// around it.
HWY_NOINLINE ReadState* thread_read_states() {
  static thread_local ReadState states[QuadBatch8::kMaxReads];
  return states;
}

// Texture2D::sample_quads' jobs (quad q, read r) from position `first` = q * read_count + r on,
// in that order (texture.cpp's quad_lambda and linear8_job, operation for operation); returns
// the position of the first job that needs the general path, or quad_count * read_count.
// kAfterQuad: batch.after_quad traces after each quad (a separate instance, so batches without
// a hook pay nothing per quad).
template <bool kAfterQuad>
int sample_quad_batch(const QuadBatch8& batch, int first) {
  const hn::CappedTag<float, kLanes> d;
  constexpr int kBlockQuads = kLanes;
  ReadState* const states = thread_read_states();
  for (int r = 0; r < batch.read_count; ++r) states[r].take(batch.reads[r], batch);
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
  const int read_count = batch.read_count;
  const int first_quad = first / read_count;
  int first_read = first - first_quad * read_count;
  // Quads a block of 4 at a time: the block's coordinates made finite (finite_or_zero on lanes:
  // |x| < inf is false for NaN and infinities), then quad_lambda's rho = max(|d(uv)/dx|,
  // |d(uv)/dy|) in texels of level 0 (OpenGL 4.6 eq. 8.7) for each read, one quad per lane: the
  // scalar operations on lanes, std::max as a compare and select.
  for (int block = first_quad; block < batch.quad_count; block += kBlockQuads) {
    const int quads = std::min(kBlockQuads, batch.quad_count - block);
    alignas(64) float block_u[kBlockQuads * kLanes], block_v[kBlockQuads * kLanes];  // [quad][lane]
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
    const hn::CappedTag<float, kBlockQuads * kLanes> d_block;
    for (size_t i = 0; i < static_cast<size_t>(kBlockQuads * kLanes); i += hn::Lanes(d_block)) {
      const auto uu = hn::LoadU(d_block, raw_u + i), vv = hn::LoadU(d_block, raw_v + i);
      const auto inf = hn::Set(d_block, std::numeric_limits<float>::infinity());
      hn::Store(hn::IfThenElseZero(hn::Lt(hn::Abs(uu), inf), uu), d_block, block_u + i);
      hn::Store(hn::IfThenElseZero(hn::Lt(hn::Abs(vv), inf), vv), d_block, block_v + i);
    }
    alignas(16) float rho[QuadBatch8::kMaxReads][kBlockQuads];  // [read][quad of the block]
    for (size_t i = 0; i < static_cast<size_t>(kBlockQuads); i += hn::Lanes(d)) {
      hn::Vec<decltype(d)> u0, u1, u2, u3, v0, v1, v2, v3;
      hn::LoadInterleaved4(d, block_u + i * kLanes, u0, u1, u2, u3);
      hn::LoadInterleaved4(d, block_v + i * kLanes, v0, v1, v2, v3);
      const auto du_dx = hn::Sub(u1, u0), dv_dx = hn::Sub(v1, v0);
      const auto du_dy = hn::Sub(u2, u0), dv_dy = hn::Sub(v2, v0);
      for (int r = 0; r < read_count; ++r) {
        const auto width = hn::Set(d, states[r].width);
        const auto height = hn::Set(d, states[r].height);
        const auto dx_u = hn::Mul(du_dx, width), dx_v = hn::Mul(dv_dx, height);
        const auto dy_u = hn::Mul(du_dy, width), dy_v = hn::Mul(dv_dy, height);
        const auto rho_x = hn::Sqrt(hn::Add(hn::Mul(dx_u, dx_u), hn::Mul(dx_v, dx_v)));
        const auto rho_y = hn::Sqrt(hn::Add(hn::Mul(dy_u, dy_u), hn::Mul(dy_v, dy_v)));
        hn::Store(hn::IfThenElse(hn::Lt(rho_x, rho_y), rho_y, rho_x), d, rho[r] + i);
      }
    }
    // lambda = log2_exact(rho) + lod_bias on lanes, or per quad where a lane's rho is not a
    // normal positive float. Quads past the batch's end take rho 1. Then linear8_job's level
    // selection on lanes for Linear and None mipmaps: level d and the weight of level d + 1
    // (0: level d alone); Nearest selects per quad below.
    for (int r = 0; r < read_count; ++r) {
      const BatchRead8& read = batch.reads[r];
      ReadState& state = states[r];
      for (int j = quads; j < kBlockQuads; ++j) rho[r][j] = 1.0f;
      if (!log2_exact_lanes(rho[r], read.lod_bias, state.lambda)) {
        for (int j = 0; j < kBlockQuads; ++j) state.lambda[j] = log2_exact(rho[r][j]) + read.lod_bias;
      }
      state.tame = coordinates_tame(block_u, block_v, kBlockQuads * kLanes, state.limit_u, state.limit_v);
      if (read.mipmap_mode == MipmapMode::Nearest) continue;
      const hn::RebindToSigned<decltype(d)> di;
      for (size_t i = 0; i < static_cast<size_t>(kBlockQuads); i += hn::Lanes(d)) {
        const auto lambda = hn::Load(d, state.lambda + i);
        // std::min(lambda, max_level) is lambda unless max_level < lambda; NaN is not > 0.
        const auto mipmapped = read.mipmap_mode == MipmapMode::Linear ? hn::Gt(lambda, hn::Zero(d)) : hn::FirstN(d, 0);
        const auto max_level = hn::Set(d, read.max_level);
        const auto clamped = hn::IfThenElse(hn::Lt(max_level, lambda), max_level, lambda);
        const auto level = hn::Floor(clamped);
        hn::Store(hn::IfThenElseZero(hn::RebindMask(di, mipmapped), hn::ConvertTo(di, level)), di, state.level + i);
        hn::Store(hn::IfThenElseZero(mipmapped, hn::Sub(clamped, level)), d, state.blend + i);
      }
    }
    for (int j = 0; j < quads; ++j, first_read = 0) {
      const int q = block + j;
      const int f0 = q * kLanes;
      const float* quad_u = block_u + j * kLanes;  // the quad's 4 finite coordinates
      const float* quad_v = block_v + j * kLanes;
      for (int r = first_read; r < read_count; ++r) {
        ReadState& state = states[r];
        const BatchRead8& read = *state.source;
        QuadSample8& job = state.job;
        bool trilinear = false;
        if (read.mipmap_mode != MipmapMode::Nearest) {
          const int level = state.level[j];
          const float blend = state.blend[j];
          trilinear = blend != 0.0f;
          job.levels[0] = &read.levels[level];
          job.level_count = 1;
          job.blend = 0.0f;
          if (trilinear) {
            job.levels[1] = &read.levels[level + 1];
            job.level_count = 2;
            job.blend = blend;
          }
        } else {
          // linear8_job's level selection for Nearest mipmaps.
          float lambda = state.lambda[j];
          job.level_count = 1;
          job.blend = 0.0f;
          if (lambda > 0.0f) {
            lambda = std::min(lambda, read.max_level);
            const int single_level = lambda <= 0.5f ? 0 : static_cast<int>(std::ceil(lambda + 0.5f)) - 1;
            job.levels[0] = &read.levels[single_level];
          } else {
            job.levels[0] = &read.levels[0];
          }
        }
        // The common case on its fast path: level pairs for trilinear jobs, single levels for the
        // rest, each prepared when a read's job moves to another level.
        FastLevelPair& prepared = trilinear ? state.fast_pair : state.fast_single;
        if (prepared.first != job.levels[0]) {
          const int levels_after = static_cast<int>(read.max_level) - static_cast<int>(job.levels[0] - read.levels);
          if (trilinear) {
            prepared.prepare<2>(job.levels[0], levels_after, read.wrap_u, read.wrap_v);
          } else {
            prepared.prepare<1>(job.levels[0], levels_after, read.wrap_u, read.wrap_v);
          }
        }
        if (prepared.usable) {
          if (!sample_fast(prepared, job, state.tame, quad_u, quad_v, read.out, static_cast<size_t>(f0), &staging)) {
            return finish(q * batch.read_count + r);
          }
          continue;
        }
        if (job.levels[0] != state.facts_level) {
          state.facts_level = job.levels[0];
          const int level = static_cast<int>(job.levels[0] - read.levels);
          state.facts = LevelFacts::of(job.levels[0], std::min(2, static_cast<int>(read.max_level) - level + 1));
        }
        // u, v: the 4 lanes' coordinates twice (pairs), as sample_one takes them.
        alignas(32) float u[kPairs], v[kPairs];
        for (int pair = 0; pair < kPairs; ++pair) {
          u[pair] = quad_u[pair % kLanes];
          v[pair] = quad_v[pair % kLanes];
        }
        float* const out[4] = {read.out[0] + f0, read.out[1] + f0, read.out[2] + f0, read.out[3] + f0};
        if (!sample_job(job, state.facts, u, v, out, &staging)) return finish(q * batch.read_count + r);
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
