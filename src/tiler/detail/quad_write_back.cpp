// The write half of a batch (see quad_batcher.h): per-quad writes of shaded outputs, late
// depth and blending into tile memory in queue order, the counters, and the fragment records
// of the IMR model; the single-sample opaque case a batch at a time on SIMD stores.
#include <cstring>

#include "raster/blend.h"
#include "tiler/detail/quad_batcher.h"
#include "tiler/detail/quad_store_simd.h"

namespace ontile {
namespace {

// Records, per covered pixel, which samples were covered and written and what was accessed.
void record_fragments(const TriangleContext& ctx, const BatchTriangle& triangle, int qx, int qy,
                      QuadCoverage coverage, QuadCoverage written) {
  const bool blend_reads = ctx.draw.blend.mode != BlendMode::Opaque || ctx.draw.blend.write_mask != 0xF;
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    const uint8_t covered = static_cast<uint8_t>(lane_coverage(coverage, lane));
    if (!covered) continue;
    FragmentAccess f;
    f.triangle_ref = triangle.triangle_ref;
    f.x_px = static_cast<uint16_t>(qx + (lane & 1));
    f.y_px = static_cast<uint16_t>(qy + (lane >> 1));
    f.covered_samples = covered;
    f.written_samples = static_cast<uint8_t>(lane_coverage(written, lane));
    f.subpass = static_cast<uint8_t>(triangle.tri->subpass);
    if (ctx.depth_test) f.flags |= kDepthRead;
    if (f.written_samples && ctx.depth_write) f.flags |= kDepthWritten;
    if (f.written_samples && ctx.write_color && !ctx.subpass.color_outputs.empty()) {
      f.flags |= kColorWritten;
      if (blend_reads) f.flags |= kColorRead;
    }
    ctx.fragments->push_back(f);
  }
}

}  // namespace

void QuadBatcher::write_back(int q, const BatchTriangle& triangle) {
  const TriangleContext& ctx = *ctx_;
  const int qx = quad_qx_[q], qy = quad_qy_[q];
  const QuadCoverage coverage = quad_coverage_[q], passing = quad_passing_[q];
  if (ctx.late_z) {
    counters_->fragments_depth_rejected += lane_count(lanes_of(coverage) & ~lanes_of(passing));
  }
  if (ctx.fragments) {
    record_fragments(ctx, triangle, qx, qy, coverage, passing);
  }
  if (!passing) return;
  const int samples = ctx.pattern.count;
  const std::vector<int>& outputs = ctx.subpass.color_outputs;
  const int cx = qx & ~(kCellSizePx - 1), cy = qy & ~(kCellSizePx - 1);  // cells are aligned
  const float* z = cell_depth_ + static_cast<size_t>(quad_cell_[q]) * kMaxSamples * kCellPixels;
  const bool late_depth_write = ctx.late_z && ctx.depth_write;
  float* depth_plane = memory_->depth_plane();
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    const unsigned lane_bits = lane_coverage(passing, lane);
    if (!lane_bits) continue;
    const int x = qx + (lane & 1), y = qy + (lane >> 1);
    for (int s = 0; s < samples; ++s) {
      if (!((lane_bits >> s) & 1u)) continue;
      const size_t i = memory_->index(x - ctx.rect.x0, y - ctx.rect.y0, s);
      if (late_depth_write) depth_plane[i] = z[s * kCellPixels + (y - cy) * kCellSizePx + (x - cx)];
      if (ctx.write_color) {
        const int inv = ctx.per_sample ? s : 0;
        const BatchOutput& out = *outputs_[inv];
        const int f = slot_[inv][q] * kQuadLanes + lane;
        for (size_t k = 0; k < outputs.size(); ++k) {
          const int a = outputs[k];
          if (memory_->holds_codes(a)) {
            if (opaque_writes_) {
              memory_->code_plane(a)[i] = codes_[inv][k][f];
            } else {
              memory_->set_color(a, i, blend_color(ctx.draw.blend, out.get(static_cast<int>(k), f),
                                                   memory_->color(a, i)));
            }
            continue;
          }
          glm::vec4& dst = memory_->color_plane(a)[i];
          if (opaque_writes_) {
            dst = out.get(static_cast<int>(k), f);
          } else {
            dst = quantize_pixel(ctx.pass.attachments[a].format,
                                 blend_color(ctx.draw.blend, out.get(static_cast<int>(k), f), dst));
          }
        }
      }
      ++counters_->samples_written;
    }
  }
}

