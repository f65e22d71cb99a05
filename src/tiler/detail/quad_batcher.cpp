// Batched shading of a tile's triangles (see quad_batcher.h): the batch's triangles and draw
// state, interpolation and the functor call; the writes are in quad_write_back.cpp.
#include "tiler/detail/quad_batcher.h"

#include <atomic>
#include <cstring>

#include "raster/blend.h"
#include "raster/interpolation_runs.h"
#include "raster/pixel_quantize_simd.h"
#include "tiler/detail/hierarchical_depth.h"

namespace ontile {
namespace {

std::atomic<bool> batches_across_triangles_enabled{true};

static_assert(kMaxRunFragments == kBatchFragments, "a batch is interpolated in one call");

// Coverage bits of sample 0 in every lane; shifted left by s for sample s.
constexpr QuadCoverage kSampleBits = 1u | (1u << kMaxSamples) | (1u << (2 * kMaxSamples)) |
                                     (1u << (3 * kMaxSamples));

int unorm_bits_of(const RenderPassDesc& pass) {
  if (pass.depth_index < 0) return 0;
  const PixelFormat f = pass.attachments[pass.depth_index].format;
  return f == PixelFormat::D16_UNORM ? 16 : f == PixelFormat::D24S8 ? 24 : 0;
}

}  // namespace

DrawState::DrawState(const RenderPassDesc& pass, const SubpassDesc& subpass, const DrawCall& draw) {
  has_depth = pass.depth_index >= 0;
  depth_test = has_depth && draw.raster.depth_test;
  depth_write = has_depth && draw.raster.depth_write && !subpass.depth_read_only;
  late_z = draw.fragment_shader && draw.fragment_shader->may_discard();
  per_sample = draw.fragment_shader && draw.fragment_shader->per_sample_shading();
  write_color = draw.fragment_shader != nullptr;
  depth_unorm_bits = unorm_bits_of(pass);
  hiz_tracked = has_depth;
  hiz_enabled = depth_test && !late_z && HierarchicalDepth::usable(draw.raster.depth_compare);
}

TriangleContext::TriangleContext(const RenderPassDesc& pass_, const SubpassDesc& subpass_,
                                 const DrawCall& draw_, const BinnedTriangle& tri_,
                                 const float* varyings_, int varying_count_,
                                 const SamplePattern& pattern_, const TileRect& rect_,
                                 const FramebufferFetch* fetch_, uint32_t triangle_ref_,
                                 std::vector<FragmentAccess>* fragments_, const DrawState& state)
    : pass(pass_), subpass(subpass_), draw(draw_), tri(tri_), varyings(varyings_),
      varying_count(varying_count_), pattern(pattern_), rect(rect_), fetch(fetch_),
      triangle_ref(triangle_ref_), fragments(fragments_), has_depth(state.has_depth),
      depth_test(state.depth_test), depth_write(state.depth_write), late_z(state.late_z),
      per_sample(state.per_sample), write_color(state.write_color),
      depth_unorm_bits(state.depth_unorm_bits), hiz_tracked(state.hiz_tracked),
      hiz_enabled(state.hiz_enabled) {}

float TriangleContext::to_unorm_depth(float f) const {
  return unorm_to_float(float_to_unorm(f, depth_unorm_bits), depth_unorm_bits);
}

void set_batches_across_triangles(bool enabled) { batches_across_triangles_enabled.store(enabled); }

QuadBatcher::QuadBatcher() : batch_(std::make_unique<FragmentBatch>()) {
  for (auto& out : outputs_) out = std::make_unique<BatchOutput>();
}

void QuadBatcher::begin(const TriangleContext& ctx, TileMemory& memory, TileCounters& counters,
                        const CellState* cells, const float* cell_depth, const CellPlane* planes) {
  if (!continues(ctx)) {
    flush();
    ctx_.emplace(ctx);
    memory_ = &memory;
    counters_ = &counters;
    cells_ = cells;
    cell_depth_ = cell_depth;
    varyings_read_ = ctx.draw.fragment_shader ? ctx.draw.fragment_shader->varyings_read() : ~uint32_t{0};
    outputs_always_written_ = ctx.draw.fragment_shader ? ctx.draw.fragment_shader->outputs_always_written() : 0;
    opaque_writes_ = ctx.draw.blend.mode == BlendMode::Opaque && ctx.draw.blend.write_mask == 0xF;
    across_triangles_ = batches_across_triangles_enabled.load(std::memory_order_relaxed) &&
                        ctx.draw.fragment_shader && ctx.draw.fragment_shader->batches_across_triangles() &&
                        !ctx.late_z && !ctx.per_sample && ctx.subpass.inputs.empty();
    triangle_count_ = 0;
  } else if (triangles_[triangle_count_ - 1].first_quad == queued_) {
    --triangle_count_;  // the previous triangle queued nothing: reuse its entry
  }
  triangles_[triangle_count_++] =
      BatchTriangle{&ctx.tri, ctx.varyings, ctx.triangle_ref, planes[0].dx, planes[0].dy,
                    planes[1].dx, planes[1].dy, planes[2].dx, planes[2].dy, queued_};
}

void QuadBatcher::flush() {
  if (queued_ == 0) return;
  const TriangleContext& ctx = *ctx_;
  passing_lanes_shaded_ = false;
  if (ctx.draw.fragment_shader) {
    const int invocations = ctx.per_sample ? ctx.pattern.count : 1;
    for (int inv = 0; inv < invocations; ++inv) shade_invocation(inv);
  }
  if (ctx.pattern.count == 1 && opaque_writes_ && !ctx.fragments) {
    write_back_single_sample();
  } else {
    for (int t = 0; t < triangle_count_; ++t) {
      for (int q = triangles_[t].first_quad; q < end_of(t); ++q) write_back(q, triangles_[t]);
    }
  }
  // The open triangle (the last) may queue more quads into the next batch.
  triangles_[0] = triangles_[triangle_count_ - 1];
  triangles_[0].first_quad = 0;
  triangle_count_ = 1;
  queued_ = 0;
}

// Shades, at one sample position (or the pixel centre), every queued quad that has lanes for
// it; discards then remove those lanes' samples from the quad's coverage.
void QuadBatcher::shade_invocation(int inv) {
  const TriangleContext& ctx = *ctx_;
  const QuadCoverage sample_bits = ctx.per_sample ? kSampleBits << inv : ~QuadCoverage{0};
  FragmentBatch& b = *batch_;
  BatchOutput& out = *outputs_[inv];
  const float off_x = ctx.per_sample ? static_cast<float>(ctx.pattern.x[inv] - kSubpixelScale / 2) / kSubpixelScale : 0.0f;
  const float off_y = ctx.per_sample ? static_cast<float>(ctx.pattern.y[inv] - kSubpixelScale / 2) / kSubpixelScale : 0.0f;
  // Late Z shades the covered lanes (the depth test follows), early Z those that passed.
  const QuadCoverage* const shaded_samples = ctx.late_z ? quad_coverage_ : quad_passing_;
  // Runs of batch quads of one triangle: triangle table index and first batch quad.
  int run_triangle[kBatchQuads + 1], run_first[kBatchQuads + 1];
  int runs = 0;
  int count = 0;
  uint64_t shaded = 0;  // fragments: the active lanes of the shaded quads
  // Locals: the stores below are ints too, so members (and ctx, which they might alias) would
  // be reloaded every quad.
  const int triangles = triangle_count_;
  const int queued = queued_;
  const bool per_sample = ctx.per_sample;
  const bool one_sample = ctx.pattern.count == 1;
  int* const slots = slot_[inv];
  for (int t = 0; t < triangles; ++t) {
    const int first_slot = count;
    const uint32_t primitive_id = triangles_[t].tri->primitive_id;
    const int q_end = t + 1 < triangles ? triangles_[t + 1].first_quad : queued;  // end_of(t)
    for (int q = triangles_[t].first_quad; q < q_end; ++q) {
      const QuadCoverage samples = shaded_samples[q] & sample_bits;
      const uint8_t lanes = one_sample ? lanes_of_sample0(samples) : lanes_of(samples);
      slots[q] = lanes ? count : -1;
      shaded_lanes_[q] = lanes;
      if (!lanes) continue;
      shaded += static_cast<uint64_t>(lane_count(lanes));
      b.quad_x_px[count] = quad_qx_[q];
      b.quad_y_px[count] = quad_qy_[q];
      b.lane_mask[count] = lanes;
      b.quad_primitive_id[count] = primitive_id;
      if (!per_sample) {
        // Pixel centres: the quad's origin entry packed down to its batch position (one
        // invocation, so nothing reads entry q again; count <= q).
        if (count != q) {
          origin_ox_[count] = origin_ox_[q];
          origin_oy_[count] = origin_oy_[q];
          origin_l1_[count] = origin_l1_[q];
          origin_l2_[count] = origin_l2_[q];
          origin_z_[count] = origin_z_[q];
        }
        ++count;
        continue;
      }
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        const int f = count * kQuadLanes + lane;
        fx_[f] = static_cast<float>(origin_ox_[q] + (lane & 1)) + off_x;
        fy_[f] = static_cast<float>(origin_oy_[q] + (lane >> 1)) + off_y;
        l1_[f] = origin_l1_[q];
        l2_[f] = origin_l2_[q];
        z_[f] = origin_z_[q];
      }
      ++count;
    }
    if (count > first_slot) {
      run_triangle[runs] = t;
      run_first[runs++] = first_slot;
    }
  }
  // Early Z at pixel centres shades exactly the passing lanes; a discard below changes them.
  passing_lanes_shaded_ = !per_sample && !ctx.late_z;
  if (count == 0) return;
  b.quad_count = count;
  const int padded = b.padded_fragment_count();
  if (!ctx.per_sample) {
    interpolate_quads(count, padded / kQuadLanes, runs, run_triangle, run_first);
  } else {
    interpolate_samples(count, padded, runs, run_triangle, run_first);
  }
  b.varying_count = ctx.varying_count;
  b.color_output_count = static_cast<int>(ctx.subpass.color_outputs.size());
  b.front_facing = ctx.tri.setup.front_facing;  // one facing per batch
  b.primitive_id = b.quad_primitive_id[0];
  b.sample = ctx.per_sample ? inv : -1;
  b.fetch = ctx.fetch;
  // Outputs a shader leaves unwritten (e.g. a sky in an MRT subpass) are defined as zero, so
  // images never depend on earlier contents. Those it writes in full for every active fragment
  // need no zeroing: an inactive or padding lane's output is never written back.
  for (int k = outputs_always_written_; k < b.color_output_count; ++k) {
    std::memset(out.color[k], 0, sizeof(out.color[k]));
  }
  out.discard_mask = 0;
  out.output0_codes_of.reset();
  ctx.draw.fragment_shader->shade_batch(b, out);
  // Opaque writes do not depend on the destination: quantise the whole batch per output in one
  // pass (the same values write_back would compute one by one).
  if (opaque_writes_) {
    for (int k = 0; k < b.color_output_count; ++k) {
      const PixelFormat format = ctx.pass.attachments[ctx.subpass.color_outputs[k]].format;
      // The padded count keeps every SIMD vector whole; padding lanes are never written back.
      if (TileMemory::holds_codes(format)) {  // decoded codes give their own codes back
        const auto codes_of = k == 0 && out.output0_codes_of == format ? rgba8_codes_of_decoded_simd
                                                                       : quantize_rgba8_codes_simd;
        codes_of(out.color[k][0], out.color[k][1], out.color[k][2], out.color[k][3], padded,
                 format == PixelFormat::RGBA8_SRGB, codes_[inv][k]);
        continue;
      }
      if (k == 0 && out.output0_codes_of == format) continue;  // already quantised
      quantize_pixels(format, out.color[k][0], out.color[k][1], out.color[k][2], out.color[k][3],
                      padded);
    }
  }
  counters_->fragments_shaded += shaded;
  if (out.discard_mask == 0) return;
  passing_lanes_shaded_ = false;
  for (int q = 0; q < queued_; ++q) {
    const int slot = slot_[inv][q];
    if (slot < 0) continue;
    const uint32_t discarded = static_cast<uint32_t>(out.discard_mask >> (slot * kQuadLanes)) & 0xFu;
    for (int lane = 0; discarded && lane < kQuadLanes; ++lane) {
      if (!((discarded >> lane) & 1u)) continue;
      const QuadCoverage lane_bits = (QuadCoverage{0xFF} << (lane * kMaxSamples)) & sample_bits;
      quad_passing_[q] &= ~lane_bits;
      quad_coverage_[q] &= ~lane_bits;
    }
  }
}

