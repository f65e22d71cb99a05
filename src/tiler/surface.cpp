// External-memory surfaces (see surface.h).
#include "tiler/surface.h"

#include <algorithm>

#include "util/error.h"

namespace ontile {

Surface::Surface(std::string name, PixelFormat format, int width_px, int height_px, int samples)
    : name_(std::move(name)), format_(format), width_(width_px), height_(height_px),
      samples_(samples), bytes_per_pixel_(bytes_per_pixel(format)) {
  if (width_px <= 0 || height_px <= 0 || samples <= 0) {
    throw Error("surface '" + name_ + "': invalid size " + std::to_string(width_px) + "x" +
                std::to_string(height_px) + "x" + std::to_string(samples));
  }
  bytes_.assign(static_cast<size_t>(width_px) * height_px * samples * bytes_per_pixel_, 0);
}

void Surface::fill(const glm::vec4& value) {
  uint8_t pixel[16];
  encode_pixel(format_, value, pixel);
  for (size_t i = 0; i < bytes_.size(); i += bytes_per_pixel_) {
    std::copy_n(pixel, bytes_per_pixel_, &bytes_[i]);
  }
}

}  // namespace ontile
