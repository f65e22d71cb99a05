// Self-contained, byte-deterministic PNG encoder for the generated textures (8-bit RGB). Written
// here rather than taken from a library so the bytes cannot change with a library version.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/gen/procedural_textures.h"

namespace ontile::gen {

// PNG (RFC 2083) with one IDAT holding a zlib stream (RFC 1950) of fixed-Huffman deflate blocks
// (RFC 1951 3.2.6) over greedy LZ77 matches; each row uses the filter with the smallest sum of
// absolute residuals (the heuristic the PNG spec suggests, 12.8).
std::vector<uint8_t> encode_png(const RgbImage& image);

}  // namespace ontile::gen
