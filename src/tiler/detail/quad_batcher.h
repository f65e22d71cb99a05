// The shading half of a tile's triangles: queues covered quads in the tile's row-major order,
// shades them in batches of up to 16 quads per functor call (structure-of-arrays varyings
// interpolated on SIMD lanes; quads of consecutive triangles of one draw share a batch when the
// functor allows it), then applies discards, late depth, blending and quantisation in queue order.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "raster/cell_raster.h"
#include "raster/pixel_format.h"
#include "raster/rasterize.h"
#include "raster/shader_interface.h"
#include "tiler/detail/parameter_buffer.h"
#include "tiler/detail/tile_load_store.h"
#include "tiler/detail/tile_memory.h"
#include "memory/tile_trace.h"

namespace ontile {

// Lanes with at least one covered sample: the non-zero bytes of the coverage (one byte of
// sample bits per lane). Each byte is folded onto its lowest bit, then bits 0, 8, 16 and 24 are
// gathered into bits 0-3 by one multiply (bit 8i moves to 24 + i; no two partial products meet,
// so nothing carries). Called several times per quad, where a loop over lanes cost ~20
// instructions.
inline uint8_t lanes_of(QuadCoverage coverage) {
  static_assert(kMaxSamples == 8 && kQuadLanes == 4 && sizeof(QuadCoverage) == 4);
  uint32_t folded = coverage | coverage >> 4;
  folded |= folded >> 2;
  folded |= folded >> 1;
  return static_cast<uint8_t>(((folded & 0x01010101u) * 0x01020408u) >> 24);
}

// lanes_of for coverage of sample 0 only (one sample per pixel: no other bit is ever set), without
// the folding: the multiply gathers bits 0, 8, 16 and 24 alone.
inline uint8_t lanes_of_sample0(QuadCoverage coverage) {
  return static_cast<uint8_t>(((coverage & 0x01010101u) * 0x01020408u) >> 24);
}

// How many of a quad's 4 lanes a lane mask holds: a table, since the baseline x86-64 target
// has no popcount instruction and std::popcount becomes a library call per quad (a byte read
// is one instruction where a nibble table in a register took five).
inline int lane_count(uint8_t lanes) {
  static constexpr uint8_t kCount[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
  return kCount[lanes & 0xFu];
}

// Coverage (and passing) of a quad whose 4 lanes hold sample 0, at one sample per pixel.
constexpr QuadCoverage kWholeQuadSample0 = 1u | (1u << kMaxSamples) | (1u << (2 * kMaxSamples)) |
                                           (1u << (3 * kMaxSamples));

// A draw's state as its triangles see it, the same for all of them (computed once per draw
// and tile rather than once per triangle: it asks the functor through virtual calls).
struct DrawState {
  bool has_depth, depth_test, depth_write, late_z, per_sample, write_color;
  int depth_unorm_bits;
  bool hiz_tracked, hiz_enabled;
  DrawState(const RenderPassDesc& pass, const SubpassDesc& subpass, const DrawCall& draw);
};

// What one triangle of a tile needs to know about its draw, pass and state.
struct TriangleContext {
  const RenderPassDesc& pass;
  const SubpassDesc& subpass;
  const DrawCall& draw;
  const BinnedTriangle& tri;
  const float* varyings;  // 3 * varying_count, setup slot order
  int varying_count;
  const SamplePattern& pattern;
  const TileRect& rect;
  const FramebufferFetch* fetch;
  uint32_t triangle_ref;
  std::vector<FragmentAccess>* fragments;  // null unless recording for the IMR model

  bool has_depth, depth_test, depth_write, late_z, per_sample, write_color;
  // A fixed-point depth attachment (D16, D24S8) converts the fragment's depth to its format
  // before the depth test (Vulkan 1.3 "Depth Test", Fixed-Point Data Conversions): tile memory
  // keeps floats, so the incoming depth is quantised and the quantised value tested and written.
  int depth_unorm_bits;
  bool hiz_tracked;  // the pass has depth: cells keep their depth bounds
  bool hiz_enabled;  // this draw may skip cells by hierarchical Z (early Z, ordering compare)

  // `state`: the draw's DrawState, computed once per run of its triangles.
  TriangleContext(const RenderPassDesc& pass, const SubpassDesc& subpass, const DrawCall& draw,
                  const BinnedTriangle& tri, const float* varyings, int varying_count,
                  const SamplePattern& pattern, const TileRect& rect,
                  const FramebufferFetch* fetch, uint32_t triangle_ref,
                  std::vector<FragmentAccess>* fragments, const DrawState& state);
  // The incoming depth as the attachment holds it: clamped to [0, 1], rounded to float and,
  // for a fixed-point format, to its nearest code. Inline: asked twice per cell.
  float quantize_depth(double z) const {
    const float f = static_cast<float>(z < 0.0 ? 0.0 : (z > 1.0 ? 1.0 : z));
    return depth_unorm_bits ? to_unorm_depth(f) : f;
  }
  float to_unorm_depth(float f) const;
  // Early Z, or late Z with neither a depth test nor a depth write (deferred lighting, which
  // may discard): a covered quad's lanes then all pass unless the functor discards them.
  bool whole_quads_pass_as_covered() const { return !late_z || (!depth_test && !depth_write); }
};

// Per-cell results of coverage and early depth for the current triangle.
struct CellState {
  CellMask covered_any = 0;
  CellMask covered[kMaxSamples] = {};
  CellMask passing[kMaxSamples] = {};
  CellPlane planes[3];  // lambda1, lambda2, depth at the cell's origin
};

// What a batch keeps of each triangle with quads in it: the tile's cell state already holds a
// later triangle's planes when the batch is shaded.
struct BatchTriangle {
  const BinnedTriangle* tri;
  const float* varyings;
  uint32_t triangle_ref;
  float l1_dx, l1_dy, l2_dx, l2_dy, z_dx, z_dy;  // plane gradients per pixel
  int first_quad;  // queue position of its first quad (its quads run to the next triangle's)
};

// Batches across triangles are on by default; tests turn them off to compare frames with one
// triangle per batch (same images and counters). Set between frames only.
void set_batches_across_triangles(bool enabled);

// Usage per triangle: if (!continues(ctx)) flush(); ... begin(); add() per quad; end_triangle().
// A batch spans triangles only while nothing between them can observe the delayed shading:
// one draw (functor, material, pass state), one facing, early depth (depth was tested and
// written when each triangle was rasterized), no input attachments, no sample shading, and a
// functor that declares batches_across_triangles(). Writes still happen in queue order.
class QuadBatcher {
 public:
  QuadBatcher();
  // True when a triangle of `ctx` may add its quads to the open batch.
  bool continues(const TriangleContext& ctx) const {
    return queued_ > 0 && across_triangles_ && &ctx.draw == &ctx_->draw &&
           ctx.tri.setup.front_facing == ctx_->tri.setup.front_facing;
  }
  // Starts a triangle (flushing an open batch it cannot join): cells and cell_depth are the
  // tile's per-cell state (see tile_executor), planes those of any cell the triangle covers
  // (the gradients are per triangle). Every pointer must stay valid until the batch is flushed.
  void begin(const TriangleContext& ctx, TileMemory& memory, TileCounters& counters,
             const CellState* cells, const float* cell_depth, const CellPlane* planes);
  // Queues a quad: its queue entry and its interpolation inputs at once (the cell's plane
  // origins are the triangle's while it adds quads; a later triangle overwrites the cells).
  void add(int qx, int qy, int cell, int cell_x, int cell_y, QuadCoverage coverage, QuadCoverage passing) {
    const int q = queued_++;
    const CellPlane* planes = cells_[cell].planes;
    quad_qx_[q] = qx;
    quad_qy_[q] = qy;
    quad_cell_[q] = cell;
    quad_coverage_[q] = coverage;
    quad_passing_[q] = passing;
    origin_ox_[q] = qx - cell_x;
    origin_oy_[q] = qy - cell_y;
    origin_l1_[q] = planes[0].origin;
    origin_l2_[q] = planes[1].origin;
    origin_z_[q] = planes[2].origin;
    if (queued_ == kBatchQuads) flush();
  }
  // The whole-tile path (full-screen triangles; whole_tile_batches.cpp): called right after
  // begin() for a triangle that covers every pixel of `rect` (even origin and size) at one
  // sample, every pixel having passed early depth (or facing no depth test or write after
  // shading: whole_quads_pass_as_covered). Shades and writes the rect's quads in the
  // tile's row-major order kBatchQuads at a time, the batches add() per quad would form, without
  // queueing them, and queues the last partial batch with add(). Returns false, doing nothing,
  // unless the batch is empty and the draw shades one opaque invocation per pixel with early
  // depth (or whole_quads_pass_as_covered) and no fragment recording. The cells grid: cell (i, j) has its top-left pixel at
  // (first_cell_x + 8 i, first_cell_y + 8 j), index j * cells_x + i in cells_.
  bool add_whole_rect(const TileRect& rect, int first_cell_x, int first_cell_y, int cells_x);
  // Ends a triangle: its quads stay queued only if the next triangle may join them.
  void end_triangle() {
    if (!across_triangles_) flush();
  }
  // Shades and writes every queued quad.
  void flush();
  // Drops queued quads without shading them (a tile that threw may have left some).
  void reset() { queued_ = 0; }

 private:
  void shade_invocation(int invocation);
  void write_back(int q, const BatchTriangle& triangle);
  int end_of(int triangle) const {  // queue position after the triangle's last quad
    return triangle + 1 < triangle_count_ ? triangles_[triangle + 1].first_quad : queued_;
  }
  void write_back_single_sample();
  InterpolationInput run_input(int triangle) const;
  void interpolate_quads(int count, int padded_quads, int runs, const int* run_triangle,
                         const int* run_first);
  void interpolate_samples(int count, int padded, int runs, const int* run_triangle,
                           const int* run_first);
  // One whole batch of add_whole_rect: the kBatchQuads quads of `rect` from (qx, qy) on in
  // row-major order; qx, qy are advanced past them.
  void shade_whole_batch(const TileRect& rect, int& qx, int& qy, int first_cell_x,
                         int first_cell_y, int cells_x);

  std::optional<TriangleContext> ctx_;  // the batch's first triangle: draw, pass and facing
  TileMemory* memory_ = nullptr;
  TileCounters* counters_ = nullptr;
  const CellState* cells_ = nullptr;
  const float* cell_depth_ = nullptr;
  bool opaque_writes_ = false;     // blending is a plain overwrite: outputs are quantised per batch
  bool across_triangles_ = false;  // the batch may take the next triangle's quads
  uint32_t varyings_read_ = ~uint32_t{0};  // the functor's varyings_read(): only those interpolated
  int outputs_always_written_ = 0;         // the functor's outputs_always_written(), per draw
  // The queue, quad q of the batch: top-left pixel, cell index (its top-left pixel is the
  // quad's rounded down to a multiple of kCellSizePx), coverage and passing samples.
  int32_t quad_qx_[kBatchQuads], quad_qy_[kBatchQuads], quad_cell_[kBatchQuads];
  QuadCoverage quad_coverage_[kBatchQuads], quad_passing_[kBatchQuads];
  int queued_ = 0;
  // Every triangle but the last has a queued quad: at most one per quad, plus the open one.
  BatchTriangle triangles_[kBatchQuads + 1];
  int triangle_count_ = 0;
  int slot_[kMaxSamples][kBatchQuads];  // batch position of queued quad q per invocation, or -1
  // The lanes shade_invocation shaded of queued quad q (its last invocation), and whether they
  // are the quad's passing lanes, lanes_of(quad_passing_[q]) (pixel centres, early Z, no
  // discard): the write-back then reads them instead of folding the coverage again.
  uint8_t shaded_lanes_[kBatchQuads];
  bool passing_lanes_shaded_ = false;
  std::unique_ptr<FragmentBatch> batch_;
  std::unique_ptr<BatchOutput> outputs_[kMaxSamples];
  // Opaque outputs into code planes (TileMemory::holds_codes), per invocation and output: each
  // fragment's packed 8-bit code, quantised per batch (the BatchOutput floats stay as shaded).
  alignas(64) uint32_t codes_[kMaxSamples][kMaxColorTargets][kBatchFragments];
  // Interpolation inputs per batch fragment.
  alignas(64) float fx_[kBatchFragments], fy_[kBatchFragments];
  alignas(64) float l1_[kBatchFragments], l2_[kBatchFragments], z_[kBatchFragments];
  // Interpolation inputs of queued quad q (add()): offset of its top-left pixel in its cell and
  // the cell's plane origins. shade_invocation packs the shaded quads' entries to the front for
  // interpolate_quad_runs (pixel centres), or reads them per fragment (sample shading).
  alignas(64) int32_t origin_ox_[kBatchQuads + kQuadOriginsPadding] = {};
  alignas(64) int32_t origin_oy_[kBatchQuads + kQuadOriginsPadding] = {};
  alignas(64) float origin_l1_[kBatchQuads + kQuadOriginsPadding] = {};
  alignas(64) float origin_l2_[kBatchQuads + kQuadOriginsPadding] = {};
  alignas(64) float origin_z_[kBatchQuads + kQuadOriginsPadding] = {};
  // A whole-tile batch's quads whose lanes all pass: first fragment, tile pixel index.
  int32_t full_first_fragment_[kBatchQuads];
  uint32_t full_pixel_[kBatchQuads];
  // shade_whole_batch's interpolation inputs per quad (interpolate_whole_quads).
  alignas(64) int32_t quad_ox_[kBatchQuads + kQuadOriginsPadding] = {};
  alignas(64) int32_t quad_oy_[kBatchQuads + kQuadOriginsPadding] = {};
  alignas(64) float quad_l1_[kBatchQuads + kQuadOriginsPadding] = {};
  alignas(64) float quad_l2_[kBatchQuads + kQuadOriginsPadding] = {};
  alignas(64) float quad_z_[kBatchQuads + kQuadOriginsPadding] = {};
};

}  // namespace ontile
