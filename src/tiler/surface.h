// A surface in external (DRAM) memory: the encoded bytes of an attachment or texture target,
// exactly as many bytes per pixel as its format stores.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "raster/pixel_format.h"

namespace ontile {

class Surface {
 public:
  Surface(std::string name, PixelFormat format, int width_px, int height_px, int samples = 1);

  const std::string& name() const { return name_; }
  PixelFormat format() const { return format_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  uint64_t size_bytes() const { return bytes_.size(); }
  const std::vector<uint8_t>& bytes() const { return bytes_; }

  glm::vec4 read(int x, int y, int sample = 0) const {
    return decode_pixel(format_, &bytes_[offset(x, y, sample)]);
  }
  void write(int x, int y, int sample, const glm::vec4& value) {
    encode_pixel(format_, value, &bytes_[offset(x, y, sample)]);
  }
  void fill(const glm::vec4& value);
  // The encoded bytes of (x, y, sample) and the pixels after it in the row (samples of a pixel
  // are adjacent, pixels of a row follow each other): what row conversions read and write.
  uint8_t* pixel_bytes(int x, int y, int sample = 0) { return &bytes_[offset(x, y, sample)]; }
  const uint8_t* pixel_bytes(int x, int y, int sample = 0) const {
    return &bytes_[offset(x, y, sample)];
  }

 private:
  size_t offset(int x, int y, int sample) const {
    return ((static_cast<size_t>(y) * width_ + x) * samples_ + sample) * bytes_per_pixel_;
  }
  std::string name_;
  PixelFormat format_;
  int width_, height_, samples_, bytes_per_pixel_;
  std::vector<uint8_t> bytes_;
};

}  // namespace ontile