// The runs' input for interpolation: each run's triangle planes, vertex 1/w and varyings.
InterpolationInput QuadBatcher::run_input(int triangle) const {
  const BatchTriangle& t = triangles_[triangle];
  const int n = ctx_->varying_count;
  return InterpolationInput{nullptr, nullptr, nullptr, nullptr, nullptr,
                            t.l1_dx, t.l1_dy, t.l2_dx, t.l2_dy, t.z_dx, t.z_dy,
                            {t.tri->setup.inv_w[0], t.tri->setup.inv_w[1], t.tri->setup.inv_w[2]},
                            {t.varyings, t.varyings + n, t.varyings + 2 * n},
                            n, varyings_read_};
}

// Interpolation at pixel centres from one origin entry per quad, all runs (one triangle each)
// in one call (interpolate_quad_runs: interpolate_whole_quads per run, bit for bit); the padding
// quads up to padded_quads repeat the last quad.
void QuadBatcher::interpolate_quads(int count, int padded_quads, int runs, const int* run_triangle,
                                    const int* run_first) {
  FragmentBatch& b = *batch_;
  for (int q = count; q < padded_quads; ++q) {
    origin_ox_[q] = origin_ox_[count - 1];
    origin_oy_[q] = origin_oy_[count - 1];
    origin_l1_[q] = origin_l1_[count - 1];
    origin_l2_[q] = origin_l2_[count - 1];
    origin_z_[q] = origin_z_[count - 1];
  }
  const int n = ctx_->varying_count;
  InterpolationRun run_terms[kBatchQuads];
  for (int r = 0; r < runs; ++r) {
    const BatchTriangle& t = triangles_[run_triangle[r]];
    const float* inv_w = t.tri->setup.inv_w;
    run_terms[r] = InterpolationRun{run_first[r], t.l1_dx, t.l1_dy, t.l2_dx, t.l2_dy, t.z_dx, t.z_dy,
                                    {inv_w[0], inv_w[1], inv_w[2]},
                                    {t.varyings, t.varyings + n, t.varyings + 2 * n}};
  }
  const QuadOrigins origins{origin_ox_, origin_oy_, origin_l1_, origin_l2_, origin_z_};
  interpolate_quad_runs(run_terms, runs, origins, padded_quads, n, varyings_read_, b.depth,
                        &b.varyings[0][0], kBatchFragments);
}

