// Texel index wrapping (Vulkan "Wrapping Operation"), shared by the scalar and SIMD samplers so
// both select the same texels.
#pragma once

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

}  // namespace ontile
