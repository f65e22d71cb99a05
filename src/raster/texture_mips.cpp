// Mip chain construction for Texture2D (see texture_mips.h): 2x2 box filter in linear space,
// odd sizes folded into the last texel, levels re-encoded with round to nearest.
#include "raster/texture_mips.h"

#include <cmath>

#include "raster/pixel_format.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr int kChannels = 4;

// Footprint of destination texel dst along one axis: 2 source texels, except that a
// destination of an odd-sized source folds the last source texel into its last texel (3
// texels), and a size-1 source maps 1:1. Every source texel counts once with equal weight.
struct Footprint {
  int first, count;
};
Footprint footprint(int dst, int dst_size, int src_size) {
  if (src_size == 1) return {0, 1};
  return {2 * dst, dst == dst_size - 1 ? src_size - 2 * dst : 2};
}

// Next mip level: each texel is the mean of its footprint (box filter; 2x2, or 3 texels
// weighted 1/3 each along an odd axis) in linear space, re-encoded with round to nearest.
template <TexelEncoding kEncoding>
void downsample_into(const Texture2D::Level& src, Texture2D::Level& dst) {
  const float* srgb = srgb8_decode_table().data();
  for (int y = 0; y < dst.height; ++y) {
    const Footprint fy = footprint(y, dst.height, src.height);
    for (int x = 0; x < dst.width; ++x) {
      const Footprint fx = footprint(x, dst.width, src.width);
      const int texels = fx.count * fy.count;
      double sum[kChannels] = {0.0, 0.0, 0.0, 0.0};
      uint32_t code_sum[kChannels] = {0, 0, 0, 0};
      for (int sy = fy.first; sy < fy.first + fy.count; ++sy) {
        for (int sx = fx.first; sx < fx.first + fx.count; ++sx) {
          const size_t s = (static_cast<size_t>(sy) * src.width + sx) * kChannels;
          for (int c = 0; c < kChannels; ++c) {
            if constexpr (kEncoding == TexelEncoding::Float32) {
              sum[c] += src.texels32f[s + c];
            } else if (kEncoding == TexelEncoding::Srgb8 && c < 3) {
              sum[c] += srgb[src.texels8[s + c]];
            } else {
              code_sum[c] += src.texels8[s + c];
            }
          }
        }
      }
      const size_t d = (static_cast<size_t>(y) * dst.width + x) * kChannels;
      for (int c = 0; c < kChannels; ++c) {
        if constexpr (kEncoding == TexelEncoding::Float32) {
          dst.texels32f[d + c] = static_cast<float>(sum[c] / texels);
        } else if (kEncoding == TexelEncoding::Srgb8 && c < 3) {
          dst.texels8[d + c] = linear_to_srgb8(static_cast<float>(sum[c] / texels));
        } else {
          // UNORM codes are linear, so the exact mean is code_sum / texels; round half up in
          // integers (same rule as float_to_unorm).
          dst.texels8[d + c] = static_cast<uint8_t>((2 * code_sum[c] + texels) / (2 * texels));
        }
      }
    }
  }
}

Texture2D::Level downsample(const Texture2D::Level& src, TexelEncoding encoding) {
  Texture2D::Level dst;
  dst.width = std::max(1, src.width / 2);
  dst.height = std::max(1, src.height / 2);
  const size_t count = static_cast<size_t>(dst.width) * dst.height * kChannels;
  switch (encoding) {
    case TexelEncoding::Unorm8:
      dst.texels8.resize(count);
      downsample_into<TexelEncoding::Unorm8>(src, dst);
      break;
    case TexelEncoding::Srgb8:
      dst.texels8.resize(count);
      downsample_into<TexelEncoding::Srgb8>(src, dst);
      break;
    case TexelEncoding::Float32:
      dst.texels32f.resize(count);
      downsample_into<TexelEncoding::Float32>(src, dst);
      break;
    case TexelEncoding::SurfaceFormat:
      // Render-target views (Texture2D::view_of_surface) sample level 0 in place: no mips.
      throw Error("texture: no mip chain for a view of a render target");
  }
  return dst;
}

}  // namespace

std::vector<Texture2D::Level> build_mip_chain(Texture2D::Level base, TexelEncoding encoding) {
  std::vector<Texture2D::Level> levels;
  levels.push_back(std::move(base));
  while (levels.back().width > 1 || levels.back().height > 1) {
    levels.push_back(downsample(levels.back(), encoding));
  }
  return levels;
}

}  // namespace ontile
