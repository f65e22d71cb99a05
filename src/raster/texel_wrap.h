// Texel index wrapping (Vulkan "Wrapping Operation"), shared by the scalar and SIMD samplers so
// both select the same texels.
#pragma once
#include <cstddef>

#include "raster/texture.h"

namespace ontile {

// Integer texel index -> [0, size), Vulkan "Wrapping Operation".
inline int wrap_texel_index(int i, int size, WrapMode mode) {
  if (static_cast<unsigned>(i) < static_cast<unsigned>(size)) return i;  // common case
  switch (mode) {
    case WrapMode::Repeat: {
      const int m = i % size;
      return m < 0 ? m + size : m;
    }
    case WrapMode::ClampToEdge:
      return i < 0 ? 0 : size - 1;
    case WrapMode::MirroredRepeat: {
      // (size - 1) - mirror((i mod 2*size) - size), mirror(n) = n >= 0 ? n : -(1 + n)
      const int period = 2 * size;
      int m = i % period;
      if (m < 0) m += period;
      const int n = m - size;
      return (size - 1) - (n >= 0 ? n : -(1 + n));
    }
  }
  return 0;
}

// The 2x2 bilinear footprint whose top-left texel is (i0, j0), wrapped: the texel indices of
// t00, t10, t01, t11 (row-major within a level of width w), in the order samplers read them.
inline void bilinear_footprint(int i0, int j0, int w, int h, WrapMode wrap_u, WrapMode wrap_v,
                               size_t taps[4]) {
  int xa = i0, xb = i0 + 1, ya = j0, yb = j0 + 1;
  if (static_cast<unsigned>(i0) >= static_cast<unsigned>(w - 1)) {
    xa = wrap_texel_index(i0, w, wrap_u);
    xb = wrap_texel_index(i0 + 1, w, wrap_u);
  }
  if (static_cast<unsigned>(j0) >= static_cast<unsigned>(h - 1)) {
    ya = wrap_texel_index(j0, h, wrap_v);
    yb = wrap_texel_index(j0 + 1, h, wrap_v);
  }
  const size_t row_a = static_cast<size_t>(ya) * w, row_b = static_cast<size_t>(yb) * w;
  taps[0] = row_a + xa;
  taps[1] = row_a + xb;
  taps[2] = row_b + xa;
  taps[3] = row_b + xb;
}

}  // namespace ontile
