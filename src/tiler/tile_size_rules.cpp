// The drivers' tile-size rules (see tile_size_rules.h).
#include "tiler/tile_size_rules.h"

#include <algorithm>
#include <bit>
#include <string>

#include "util/error.h"

namespace ontile {
namespace {

uint32_t ceil_log2(uint32_t v) { return v <= 1 ? 0 : static_cast<uint32_t>(std::bit_width(v - 1)); }

// panfrost's largest tile before Valhall v10 (pan_max_effective_tile_size): 16x16.
constexpr uint32_t kPanfrostMaxTilePixels = 16 * 16;
constexpr uint32_t kPanfrostMinTilePixels = 4 * 4;

int div_align(int num, int denom, int align) {
  const int q = (num + denom - 1) / denom;
  return (q + align - 1) / align * align;
}

}  // namespace

int panfrost_tib_bytes_per_sample(PixelFormat format) {
  switch (format) {
    // Blendable formats sit in the tile buffer at 32 bits, extra bits padding or dither.
    case PixelFormat::RGBA8_UNORM:
    case PixelFormat::RGBA8_SRGB:
    case PixelFormat::RGB10A2_UNORM:
      return 4;
    default:
      return static_cast<int>(std::bit_ceil(static_cast<unsigned>(bytes_per_pixel(format))));
  }
}

TileSize panfrost_tile_size(const TileMemoryUse& use, uint32_t tile_buffer_bytes, bool pipelining_required) {
  // No colour target: the hardware still needs one, RGBA8 (pan_cbuf_bytes_per_pixel).
  uint32_t bytes_per_px = use.colors.empty() ? 4u * static_cast<uint32_t>(use.samples) : 0u;
  for (const PixelFormat f : use.colors) {
    bytes_per_px += static_cast<uint32_t>(panfrost_tib_bytes_per_sample(f) * use.samples);
  }
  uint32_t pixels = tile_buffer_bytes >> ceil_log2(bytes_per_px);
  if (!pipelining_required && pixels < kPanfrostMinTilePixels) pixels *= 2;
  pixels = std::clamp(pixels, 1u, kPanfrostMaxTilePixels);
  // The tile's shape (pan_desc.h): height 2^floor(n/2), width 2^ceil(n/2) for 2^n pixels.
  const int n = std::countr_zero(std::bit_floor(pixels));
  return TileSize{1 << ((n + 1) >> 1), 1 << (n >> 1)};
}

TileSize asahi_tile_size(const TileMemoryUse& use) {
  // agx_build_tilebuffer_layout places the targets in descending order of alignment (their size),
  // each naturally aligned, so no padding is left between them.
  std::vector<uint32_t> sizes;
  for (const PixelFormat f : use.colors) sizes.push_back(static_cast<uint32_t>(bytes_per_pixel(f)));
  std::stable_sort(sizes.begin(), sizes.end(), [](uint32_t a, uint32_t b) { return a > b; });
  uint32_t offset = 0;
  for (const uint32_t size : sizes) offset = (offset + size - 1) / size * size + size;
  const uint32_t sample_bytes = (offset + 7) / 8 * 8;
  const uint32_t bytes_per_px = sample_bytes * static_cast<uint32_t>(use.samples);
  for (const TileSize size : {TileSize{32, 32}, TileSize{32, 16}, TileSize{16, 16}}) {
    if (bytes_per_px * static_cast<uint32_t>(size.width_px * size.height_px) <= kAsahiMaxBytesPerTile) return size;
  }
  throw Error("asahi tile size: " + std::to_string(bytes_per_px) +
              " bytes per pixel of colour do not fit a 16x16 tile of the Apple G13 tile buffer (" +
              std::to_string(kAsahiMaxBytesPerTile) + " bytes)");
}

TileSize freedreno_tile_size(const TileMemoryUse& use, int width_px, int height_px, const FreedrenoGmem& gmem) {
  std::vector<uint64_t> cpp;  // bytes per pixel of each buffer GMEM holds, colour then depth
  for (const PixelFormat f : use.colors) cpp.push_back(static_cast<uint64_t>(bytes_per_pixel(f)) * use.samples);
  if (use.depth) cpp.push_back(static_cast<uint64_t>(bytes_per_pixel(*use.depth)) * use.samples);
  const auto layout_fits = [&](int nx, int ny) {
    if (nx <= 0 || ny <= 0) return false;
    const int w = div_align(width_px, nx, gmem.tile_align_w);
    const int h = div_align(height_px, ny, gmem.tile_align_h);
    if (w > gmem.tile_max_w || h > gmem.tile_max_h) return false;
    uint64_t total = 0;
    for (const uint64_t c : cpp) {
      total = (total + gmem.page_align_bytes - 1) / gmem.page_align_bytes * gmem.page_align_bytes;
      total += c * static_cast<uint64_t>(w) * static_cast<uint64_t>(h);
    }
    return total <= gmem.gmem_bytes;
  };
  int nx = 1, ny = 1;
  while (div_align(width_px, nx, gmem.tile_align_w) > gmem.tile_max_w) ++nx;
  while (div_align(height_px, ny, gmem.tile_align_h) > gmem.tile_max_h) ++ny;
  while (!layout_fits(nx, ny)) {
    if (ny > nx) {
      ++nx;
    } else {
      ++ny;
    }
    if (nx > width_px && ny > height_px) throw Error("freedreno tile size: the attachments do not fit GMEM");
  }
  if ((nx - 1) * (ny + 1) < nx * ny && layout_fits(nx - 1, ny + 1)) {
    --nx;
    ++ny;
  } else if ((nx + 1) * (ny - 1) < nx * ny && layout_fits(nx + 1, ny - 1)) {
    ++nx;
    --ny;
  }
  return TileSize{div_align(width_px, nx, gmem.tile_align_w), div_align(height_px, ny, gmem.tile_align_h)};
}

}  // namespace ontile
