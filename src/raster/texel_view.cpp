// Texture2D::texel_view (texture.h): direct, untraced access to one level's texels for kernels
// that compute their own texel indices (the Sobel edge pass).
#include "raster/pixel_format.h"
#include "raster/texture.h"

namespace ontile {

Texture2D::TexelView Texture2D::texel_view(int level) const {
  const Level& l = levels_[level];
  TexelView v;
  if (encoding_ == TexelEncoding::Float32) {
    v.texels32f = l.texels32f.data();
  } else if (encoding_ == TexelEncoding::SurfaceFormat) {
    v.surface_bytes = l.surface_bytes;
    v.surface_format = l.surface_format;
  } else {
    // The tables fetch() decodes with: sRGB colour channels for Srgb8, alpha always unorm.
    v.texels8 = l.bytes8();
    v.rgb_decode = encoding_ == TexelEncoding::Srgb8 ? srgb8_decode_table().data()
                                                     : unorm8_decode_table().data();
    v.alpha_decode = unorm8_decode_table().data();
  }
  v.width = l.width;
  v.height = l.height;
  v.address = l.address;
  v.memory_bytes_per_texel = l.memory_bytes_per_texel;
  return v;
}

}  // namespace ontile
