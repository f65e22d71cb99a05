// The texture cache model: set-associative, LRU, fed with the 64-byte granules every tile's
// texture fetches touched, replayed in tile-index order so hits and misses are deterministic.
#pragma once
#include <cstdint>
#include <map>
#include <vector>

#include "tiler/tile_trace.h"

namespace ontile {

struct TextureCacheConfig {
  uint32_t size_bytes = 256 * 1024;
  uint32_t line_bytes = 64;   // a power of two >= 64 (the trace granule)
  uint32_t ways = 16;
};

struct TextureTraffic {
  uint64_t accesses = 0;   // granule lookups (consecutive repeats within a tile already merged)
  uint64_t hits = 0;
  uint64_t misses = 0;
  uint64_t bytes_read = 0;  // misses x line_bytes
  void add(const TextureTraffic& o);
};

class TextureCache {
 public:
  explicit TextureCache(const TextureCacheConfig& config);  // throws ontile::Error if invalid
  // Looks up the line holding `granule`; returns true on a hit. Misses fill the LRU way.
  bool access(uint64_t granule);
  // Maps a traced texture granule (texture region id << 34 | offset) to this frame's address
  // space: each texture is placed, 4 KiB aligned, after the ones used before it in this frame.
  // Granules outside any texture region (id 0) are used as they are.
  uint64_t frame_granule(uint64_t traced_granule);
  // The first frame granule of texture region `id` (placing it now if this is its first use).
  uint64_t frame_base_granule(uint64_t id);
  const TextureCacheConfig& config() const { return config_; }
  // The set a frame granule's line maps to: accesses to different sets never interact, so
  // the replay hands disjoint groups of sets to different threads.
  uint32_t set_of(uint64_t frame_granule) const;
  uint32_t set_count() const { return sets_; }
  static constexpr int kRegionShiftGranules = 34;  // Texture2D::kTextureIdShift - 6

 private:
  TextureCacheConfig config_;
  uint32_t sets_ = 0;
  std::vector<uint64_t> tags_;  // sets_ x ways, each set most recently used first, ~0 = empty
  std::map<uint64_t, uint64_t> frame_base_granule_;  // texture id -> first granule this frame
  uint64_t next_frame_granule_ = 0;
  // The last texture looked up: consecutive granules nearly always share a texture, so the map
  // is searched only when the texture changes.
  uint64_t last_id_ = 0, last_base_granule_ = 0;
};

// Feeds every tile's texture granules through the cache, tiles in index order.
TextureTraffic replay_texture_traces(TextureCache& cache, const std::vector<TileTrace>& traces);

}  // namespace ontile
