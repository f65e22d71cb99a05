// Perspective-correct interpolation of fragments from cell planes (see cell_raster.h), compiled
// once per SIMD target by Highway's foreach_target: IEEE add, multiply and divide only, never
// fused multiply-add, in one fixed order, so every target and both entry points (per-fragment
// inputs, whole quads) produce the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/interpolation_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <bit>

#include "raster/cell_raster.h"
#include "raster/interpolation_runs.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

constexpr size_t kFragmentsPerQuad = 4;  // a 2x2 quad's lanes

// Fragments are interpolated in chunks: first the depth and the two perspective weights of every
// fragment of the chunk, then each varying over the whole chunk, so a varying's vertex terms are
// broadcast once per chunk rather than once per vector.
constexpr size_t kChunkFragments = 64;

// The plane gradients and vertex 1/w, broadcast once per call.
template <class D>
struct PlaneTerms {
  hn::Vec<D> l1_dx, l1_dy, l2_dx, l2_dy, z_dx, z_dy, inv_w0, inv_w1, inv_w2;
  PlaneTerms(D d, const InterpolationInput& in)
      : l1_dx(hn::Set(d, in.l1_dx)), l1_dy(hn::Set(d, in.l1_dy)), l2_dx(hn::Set(d, in.l2_dx)),
        l2_dy(hn::Set(d, in.l2_dy)), z_dx(hn::Set(d, in.z_dx)), z_dy(hn::Set(d, in.z_dy)),
        inv_w0(hn::Set(d, in.inv_w[0])), inv_w1(hn::Set(d, in.inv_w[1])),
        inv_w2(hn::Set(d, in.inv_w[2])) {}
};

// Depth and weights of fragments [i, i + Lanes(d)) at offsets fx, fy from their cells' origins
// l1o, l2o, zo: depth_out[i..], w1[i..], w2[i..].
template <class D, class V>
HWY_INLINE void weights_vector(D d, const PlaneTerms<D>& p, V fx, V fy, V l1o, V l2o, V zo,
                               size_t i, float* depth_out, float* w1_out, float* w2_out) {
  const auto zero = hn::Zero(d);
  const auto one = hn::Set(d, 1.0f);
  const auto l1 = hn::Add(hn::Add(l1o, hn::Mul(p.l1_dx, fx)), hn::Mul(p.l1_dy, fy));
  const auto l2 = hn::Add(hn::Add(l2o, hn::Mul(p.l2_dx, fx)), hn::Mul(p.l2_dy, fy));
  auto z = hn::Add(hn::Add(zo, hn::Mul(p.z_dx, fx)), hn::Mul(p.z_dy, fy));
  z = hn::IfThenElse(hn::Lt(z, zero), zero, z);
  z = hn::IfThenElse(hn::Gt(z, one), one, z);
  hn::StoreU(z, d, depth_out + i);
  const auto l0 = hn::Sub(hn::Sub(one, l1), l2);
  // Perspective correction: lambda_i / w_i, normalised (the reciprocal is a true division).
  const auto q0 = hn::Mul(l0, p.inv_w0);
  const auto q1 = hn::Mul(l1, p.inv_w1);
  const auto q2 = hn::Mul(l2, p.inv_w2);
  const auto inv_sum = hn::Div(one, hn::Add(hn::Add(q0, q1), q2));
  hn::StoreU(hn::Mul(q1, inv_sum), d, w1_out + i);
  hn::StoreU(hn::Mul(q2, inv_sum), d, w2_out + i);
}

// v0 + w1 (v1 - v0) + w2 (v2 - v0) for every varying of `count` fragments (a multiple of 4):
// a varying equal at the three vertices (a flat attribute, a material id) comes out exactly,
// whatever the rounding of the weights.
template <class D>
HWY_INLINE void varyings_vector(D d, float v0, float d1, float d2, const float* w1,
                                const float* w2, size_t i, float* out) {
  const auto v = hn::Add(hn::Add(hn::Set(d, v0), hn::Mul(hn::LoadU(d, w1 + i), hn::Set(d, d1))),
                         hn::Mul(hn::LoadU(d, w2 + i), hn::Set(d, d2)));
  hn::StoreU(v, d, out + i);
}

