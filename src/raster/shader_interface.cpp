// The adapters between per-quad and batched fragment shading (see shader_interface.h).
#include "raster/shader_interface.h"

#include <memory>

namespace ontile {

void FramebufferFetch::load_quads(int input_slot, const int32_t* quad_x_px, const int32_t* quad_y_px,
                                  int quad_count, int sample, float* const channel[4]) const {
  for (int q = 0; q < quad_count; ++q) {
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      const glm::vec4 v = load(input_slot, quad_x_px[q] + (lane & 1), quad_y_px[q] + (lane >> 1), sample);
      for (int c = 0; c < 4; ++c) {
        if (channel[c]) channel[c][q * kQuadLanes + lane] = v[c];
      }
    }
  }
}

void FragmentBatch::quad(int q, QuadFragment& out) const {
  out.x_px = quad_x_px[q];
  out.y_px = quad_y_px[q];
  out.lane_mask = lane_mask[q];
  out.front_facing = front_facing;
  out.primitive_id = quad_primitive_id[q];
  out.sample = sample;
  out.fetch = fetch;
  for (int lane = 0; lane < kQuadLanes; ++lane) out.depth[lane] = depth[q * kQuadLanes + lane];
  for (int k = 0; k < varying_count; ++k) {
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      out.varyings[k][lane] = varyings[k][q * kQuadLanes + lane];
    }
  }
}

void BatchOutput::store_quad(int q, const QuadOutput& quad_out, int targets) {
  for (int k = 0; k < targets; ++k) {
    for (int lane = 0; lane < kQuadLanes; ++lane) set(k, q * kQuadLanes + lane, quad_out.color[k][lane]);
  }
  discard_mask |= uint64_t{quad_out.discard_mask} << (q * kQuadLanes);
}

void FragmentShader::shade_batch(const FragmentBatch& batch, BatchOutput& out) const {
  for (int q = 0; q < batch.quad_count; ++q) {
    QuadFragment quad;
    batch.quad(q, quad);
    QuadOutput quad_out;
    for (int k = 0; k < batch.color_output_count; ++k) {
      for (int lane = 0; lane < kQuadLanes; ++lane) quad_out.color[k][lane] = out.get(k, q * kQuadLanes + lane);
    }
    shade(quad, quad_out);
    out.store_quad(q, quad_out, batch.color_output_count);
  }
}

void FragmentShader::shade(const QuadFragment& quad, QuadOutput& out) const {
  // A batch of one quad; heap-allocated once per thread (it is 16 KiB) since this adapter serves
  // unit tests and the reference renderer, not the tile loop.
  thread_local std::unique_ptr<FragmentBatch> batch = std::make_unique<FragmentBatch>();
  thread_local std::unique_ptr<BatchOutput> batch_out = std::make_unique<BatchOutput>();
  batch->quad_count = 1;
  batch->varying_count = kMaxVaryings;
  batch->color_output_count = kMaxColorTargets;
  batch->front_facing = quad.front_facing;
  batch->primitive_id = quad.primitive_id;
  batch->quad_primitive_id[0] = quad.primitive_id;
  batch->sample = quad.sample;
  batch->fetch = quad.fetch;
  batch->quad_x_px[0] = quad.x_px;
  batch->quad_y_px[0] = quad.y_px;
  batch->lane_mask[0] = quad.lane_mask;
  // Fill all 16 padded fragments with the quad, so SIMD shaders see defined values.
  for (int f = 0; f < 16; ++f) {
    batch->depth[f] = quad.depth[f & 3];
    for (int k = 0; k < kMaxVaryings; ++k) batch->varyings[k][f] = quad.varyings[k][f & 3];
  }
  for (int k = 0; k < kMaxColorTargets; ++k) {
    for (int f = 0; f < 16; ++f) batch_out->set(k, f, out.color[k][f & 3]);
  }
  batch_out->discard_mask = 0;
  shade_batch(*batch, *batch_out);
  for (int k = 0; k < kMaxColorTargets; ++k) {
    for (int lane = 0; lane < kQuadLanes; ++lane) out.color[k][lane] = batch_out->get(k, lane);
  }
  out.discard_mask |= static_cast<uint8_t>(batch_out->discard_mask & 0xFu);
}

}  // namespace ontile