// Interpolation at one sample position per fragment (sample shading), from the per-fragment
// inputs shade_invocation stored; the padding fragments up to `padded` repeat the last one.
void QuadBatcher::interpolate_samples(int count, int padded, int runs, const int* run_triangle,
                                      const int* run_first) {
  FragmentBatch& b = *batch_;
  for (int f = count * kQuadLanes; f < padded; ++f) {
    const int last = count * kQuadLanes - 1;
    fx_[f] = fx_[last];
    fy_[f] = fy_[last];
    l1_[f] = l1_[last];
    l2_[f] = l2_[last];
    z_[f] = z_[last];
  }
  // Each run with its triangle's planes and vertices; the last run also fills the padding.
  for (int r = 0; r < runs; ++r) {
    const int first = run_first[r] * kQuadLanes;
    const int end = r + 1 < runs ? run_first[r + 1] * kQuadLanes : padded;
    InterpolationInput in = run_input(run_triangle[r]);
    in.fx = fx_ + first;
    in.fy = fy_ + first;
    in.l1_origin = l1_ + first;
    in.l2_origin = l2_ + first;
    in.z_origin = z_ + first;
    interpolate_fragments(in, end - first, b.depth + first, &b.varyings[0][first], kBatchFragments);
  }
}

}  // namespace ontile