void interpolate_varyings(const InterpolationInput& in, const float* w1, const float* w2,
                          size_t count, float* varyings_out, int stride) {
  const hn::ScalableTag<float> d;
  const hn::CappedTag<float, 4> d4;  // one quad
  const size_t n = hn::Lanes(d);
  for (int k = 0; k < in.varying_count; ++k) {
    if (!((in.varyings_written >> k) & 1u)) continue;  // the functor does not read it
    const float v0 = in.vertex_varyings[0][k];
    const float d1 = in.vertex_varyings[1][k] - v0;
    const float d2 = in.vertex_varyings[2][k] - v0;
    float* out = varyings_out + static_cast<size_t>(k) * stride;
    size_t i = 0;
    for (; i + n <= count; i += n) varyings_vector(d, v0, d1, d2, w1, w2, i, out);
    for (; i < count; i += hn::Lanes(d4)) varyings_vector(d4, v0, d1, d2, w1, w2, i, out);
  }
}

// Whole vectors, then the remaining quads on 4-lane vectors: the same IEEE operations per lane
// at any width, so the bits do not depend on where a run of fragments starts or ends.
void InterpolateKernel(const InterpolationInput& in, int count, float* depth_out,
                       float* varyings_out, int stride) {
  const hn::ScalableTag<float> d;
  const hn::CappedTag<float, 4> d4;  // one quad
  const PlaneTerms<hn::ScalableTag<float>> p(d, in);
  const PlaneTerms<hn::CappedTag<float, 4>> p4(d4, in);
  const size_t n = hn::Lanes(d);
  alignas(64) float w1[kChunkFragments], w2[kChunkFragments];
  for (size_t first = 0; first < static_cast<size_t>(count); first += kChunkFragments) {
    const size_t chunk = std::min(kChunkFragments, static_cast<size_t>(count) - first);
    const auto per_fragment = [&](auto dt, const auto& terms, size_t i) {
      const size_t f = first + i;
      weights_vector(dt, terms, hn::LoadU(dt, in.fx + f), hn::LoadU(dt, in.fy + f),
                     hn::LoadU(dt, in.l1_origin + f), hn::LoadU(dt, in.l2_origin + f),
                     hn::LoadU(dt, in.z_origin + f), i, depth_out + first, w1, w2);
    };
    size_t i = 0;
    for (; i + n <= chunk; i += n) per_fragment(d, p, i);
    for (; i < chunk; i += hn::Lanes(d4)) per_fragment(d4, p4, i);
    interpolate_varyings(in, w1, w2, chunk, varyings_out + first, stride);
  }
}

// Depth and weights of whole quads' fragments [i, i + Lanes(d)): each lane takes its quad's
// values (lane >> 2 of the per-quad arrays read from quad i / 4; vectors narrower than a quad
// stay in one quad) and its offset inside the quad. Offsets are small integers, so the float
// conversion is exact and equals the per-fragment inputs the batcher would have stored.
template <class D>
HWY_INLINE void whole_quad_vector(D d, const PlaneTerms<D>& p, const QuadOrigins& quads,
                                  size_t i, float* depth_out, float* w1, float* w2) {
  const hn::RebindToSigned<D> di;
  alignas(64) static constexpr int32_t kQuadOfLane[16] = {0, 0, 0, 0, 1, 1, 1, 1,
                                                          2, 2, 2, 2, 3, 3, 3, 3};
  const auto quad_of_lane = hn::SetTableIndices(d, kQuadOfLane);
  const auto quad_of_lane_i = hn::SetTableIndices(di, kQuadOfLane);
  const size_t q = i / kFragmentsPerQuad;
  const auto spread = [&](const float* per_quad) {
    return hn::TableLookupLanes(hn::LoadU(d, per_quad + q), quad_of_lane);
  };
  const auto spread_i = [&](const int32_t* per_quad) {
    return hn::TableLookupLanes(hn::LoadU(di, per_quad + q), quad_of_lane_i);
  };
  const auto lane = hn::And(hn::Iota(di, static_cast<int32_t>(i & 3)), hn::Set(di, 3));
  const auto fx = hn::ConvertTo(d, hn::Add(spread_i(quads.ox), hn::And(lane, hn::Set(di, 1))));
  const auto fy = hn::ConvertTo(d, hn::Add(spread_i(quads.oy), hn::ShiftRight<1>(lane)));
  weights_vector(d, p, fx, fy, spread(quads.l1), spread(quads.l2), spread(quads.z), i,
                 depth_out, w1, w2);
}

