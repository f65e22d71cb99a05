// The texel trace of the Sobel edge pass (sobel_edge_shader.h): per fragment, the texels that
// sampling each tap separately reads, in that order, with the address constants held in
// locals so a tap costs an add and a compare.
#pragma once
#include <cstdint>

#include "raster/texel_trace.h"
#include "raster/texture.h"
#include "shaders_cpp/toon/sobel_edge_kernel.h"

namespace ontile::sobel {

class TapTrace {
 public:
  // depth is required; normal and border may be null (not sampled).
  TapTrace(const Texture2D::TexelView& color, const Texture2D::TexelView& depth,
           const Texture2D::TexelView* normal, const Texture2D::TexelView* border)
      : color_(color), depth_(depth), normal_(normal ? Plane(*normal) : Plane()),
        border_(border ? Plane(*border) : Plane()), has_normal_(normal != nullptr) {}

  // The reads of one fragment up to its colour sample: the 9 depth taps row by row, the normal
  // centre, the other 8 normal taps when all_normals, the colour texel.
  void fragment(const int tx[kTapsPerAxis], const int ty[kTapsPerAxis], int color_x,
                int color_y, bool all_normals) {
    // The last granule in a local, so it stays in a register across the texel trace's stores.
    uint64_t last = last_granule_;
    const auto record = [&last](uint64_t byte_address) { record_new(byte_address, last); };
    uint64_t column[kTapsPerAxis], row[kTapsPerAxis];
    for (int a = 0; a < kTapsPerAxis; ++a) {
      column[a] = depth_.column_offset(tx[a]);
      row[a] = depth_.row_address(ty[a]);
    }
    for (int b = 0; b < kTapsPerAxis; ++b) {
      for (int a = 0; a < kTapsPerAxis; ++a) record(row[b] + column[a]);
    }
    if (has_normal_) {
      for (int a = 0; a < kTapsPerAxis; ++a) {
        column[a] = normal_.column_offset(tx[a]);
        row[a] = normal_.row_address(ty[a]);
      }
      record(row[1] + column[1]);
      if (all_normals) {
        for (int b = 0; b < kTapsPerAxis; ++b) {
          for (int a = 0; a < kTapsPerAxis; ++a) {
            if (b != 1 || a != 1) record(row[b] + column[a]);
          }
        }
      }
    }
    record(color_.address(color_x, color_y));
    last_granule_ = last;
  }
  // The border read of a fragment on an edge, at its nearest tap's texel.
  void border(int x, int y) { record_new(border_.address(x, y), last_granule_); }

 private:
  // Texture2D::texel_address of level 0 split into row and column terms: origin +
  // (y * width + x) * bytes = (origin + y * width * bytes) + x * bytes, exactly (integers).
  struct Plane {
    uint64_t origin = 0, row_bytes = 0, texel_bytes = 0;
    Plane() = default;
    explicit Plane(const Texture2D::TexelView& v)
        : origin(v.address),
          row_bytes(static_cast<uint64_t>(v.width) * v.memory_bytes_per_texel),
          texel_bytes(v.memory_bytes_per_texel) {}
    uint64_t row_address(int y) const { return origin + static_cast<uint64_t>(y) * row_bytes; }
    uint64_t column_offset(int x) const { return static_cast<uint64_t>(x) * texel_bytes; }
    uint64_t address(int x, int y) const { return row_address(y) + column_offset(x); }
  };

  // Consecutive reads of one 64-byte granule are left out before record_texel_address, which
  // drops them anyway (texel_trace.h): the same trace, fewer calls.
  static void record_new(uint64_t byte_address, uint64_t& last_granule) {
    const uint64_t granule = byte_address >> 6;
    if (granule == last_granule) return;
    last_granule = granule;
    record_texel_address(byte_address);
  }

  Plane color_, depth_, normal_, border_;
  bool has_normal_;
  uint64_t last_granule_ = ~uint64_t{0};  // no granule: granules are below 2^58
};

}  // namespace ontile::sobel
