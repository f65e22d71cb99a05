// The AFBC size model (see afbc.h). The encoding, after Arm's AFBC 1.x layout: each 16x16
// superblock has a 16-byte header; a superblock whose pixels are all equal is stored in the
// header alone (AFBC's solid-colour block); otherwise each 4x4 subblock stores, per component of
// the format, its minimum (the component's width in bits) and every pixel's difference from it
// in the bits the subblock's range needs (ceil(log2(max - min + 1))), rounded up to whole bytes
// and never more than the subblock's uncompressed size (AFBC stores such subblocks raw).
// Components are the format's packed fields as unsigned integers, so the size is exact and
// lossless for every bit pattern.
#include "memory/afbc.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "util/parallel_for.h"

namespace ontile {
namespace {

// The packed fields of a 32-bit pixel, from bit 0 up.
struct ComponentLayout {
  int count = 0;
  int bits[4] = {0, 0, 0, 0};
};

ComponentLayout layout_of(PixelFormat format) {
  switch (format) {
    case PixelFormat::RGBA8_UNORM:
    case PixelFormat::RGBA8_SRGB: return {4, {8, 8, 8, 8}};
    case PixelFormat::RGB10A2_UNORM: return {4, {10, 10, 10, 2}};
    case PixelFormat::RG11B10_FLOAT: return {3, {11, 11, 10, 0}};
    case PixelFormat::RG16_FLOAT:
    case PixelFormat::RG16_UNORM: return {2, {16, 16, 0, 0}};
    case PixelFormat::R32_FLOAT: return {1, {32, 0, 0, 0}};
    default: return {};
  }
}

uint32_t load_pixel(const uint8_t* p) {
  uint32_t v;
  std::memcpy(&v, p, sizeof v);
  return v;  // little-endian packing (pixel_format.h), as the host stores it
}

// Payload bytes of the pixels [x0, x1) x [y0, y1) of one subblock.
uint64_t subblock_bytes(const ComponentLayout& layout, const uint8_t* pixels, size_t row_bytes, int x0, int x1,
                        int y0, int y1) {
  const int texels = (x1 - x0) * (y1 - y0);
  uint64_t bits = 0;
  int shift = 0;
  for (int c = 0; c < layout.count; ++c) {
    const int width = layout.bits[c];
    const uint32_t mask = width == 32 ? ~0u : ((1u << width) - 1u);
    uint32_t lo = ~0u, hi = 0;
    for (int y = y0; y < y1; ++y) {
      const uint8_t* row = pixels + static_cast<size_t>(y) * row_bytes;
      for (int x = x0; x < x1; ++x) {
        const uint32_t v = (load_pixel(row + static_cast<size_t>(x) * 4) >> shift) & mask;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
    bits += static_cast<uint64_t>(width) + static_cast<uint64_t>(texels) * std::bit_width(hi - lo);
    shift += width;
  }
  return std::min<uint64_t>((bits + 7) / 8, static_cast<uint64_t>(texels) * 4);
}

bool solid(const uint8_t* pixels, size_t row_bytes, int x0, int x1, int y0, int y1) {
  const uint32_t first = load_pixel(pixels + static_cast<size_t>(y0) * row_bytes + static_cast<size_t>(x0) * 4);
  for (int y = y0; y < y1; ++y) {
    const uint8_t* row = pixels + static_cast<size_t>(y) * row_bytes;
    for (int x = x0; x < x1; ++x) {
      if (load_pixel(row + static_cast<size_t>(x) * 4) != first) return false;
    }
  }
  return true;
}

}  // namespace

bool afbc_compresses(PixelFormat format, int samples) {
  return samples == 1 && layout_of(format).count > 0 && bytes_per_pixel(format) == 4;
}

std::vector<uint64_t> afbc_block_bytes(PixelFormat format, const uint8_t* pixels, int width, int height,
                                       size_t row_bytes) {
  const ComponentLayout layout = layout_of(format);
  const int blocks_x = (width + kAfbcBlockPx - 1) / kAfbcBlockPx;
  const int blocks_y = (height + kAfbcBlockPx - 1) / kAfbcBlockPx;
  std::vector<uint64_t> sizes(static_cast<size_t>(blocks_x) * blocks_y, 0);
  ontile::parallel_for(0, blocks_y, [&](int by) {
    for (int bx = 0; bx < blocks_x; ++bx) {
      const int x0 = bx * kAfbcBlockPx, y0 = by * kAfbcBlockPx;
      const int x1 = std::min(width, x0 + kAfbcBlockPx), y1 = std::min(height, y0 + kAfbcBlockPx);
      uint64_t bytes = kAfbcHeaderBytes;
      if (!solid(pixels, row_bytes, x0, x1, y0, y1)) {
        for (int sy = y0; sy < y1; sy += kAfbcSubblockPx) {
          for (int sx = x0; sx < x1; sx += kAfbcSubblockPx) {
            bytes += subblock_bytes(layout, pixels, row_bytes, sx, std::min(x1, sx + kAfbcSubblockPx), sy,
                                    std::min(y1, sy + kAfbcSubblockPx));
          }
        }
      }
      sizes[static_cast<size_t>(by) * blocks_x + bx] = bytes;
    }
  });
  return sizes;
}

}  // namespace ontile
