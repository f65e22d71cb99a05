// Block formats of compressed texture storage (see texture_compression.h).
#include "raster/texture_compression.h"

namespace ontile {

const char* texture_compression_name(TextureCompression compression) {
  switch (compression) {
    case TextureCompression::Astc4x4: return "astc4x4";
    case TextureCompression::Astc8x8: return "astc8x8";
    case TextureCompression::Etc2: return "etc2";
    case TextureCompression::None: break;
  }
  return "none";
}

std::optional<TextureCompression> parse_texture_compression(std::string_view name) {
  for (TextureCompression c : {TextureCompression::None, TextureCompression::Astc4x4,
                               TextureCompression::Astc8x8, TextureCompression::Etc2}) {
    if (name == texture_compression_name(c)) return c;
  }
  return std::nullopt;
}

BlockFormat block_format(TextureCompression compression, bool translucent) {
  switch (compression) {
    case TextureCompression::Astc4x4: return {16, 2, 2};  // ASTC: 128 bits per block, any size
    case TextureCompression::Astc8x8: return {16, 3, 3};
    case TextureCompression::Etc2: return {translucent ? 16u : 8u, 2, 2};  // RGBA8 = RGB8 + EAC
    case TextureCompression::None: break;
  }
  return {};
}

bool has_translucent_texel(const std::vector<uint8_t>& rgba) {
  for (size_t i = 3; i < rgba.size(); i += 4) {
    if (rgba[i] != 255) return true;
  }
  return false;
}

}  // namespace ontile
