// On-chip tile memory: every attachment of the pass for one tile, one value per sample, held
// at the attachment format's precision (values are quantised when written, as a tile buffer
// in the attachment's format would hold them).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "raster/raster_types.h"

namespace ontile {

class TileMemory {
 public:
  void prepare(int attachment_count, int tile_width_px, int tile_height_px, int samples) {
    width_ = tile_width_px;
    height_ = tile_height_px;
    samples_ = samples;
    const size_t n = static_cast<size_t>(width_) * height_ * samples_;
    color_.resize(attachment_count);
    for (auto& plane : color_) plane.resize(n);
    depth_.resize(n);
  }
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

  size_t index(int local_x, int local_y, int sample) const {
    return (static_cast<size_t>(local_y) * width_ + local_x) * samples_ + sample;
  }
  glm::vec4* color_plane(int attachment) { return color_[attachment].data(); }
  const glm::vec4* color_plane(int attachment) const { return color_[attachment].data(); }
  float* depth_plane() { return depth_.data(); }
  const float* depth_plane() const { return depth_.data(); }

 private:
  int width_ = 0, height_ = 0, samples_ = 1;
  std::vector<std::vector<glm::vec4>> color_;  // indexed by attachment (depth's stays unused)
  std::vector<float> depth_;
};

}  // namespace ontile
