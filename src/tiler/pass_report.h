// Counters a render pass produces: geometry, parameter-buffer and attachment traffic in bytes,
// fragment work, and per-attachment load/store bytes. All integers, so sums are exact and
// independent of the order tiles ran in.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "raster/pixel_format.h"
#include "memory/pass_memory.h"

namespace ontile {

struct GeometryCounters {
  uint64_t triangles_submitted = 0;
  uint64_t triangles_non_finite = 0;   // dropped: a NaN/Inf clip-space position
  uint64_t triangles_culled = 0;       // back/front-face culling
  uint64_t triangles_zero_area = 0;    // degenerate after snapping
  uint64_t triangles_outside = 0;      // trivially rejected or clipped away entirely
  uint64_t triangles_clipped = 0;      // needed near/far/guard-band clipping
  uint64_t triangles_binned = 0;       // set-up triangles in the parameter buffer
  uint64_t vertices_shaded = 0;
  uint64_t varyings_sanitized = 0;     // NaN/Inf varyings replaced by 0
  uint64_t tile_list_entries = 0;      // (tile, triangle) pairs
  uint64_t index_bytes_read = 0;
  uint64_t vertex_bytes_read = 0;      // unique vertices fetched per draw
  uint64_t parameter_bytes_written = 0;
  // Of parameter_bytes_written, the post-transform vertices' positions and varyings (the rest
  // are primitive records and tile-list entries).
  uint64_t parameter_position_bytes_written = 0;
  uint64_t parameter_varying_bytes_written = 0;

  void add(const GeometryCounters& o);
};

struct TileCounters {
  uint64_t tiles_executed = 0;         // tiles that had primitives to rasterize
  uint64_t parameter_bytes_read = 0;
  uint64_t fragments_shaded = 0;       // covered pixels whose fragment shader ran
  uint64_t fragments_depth_rejected = 0;  // covered pixels with every sample failing depth
  uint64_t samples_written = 0;        // colour/depth sample writes that passed all tests
  // Hierarchical rasterization (8x8-pixel cells, raster/cell_raster.h): cells a triangle
  // covered, and covered cells skipped whole because hierarchical Z proved every sample fails
  // the depth test (their pixels also count in fragments_depth_rejected).
  uint64_t cells_rasterized = 0;
  uint64_t cells_hiz_rejected = 0;

  void add(const TileCounters& o);
};

// One tile's share of a pass: its primitive list, fragment work and the external bytes charged
// to it. Every count but `thread` and `order` is deterministic, and each sums over the tiles to
// the pass's own figure (attachment bytes are the tile's area times the format, so on the IMR
// model, which has no tile memory, they are 0 and only the pass totals count).
struct TileStats {
  uint32_t triangles = 0;               // entries in the tile's primitive list
  uint64_t fragments_shaded = 0;
  uint64_t fragments_depth_rejected = 0;
  uint64_t cells_rasterized = 0;
  uint64_t cells_hiz_rejected = 0;      // 8x8 cells skipped whole by hierarchical Z
  uint64_t parameter_bytes_read = 0;    // as the tile read its list (before any parameter cache)
  uint64_t bytes_loaded = 0;            // attachment loads into this tile's memory
  uint64_t bytes_stored = 0;            // attachment stores and resolves from it
  uint64_t texture_bytes_read = 0;      // texture-cache misses of the tile's fetches x line size
  // Scheduling, which differs from run to run: the worker thread that ran the tile (oneTBB's
  // arena slot) and the position at which it started among the pass's tiles.
  int thread = -1;
  uint32_t order = 0;
};

// Texture-cache misses of one texture the pass sampled: a render target written by an earlier
// pass (sampled in place or decoded once) or a scene texture.
struct TextureSourceTraffic {
  std::string name;
  bool render_target = false;
  uint64_t misses = 0;
  uint64_t bytes_read = 0;  // misses x line size
};

struct PassReport {
  std::string name;
  std::string architecture = "tbdr";  // "tbdr" or "imr"
  int width_px = 0, height_px = 0, samples = 1;
  int tile_width_px = 0, tile_height_px = 0;
  bool tile_size_reduced = false;  // the colour budget forced smaller tiles
  int color_bits_per_px = 0;       // tile-memory colour bits per pixel the pass needs
  uint64_t tiles_total = 0;
  GeometryCounters geometry;
  TileCounters tiles;
  std::vector<AttachmentTraffic> attachments;
  TextureTraffic texture;
  TextureTraffic parameter_cache;  // lookups when the parameter cache is modelled (else zero)
  uint64_t render_target_cache_hits = 0, render_target_cache_misses = 0;  // IMR only
  bool transaction_elimination = false;  // TE compared this pass's tiles (16x16 tiles, TE on)
  // Texture bytes by the texture they were read from, largest first (ties by name).
  std::vector<TextureSourceTraffic> texture_sources;
  std::vector<TileStats> tile_stats;  // tiles_total entries, row-major (tiles_x() per row)
  // Wall-clock times (not deterministic; never part of comparisons).
  double binning_ms = 0.0;
  double tiles_ms = 0.0;

  int tiles_x() const { return tile_width_px ? (width_px + tile_width_px - 1) / tile_width_px : 0; }
  int tiles_y() const { return tile_height_px ? (height_px + tile_height_px - 1) / tile_height_px : 0; }
  uint64_t attachment_bytes_loaded() const;
  uint64_t attachment_bytes_stored() const;  // Store + Resolve
  uint64_t bytes_read() const;
  uint64_t bytes_written() const;
};

}  // namespace ontile