// write_back for the common case, the batch at once: one sample per pixel, outputs already
// quantised per batch. Depth was written by early Z, or (late Z: functors that may discard, such
// as deferred lighting) is written here for the samples that passed the depth test and were not
// discarded, with write_back's rejection count. The quads with written lanes are listed in queue
// order (a later triangle's quads may overwrite an earlier one's pixels) and each output is then
// stored in one call, every quad with its lane mask (no split into whole and partial quads: a
// coin toss per quad, and one call per triangle, were most of this function's cost).
void QuadBatcher::write_back_single_sample() {
  const TriangleContext& ctx = *ctx_;
  const std::vector<int>& outputs = ctx.subpass.color_outputs;
  const BatchOutput& out = *outputs_[0];
  const bool late_z = ctx.late_z;
  const bool late_depth_write = late_z && ctx.depth_write;
  // Locals, not members: the stores below are ints too, so members would be reloaded per quad.
  const int queued = queued_;
  const bool write_color = ctx.write_color;
  const int x0 = ctx.rect.x0, y0 = ctx.rect.y0;
  const size_t width = static_cast<size_t>(memory_->width());
  const size_t samples = static_cast<size_t>(memory_->samples());
  float* const depth_plane = memory_->depth_plane();
  int32_t first_fragment[kBatchQuads];
  uint32_t pixel_of[kBatchQuads];
  uint8_t lanes_written[kBatchQuads];
  int listed = 0;
  uint64_t rejected = 0, written = 0;
  const bool lanes_known = passing_lanes_shaded_;
  // The batch's quads are its triangles' in order: [0, queued).
  for (int q = 0; q < queued; ++q) {
    const uint8_t lanes = lanes_known ? shaded_lanes_[q] : lanes_of_sample0(quad_passing_[q]);
    if (late_z) rejected += static_cast<uint64_t>(lane_count(lanes_of_sample0(quad_coverage_[q]) & ~lanes));
    written += static_cast<uint64_t>(lane_count(lanes));
    if (!lanes) continue;
    const int qx = quad_qx_[q], qy = quad_qy_[q];
    // TileMemory::index(qx - x0, qy - y0, 0).
    const size_t pixel = (static_cast<size_t>(qy - y0) * width + static_cast<size_t>(qx - x0)) * samples;
    if (late_depth_write) {
      // The cell's depth at each passing lane, as rasterize_cells computed it.
      // (Cells are aligned to multiples of kCellSizePx: the quad's offset in its cell.)
      const float* z = cell_depth_ + static_cast<size_t>(quad_cell_[q]) * kMaxSamples * kCellPixels +
                       (qy & (kCellSizePx - 1)) * kCellSizePx + (qx & (kCellSizePx - 1));
      float* depth = depth_plane + pixel;
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        if (!((lanes >> lane) & 1u)) continue;
        depth[static_cast<size_t>(lane >> 1) * width + (lane & 1)] = z[(lane >> 1) * kCellSizePx + (lane & 1)];
      }
    }
    first_fragment[listed] = slot_[0][q] * kQuadLanes;
    pixel_of[listed] = static_cast<uint32_t>(pixel);
    lanes_written[listed++] = lanes;
  }
  counters_->fragments_depth_rejected += rejected;
  counters_->samples_written += written;
  if (!write_color || listed == 0) return;
  const int row_pixels = memory_->width();
  for (size_t k = 0; k < outputs.size(); ++k) {
    if (memory_->holds_codes(outputs[k])) {
      store_quad_codes(codes_[0][k], first_fragment, pixel_of, lanes_written, listed, row_pixels,
                       memory_->code_plane(outputs[k]));
      continue;
    }
    const float* const channels[4] = {out.color[k][0], out.color[k][1], out.color[k][2],
                                      out.color[k][3]};
    store_quads(channels, first_fragment, pixel_of, lanes_written, listed, row_pixels,
                memory_->color_plane(outputs[k]));
  }
}

}  // namespace ontile
