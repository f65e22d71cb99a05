// How tile-based GPUs pick the tile size of a render pass from its attachments, after the open
// drivers in Mesa (rules learnt from their source and restated here, constants cited):
// panfrost (Arm Mali), asahi (Apple G13) and freedreno (Qualcomm Adreno 6xx). ontile's default
// rule (select_tile_size in render_pass_executor.h) halves a square tile until the colour
// attachments fit a bits-per-pixel budget.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "raster/pixel_format.h"

namespace ontile {

enum class TileSizeRule {
  Budget,     // ontile's default: configured square tile, halved until the colour budget fits
  Panfrost,   // pan_select_tile_size
  Asahi,      // agx_select_tile_size
  Freedreno,  // calc_nbins / layout_gmem
};

struct TileSize {
  int width_px = 0, height_px = 0;
  bool operator==(const TileSize&) const = default;
};

// The attachments a pass keeps in tile memory.
struct TileMemoryUse {
  std::vector<PixelFormat> colors;    // colour attachments, transient ones included
  std::optional<PixelFormat> depth;   // the depth attachment, if any
  int samples = 1;
};

// panfrost (src/panfrost/lib/pan_desc.c, pan_select_tile_size; pan_bytes_per_pixel_tib): each
// colour target takes 4 bytes per sample in the tile buffer when its format is blendable (8-bit
// UNORM/sRGB, RGB10A2), else its size rounded up to a power of two; the tile holds
// tile_buffer_bytes >> ceil(log2(bytes per pixel)) pixels, doubled when that is under 16 (the
// second half of the buffer, without pipelining; not on v6, `pipelining_required`), at most 16x16
// (pan_max_effective_tile_size before v10), shaped 2^ceil(n/2) x 2^floor(n/2).
// tile_buffer_bytes: panfrost_query_optimal_tib_size (Mali-G71 8 KiB; Mali-G76 16 KiB / 2).
TileSize panfrost_tile_size(const TileMemoryUse& use, uint32_t tile_buffer_bytes, bool pipelining_required);
int panfrost_tib_bytes_per_sample(PixelFormat format);

// asahi (src/asahi/lib/agx_tilebuffer.c, agx_build_tilebuffer_layout, agx_select_tile_size): a
// sample's colour targets by descending size, each naturally aligned, rounded up to 8 bytes, x
// samples, must fit 32 KiB - 1 per tile: 32x32, else 32x16, else 16x16. Throws ontile::Error past
// 16x16 (asahi spills render targets to memory there; ontile does not model it).
TileSize asahi_tile_size(const TileMemoryUse& use);
constexpr uint32_t kAsahiMaxBytesPerTile = 32768 - 1;  // MAX_BYTES_PER_TILE on G13

// freedreno (src/gallium/drivers/freedreno/freedreno_gmem.c, calc_nbins and layout_gmem): GMEM
// holds every colour target and depth, each at a gmem_page_align x 4 KiB aligned offset; the
// bins grow in number (rows when there are no more rows than columns, else columns) until
// their buffers fit, bin sides aligned to tile_align_w x tile_align_h and at most
// tile_max_w x tile_max_h, then one column is traded for a row (or back) when that gives fewer
// bins that still fit.
struct FreedrenoGmem {
  uint32_t gmem_bytes = 1024 * 1024;  // Adreno 630 (Linux msm adreno_device.c: SZ_1M)
  int tile_align_w = 32, tile_align_h = 16;  // src/freedreno/common/a6xx_gpu.py, GPUId(630)
  int tile_max_w = 1024, tile_max_h = 1008;  // A6xxGPUInfo for a6xx
  uint32_t page_align_bytes = 2 * 4096;      // gmem_page_align = num_ccu (2 on A630) pages
};
TileSize freedreno_tile_size(const TileMemoryUse& use, int width_px, int height_px, const FreedrenoGmem& gmem);

}  // namespace ontile
