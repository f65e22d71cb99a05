// On-chip tile memory: every attachment of the pass for one tile, one value per sample, held
// at the attachment format's precision (values are quantised when written, as a tile buffer
// in the attachment's format would hold them). 8-bit RGBA attachments hold their stored bytes
// (a code plane: loads and stores are row copies, clears fills); the others hold the quantised
// values as floats (a colour plane).
#pragma once
#include <cstdint>
#include <cstring>
#include <vector>

#include <glm/glm.hpp>

#include "raster/pixel_format.h"
#include "raster/raster_types.h"

namespace ontile {

class TileMemory {
 public:
  // Formats kept as their stored bytes: one uint32_t per sample, the pixel's 4 bytes as
  // encode_pixel writes them (R in the lowest byte). Every quantised value of these formats is
  // the decode of exactly one code (PixelRows tests), so the bytes hold what the floats would.
  static bool holds_codes(PixelFormat format) {
    return format == PixelFormat::RGBA8_UNORM || format == PixelFormat::RGBA8_SRGB;
  }

  // formats[a]: attachment a's format (the depth attachment's is never an 8-bit RGBA one).
  void prepare(const std::vector<PixelFormat>& formats, int tile_width_px, int tile_height_px,
               int samples) {
    width_ = tile_width_px;
    height_ = tile_height_px;
    samples_ = samples;
    const size_t n = static_cast<size_t>(width_) * height_ * samples_;
    formats_ = formats;
    color_.resize(formats.size());
    codes_.resize(formats.size());
    for (size_t a = 0; a < formats.size(); ++a) {
      const bool codes = holds_codes(formats[a]);
      color_[a].resize(codes ? 0 : n);
      codes_[a].resize(codes ? n : 0);
    }
    depth_.resize(n);
  }
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

  size_t index(int local_x, int local_y, int sample) const {
    return (static_cast<size_t>(local_y) * width_ + local_x) * samples_ + sample;
  }
  PixelFormat format(int attachment) const { return formats_[attachment]; }
  bool holds_codes(int attachment) const { return holds_codes(formats_[attachment]); }
  // The colour plane of an attachment without codes, the code plane of one with them.
  glm::vec4* color_plane(int attachment) { return color_[attachment].data(); }
  const glm::vec4* color_plane(int attachment) const { return color_[attachment].data(); }
  uint32_t* code_plane(int attachment) { return codes_[attachment].data(); }
  const uint32_t* code_plane(int attachment) const { return codes_[attachment].data(); }
  float* depth_plane() { return depth_.data(); }
  const float* depth_plane() const { return depth_.data(); }

  // The value of sample index i of a colour attachment, whichever plane holds it.
  glm::vec4 color(int attachment, size_t i) const {
    if (!holds_codes(attachment)) return color_[attachment][i];
    uint8_t bytes[4];
    std::memcpy(bytes, &codes_[attachment][i], 4);
    return decode_pixel(formats_[attachment], bytes);
  }
  // Writes `value` quantised to the attachment's format (quantize_pixel, or the code of
  // encode_pixel, whose decode that is).
  void set_color(int attachment, size_t i, glm::vec4 value) {
    if (!holds_codes(attachment)) {
      color_[attachment][i] = quantize_pixel(formats_[attachment], value);
      return;
    }
    uint8_t bytes[4];
    encode_pixel(formats_[attachment], value, bytes);
    std::memcpy(&codes_[attachment][i], bytes, 4);
  }

 private:
  int width_ = 0, height_ = 0, samples_ = 1;
  std::vector<PixelFormat> formats_;
  std::vector<std::vector<glm::vec4>> color_;  // indexed by attachment (empty for code planes)
  std::vector<std::vector<uint32_t>> codes_;   // indexed by attachment (empty for colour planes)
  std::vector<float> depth_;
};

}  // namespace ontile
