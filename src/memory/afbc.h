// Arm Frame Buffer Compression (AFBC) as ontile models it: the exact size a surface's stored
// pixels take under a documented lossless per-block encoding (docs/memory-model.md, "AFBC"), so
// a TBDR pass's stores and loads of eligible attachments are priced at their compressed size.
// Like Mali, only single-sample colour surfaces of up to 32 bits per pixel are compressed; depth,
// multisampled and transient attachments are not (Vulkan-Samples afbc; panfrost).
#pragma once
#include <cstdint>
#include <vector>

#include "raster/pixel_format.h"

namespace ontile {

constexpr int kAfbcBlockPx = 16;          // a superblock covers 16x16 pixels
constexpr int kAfbcSubblockPx = 4;        // of 16 subblocks of 4x4 pixels
constexpr uint64_t kAfbcHeaderBytes = 16;  // per superblock

// Whether surfaces of `format` with `samples` samples per pixel are compressed.
bool afbc_compresses(PixelFormat format, int samples);

// The compressed bytes of every 16x16 superblock of a width x height surface whose pixels are
// `pixels` (bytes_per_pixel(format) each, row-major, `row_bytes` apart), superblock rows top to
// bottom, each left to right: the header plus the payload. Deterministic; runs its block rows
// in parallel. `format` must satisfy afbc_compresses(format, 1).
std::vector<uint64_t> afbc_block_bytes(PixelFormat format, const uint8_t* pixels, int width, int height,
                                       size_t row_bytes);

}  // namespace ontile
