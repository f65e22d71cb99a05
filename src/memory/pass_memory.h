// Plain descriptions of what a render pass moves, as the memory models see them: the pass's
// attachments (their formats, load/store actions and the bytes of their surfaces in external
// memory), its tile grid and subpasses, and the traffic a model reports back. The tiler fills
// the descriptions; the memory layer never sees tiler types.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "raster/pixel_format.h"

namespace ontile {

// One screen tile: its top-left pixel and its size, clipped to the render target.
struct TileRect {
  int x0 = 0, y0 = 0;
  int width = 0, height = 0;
};

// A surface's pixels in external memory: row-major, a pixel's samples adjacent. bytes == nullptr:
// no surface.
struct SurfaceBytes {
  PixelFormat format = PixelFormat::RGBA8_UNORM;
  int width = 0, height = 0, samples = 1;
  const uint8_t* bytes = nullptr;
  size_t row_bytes = 0;
  explicit operator bool() const { return bytes != nullptr; }
  const uint8_t* pixel(int x, int y) const {
    return bytes + static_cast<size_t>(y) * row_bytes +
           static_cast<size_t>(x) * samples * bytes_per_pixel(format);
  }
};

// An attachment of the pass (Vulkan load/store semantics; docs/memory-model.md).
struct AttachmentMemory {
  std::string name;
  PixelFormat format = PixelFormat::RGBA8_UNORM;
  bool is_depth = false;
  bool loads = false;     // LoadAction::Load from a bound surface
  bool clears = false;    // LoadAction::Clear
  bool stores = false;    // Store or StoreAndResolve to a bound surface
  bool resolves = false;  // Resolve or StoreAndResolve to a bound resolve surface
  SurfaceBytes surface;          // none: transient
  SurfaceBytes resolve_surface;  // none: no resolve
  bool transient() const { return !surface; }
};

struct PassMemoryDesc {
  std::string name;
  int width_px = 0, height_px = 0, samples = 1;
  int tile_width_px = 16, tile_height_px = 16;
  int depth_index = -1;
  std::vector<AttachmentMemory> attachments;
  std::vector<std::vector<int>> subpass_color_outputs;  // per subpass, the attachments it writes

  int tiles_x() const { return (width_px + tile_width_px - 1) / tile_width_px; }
  int tiles_y() const { return (height_px + tile_height_px - 1) / tile_height_px; }
  int tile_count() const { return tiles_x() * tiles_y(); }
  TileRect tile_rect(int tile) const;
};

// What one attachment of a pass moved in external memory.
struct AttachmentTraffic {
  std::string name;
  PixelFormat format = PixelFormat::RGBA8_UNORM;
  bool transient = false;
  uint64_t bytes_loaded = 0;
  uint64_t bytes_stored = 0;    // Store of all samples
  uint64_t bytes_resolved = 0;  // Resolve writes of the averaged pixel
  // AFBC (TilerConfig::afbc): whether any of the above was priced compressed, and the bytes that
  // saved against the uncompressed size (negative when headers outweigh the savings).
  bool afbc = false;
  int64_t afbc_bytes_saved = 0;
  // Transaction elimination (TilerConfig::transaction_elimination): tile writes (stores and
  // resolves) skipped because the tile's CRC equalled the previous frame's, and the bytes they
  // would have written (compressed when AFBC priced them).
  uint64_t te_tiles_eliminated = 0;
  uint64_t te_bytes_saved = 0;
};

// Cache lookups of a read-only cache model (texture cache, parameter-buffer cache).
struct TextureTraffic {
  uint64_t accesses = 0;   // line lookups (texture: consecutive repeats within a tile merged)
  uint64_t hits = 0;
  uint64_t misses = 0;
  uint64_t bytes_read = 0;  // misses x line_bytes
  void add(const TextureTraffic& o);
};

// The attachment side of a pass as a memory model priced it.
struct PassAttachmentTraffic {
  std::string architecture;  // "tbdr" or "imr"
  std::vector<AttachmentTraffic> attachments;  // one per pass attachment
  // Each tile's share of the loads and of the stores and resolves (tile-index order); all 0 on
  // a model without tile memory.
  std::vector<uint64_t> tile_bytes_loaded, tile_bytes_stored;
  uint64_t render_target_cache_hits = 0, render_target_cache_misses = 0;  // IMR only
  bool transaction_elimination = false;  // whether TE compared this pass's tiles
};

}  // namespace ontile