void InterpolateWholeQuadsKernel(const InterpolationInput& in, const QuadOrigins& quads,
                                 int quad_count, float* depth_out, float* varyings_out,
                                 int stride) {
  const hn::ScalableTag<float> d;
  const hn::CappedTag<float, 4> d4;  // one quad
  static_assert(HWY_MAX_BYTES / sizeof(float) <= 16, "kQuadOfLane covers 16 lanes");
  const PlaneTerms<hn::ScalableTag<float>> p(d, in);
  const PlaneTerms<hn::CappedTag<float, 4>> p4(d4, in);
  const size_t n = hn::Lanes(d);
  const size_t total = static_cast<size_t>(quad_count) * kFragmentsPerQuad;
  // Local copies: the stores below may not alias them.
  const QuadOrigins origins = quads;
  alignas(64) float w1[kChunkFragments], w2[kChunkFragments];
  for (size_t first = 0; first < total; first += kChunkFragments) {
    const size_t chunk = std::min(kChunkFragments, total - first);
    const QuadOrigins at{origins.ox + first / kFragmentsPerQuad, origins.oy + first / kFragmentsPerQuad,
                         origins.l1 + first / kFragmentsPerQuad, origins.l2 + first / kFragmentsPerQuad,
                         origins.z + first / kFragmentsPerQuad};
    size_t i = 0;
    for (; i + n <= chunk; i += n) whole_quad_vector(d, p, at, i, depth_out + first, w1, w2);
    for (; i < chunk; i += hn::Lanes(d4)) whole_quad_vector(d4, p4, at, i, depth_out + first, w1, w2);
    interpolate_varyings(in, w1, w2, chunk, varyings_out + first, stride);
  }
}

// PlaneTerms of one run.
template <class D>
PlaneTerms<D> run_terms(D d, const InterpolationRun& run) {
  InterpolationInput in{};
  in.l1_dx = run.l1_dx;
  in.l1_dy = run.l1_dy;
  in.l2_dx = run.l2_dx;
  in.l2_dy = run.l2_dy;
  in.z_dx = run.z_dx;
  in.z_dy = run.z_dy;
  for (int v = 0; v < 3; ++v) in.inv_w[v] = run.inv_w[v];
  return PlaneTerms<D>(d, in);
}

