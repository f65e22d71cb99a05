// PNG encoding of the generated textures (8-bit RGB) with stb_image_write from Debian's libstb,
// the library tinygltf already decodes images with. Its encoder (per-row filter chosen by the
// smallest sum of absolute residuals, its own deflate, no time or text chunks) depends on nothing
// but the pixels, so `gen-scene` writes the same bytes on every run with a given libstb.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/gen/procedural_textures.h"

namespace ontile::gen {

// The image as a complete PNG file (8-bit truecolour, no interlace). Throws Error for an image
// whose byte count does not match its size.
std::vector<uint8_t> encode_png(const RgbImage& image);

}  // namespace ontile::gen
