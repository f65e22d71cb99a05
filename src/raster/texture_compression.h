// Block-compressed texture storage (ASTC, ETC2) as the texture-cache model sees it: how many
// bytes a block of how many texels takes. Sampling always reads the decoded texels: ontile
// prices the bandwidth of block compression, not its quality loss.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace ontile {

// ASTC 4x4 and 8x8 store 16 bytes per block (1 and 0.25 bytes per texel); ETC2 stores 8 bytes
// per 4x4 block for an opaque image (ETC2 RGB8, 0.5 bytes per texel) and 16 when any texel's
// alpha is below 255 (ETC2 RGBA8 with EAC alpha). Only scene textures are compressed; render
// targets sampled as textures never are (the GPU writes them).
enum class TextureCompression { None, Astc4x4, Astc8x8, Etc2 };

const char* texture_compression_name(TextureCompression compression);  // "none", "astc4x4", ...
std::optional<TextureCompression> parse_texture_compression(std::string_view name);

struct BlockFormat {
  uint32_t bytes = 0;  // 0: uncompressed
  int width_shift = 0, height_shift = 0;  // block side = 1 << shift texels
};
// `translucent`: the image has a texel with alpha below 255 (selects ETC2's RGBA8 blocks).
BlockFormat block_format(TextureCompression compression, bool translucent);

// Whether any texel of RGBA8 texels (4 bytes each) has alpha below 255.
bool has_translucent_texel(const std::vector<uint8_t>& rgba);

}  // namespace ontile
