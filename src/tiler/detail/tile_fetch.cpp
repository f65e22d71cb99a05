// Framebuffer fetch from a tile's own memory (see tile_fetch.h).
#include "tiler/detail/tile_fetch.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "tiler/detail/quad_store_simd.h"
#include "util/error.h"

namespace ontile {

glm::vec4 TileFetch::load(int input_slot, int x_px, int y_px, int sample) const {
  const int attachment = attachment_of(input_slot);
  const size_t i = memory_.index(x_px - rect_.x0, y_px - rect_.y0, sample);
  if (attachment == depth_index_) return {memory_.depth_plane()[i], 0.0f, 0.0f, 1.0f};
  return memory_.color(attachment, i);
}

void TileFetch::load_quads(int input_slot, const int32_t* quad_x_px, const int32_t* quad_y_px,
                         int quad_count, int sample, float* const channel[4]) const {
  const int attachment = attachment_of(input_slot);
  const size_t right = memory_.index(1, 0, 0), below = memory_.index(0, 1, 0);
  const size_t offsets[kQuadLanes] = {0, right, below, below + right};
  if (attachment == depth_index_) {
    const float* depth = memory_.depth_plane();
    if (memory_.samples() == 1) {
      // Each quad row is two adjacent floats of the plane.
      for (int q = 0; q < quad_count; ++q) {
        const size_t i = memory_.index(quad_x_px[q] - rect_.x0, quad_y_px[q] - rect_.y0, 0);
        std::memcpy(channel[0] + q * kQuadLanes, depth + i, 2 * sizeof(float));
        std::memcpy(channel[0] + q * kQuadLanes + 2, depth + i + below, 2 * sizeof(float));
      }
    } else {
      for (int q = 0; q < quad_count; ++q) {
        const size_t i = memory_.index(quad_x_px[q] - rect_.x0, quad_y_px[q] - rect_.y0, sample);
        for (int lane = 0; lane < kQuadLanes; ++lane) channel[0][q * kQuadLanes + lane] = depth[i + offsets[lane]];
      }
    }
    const int fragments = quad_count * kQuadLanes;
    if (channel[1]) std::fill_n(channel[1], fragments, 0.0f);
    if (channel[2]) std::fill_n(channel[2], fragments, 0.0f);
    if (channel[3]) std::fill_n(channel[3], fragments, 1.0f);
    return;
  }
  const bool codes = memory_.holds_codes(attachment);
  if (memory_.samples() == 1) {
    uint32_t pixel[kBatchQuads];
    for (int q = 0; q < quad_count; ++q) {
      pixel[q] = static_cast<uint32_t>(memory_.index(quad_x_px[q] - rect_.x0, quad_y_px[q] - rect_.y0, 0));
    }
    if (codes) {
      load_full_quad_codes(memory_.code_plane(attachment), pixel, quad_count, memory_.width(),
                           memory_.format(attachment) == PixelFormat::RGBA8_SRGB, channel);
    } else {
      load_full_quads(memory_.color_plane(attachment), pixel, quad_count, memory_.width(), channel);
    }
    return;
  }
  for (int q = 0; q < quad_count; ++q) {
    const size_t i = memory_.index(quad_x_px[q] - rect_.x0, quad_y_px[q] - rect_.y0, sample);
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      const glm::vec4 v = memory_.color(attachment, i + offsets[lane]);
      const int f = q * kQuadLanes + lane;
      for (int c = 0; c < 4; ++c) channel[c][f] = v[c];
    }
  }
}

int TileFetch::attachment_of(int input_slot) const {
  if (input_slot < 0 || input_slot >= static_cast<int>(inputs_.size())) {
    throw Error("framebuffer fetch of input slot " + std::to_string(input_slot) +
                ", but the subpass declares " + std::to_string(inputs_.size()) + " inputs");
  }
  return inputs_[input_slot];
}

}  // namespace ontile
