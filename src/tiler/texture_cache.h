// The texture cache model: set-associative, LRU, fed with the 64-byte granules every tile's
// texture fetches touched, replayed in tile-index order so hits and misses are deterministic.
#pragma once
#include <cstdint>
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
  const TextureCacheConfig& config() const { return config_; }

 private:
  TextureCacheConfig config_;
  uint32_t sets_ = 0;
  std::vector<uint64_t> tags_;  // sets_ x ways, each set most recently used first, ~0 = empty
};

// Feeds every tile's texture granules through the cache, tiles in index order.
TextureTraffic replay_texture_traces(TextureCache& cache, const std::vector<TileTrace>& traces);

}  // namespace ontile