// Each run as InterpolateWholeQuadsKernel would do it, without a call, a chunk loop and a
// 4-lane tail per run: a run's vectors start at its first quad and its last vector may run on
// into the next run's quads (which that run then overwrites), so only the batch's end takes
// 4-lane vectors. Lanes get the same operations whatever vector they are in.
void InterpolateQuadRunsKernel(const InterpolationRun* runs, int run_count, const QuadOrigins& quads,
                               int quad_count, int varying_count, uint32_t varyings_read,
                               float* depth_out, float* varyings_out, int stride) {
  const hn::ScalableTag<float> d;
  const hn::CappedTag<float, 4> d4;  // one quad
  static_assert(HWY_MAX_BYTES / sizeof(float) <= 16, "kQuadOfLane covers 16 lanes");
  const size_t n = hn::Lanes(d);
  const size_t total = static_cast<size_t>(quad_count) * kFragmentsPerQuad;
  // Local copies: the stores below may not alias them.
  const QuadOrigins origins = quads;
  // A run's weights from its first fragment on, with room for a last vector's overrun.
  alignas(64) float w1[kMaxRunFragments + 16], w2[kMaxRunFragments + 16];
  for (int r = 0; r < run_count; ++r) {
    const InterpolationRun& run = runs[r];
    const size_t first = static_cast<size_t>(run.first_quad) * kFragmentsPerQuad;
    const size_t end = r + 1 < run_count ? static_cast<size_t>(runs[r + 1].first_quad) * kFragmentsPerQuad : total;
    const QuadOrigins at{origins.ox + run.first_quad, origins.oy + run.first_quad,
                         origins.l1 + run.first_quad, origins.l2 + run.first_quad,
                         origins.z + run.first_quad};
    // Whole vectors while they stay inside the batch, then quads.
    const size_t whole_end = std::min(end, total >= n ? total - n + 1 : 0);
    size_t i = 0;
    {
      const PlaneTerms<hn::ScalableTag<float>> p = run_terms(d, run);
      for (; first + i < whole_end; i += n) whole_quad_vector(d, p, at, i, depth_out + first, w1, w2);
    }
    const size_t vector_end = i;
    if (first + i < end) {
      const PlaneTerms<hn::CappedTag<float, 4>> p4 = run_terms(d4, run);
      for (; first + i < end; i += hn::Lanes(d4)) whole_quad_vector(d4, p4, at, i, depth_out + first, w1, w2);
    }
    const size_t run_end = i;
    // The varyings the functor reads, by their bits; the vertex pointers as locals (the stores
    // below are floats, so the run's pointers would be reloaded per varying).
    uint32_t read = varying_count >= 32 ? varyings_read : varyings_read & ((1u << varying_count) - 1u);
    const float* const vertex0 = run.vertex_varyings[0];
    const float* const vertex1 = run.vertex_varyings[1];
    const float* const vertex2 = run.vertex_varyings[2];
    for (; read; read &= read - 1) {
      const int k = std::countr_zero(read);
      const float v0 = vertex0[k];
      const float d1 = vertex1[k] - v0;
      const float d2 = vertex2[k] - v0;
      float* out = varyings_out + static_cast<size_t>(k) * stride + first;
      size_t j = 0;
      for (; j < vector_end; j += n) varyings_vector(d, v0, d1, d2, w1, w2, j, out);
      for (; j < run_end; j += hn::Lanes(d4)) varyings_vector(d4, v0, d1, d2, w1, w2, j, out);
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(InterpolateKernel);
HWY_EXPORT(InterpolateWholeQuadsKernel);
HWY_EXPORT(InterpolateQuadRunsKernel);

void interpolate_quad_runs(const InterpolationRun* runs, int run_count, const QuadOrigins& quads,
                           int quad_count, int varying_count, uint32_t varyings_read,
                           float* depth_out, float* varyings_out, int varyings_stride) {
  HWY_DYNAMIC_DISPATCH(InterpolateQuadRunsKernel)(runs, run_count, quads, quad_count, varying_count,
                                                  varyings_read, depth_out, varyings_out,
                                                  varyings_stride);
}

void interpolate_fragments(const InterpolationInput& in, int count, float* depth_out,
                           float* varyings_out, int varyings_stride) {
  HWY_DYNAMIC_DISPATCH(InterpolateKernel)(in, count, depth_out, varyings_out, varyings_stride);
}

void interpolate_whole_quads(const InterpolationInput& in, const QuadOrigins& quads,
                             int quad_count, float* depth_out, float* varyings_out,
                             int varyings_stride) {
  HWY_DYNAMIC_DISPATCH(InterpolateWholeQuadsKernel)(in, quads, quad_count, depth_out,
                                                    varyings_out, varyings_stride);
}

}  // namespace ontile
#endif  // HWY_ONCE
