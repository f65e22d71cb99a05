// The texture cache model: set-associative, LRU, fed with the 64-byte granules every tile's
// texture fetches touched, replayed in tile-index order so hits and misses are deterministic.
#pragma once
#include <cstdint>
#include <map>
#include <vector>

#include "memory/pass_memory.h"
#include "memory/set_associative_cache.h"
#include "memory/tile_trace.h"

namespace ontile {

struct TextureCacheConfig {
  uint32_t size_bytes = 256 * 1024;
  uint32_t line_bytes = 64;   // a power of two >= 64 (the trace granule)
  uint32_t ways = 16;
};

// The texture cache on the shared SetAssociativeCache: line = granule / (line_bytes / 64),
// set = line % sets, tag = line.
class TextureCache {
 public:
  explicit TextureCache(const TextureCacheConfig& config);  // throws ontile::Error if invalid

  // Every set of the cache (index_shift 0, so set index = set number).
  const SetArray& sets() const { return cache_.sets(); }
  bool access(uint64_t granule) { return cache_.sets().access(granule); }
  uint32_t set_of(uint64_t frame_granule) const {
    return sets().index_of_line(frame_granule >> sets().line_shift);
  }
  uint32_t set_count() const { return sets().sets; }
  const TextureCacheConfig& config() const { return config_; }

  // Maps a traced texture granule (texture region id << 34 | offset) to this frame's address
  // space: each texture is placed, 4 KiB aligned, after the ones used before it in this frame.
  // Granules outside any texture region (id 0) are used as they are.
  uint64_t frame_granule(uint64_t traced_granule) {
    return traced_granule + place(traced_granule >> kRegionShiftGranules);
  }
  // The first frame granule of texture region `id` (placing it now if this is its first use).
  uint64_t frame_base_granule(uint64_t id);
  // What turns a traced granule of region `id` into its frame granule: frame = traced + this
  // (mod 2^64), 0 for id 0. Places the region now if this is its first use in the frame.
  uint64_t place(uint64_t id);
  // place() for a region already placed (read-only, so replay threads may share it); 0 for id 0.
  uint64_t placed_offset(uint64_t id) const;
  static constexpr int kRegionShiftGranules = 34;  // Texture2D::kTextureIdShift - 6
  // Placed regions end below this frame granule (16 TiB of textures in one frame; more throws),
  // which the replay's SIMD hit test relies on (texture_replay_kernel.h, RegionTable).
  static constexpr uint64_t kFrameGranuleLimit = uint64_t{1} << 38;

 private:
  TextureCacheConfig config_;
  SetAssociativeCache cache_;
  std::map<uint64_t, uint64_t> frame_base_granule_;  // texture id -> first granule this frame
  uint64_t next_frame_granule_ = 0;
};

// Where a replay's misses came from: per tile (tile index order) and per texture region id
// (Texture2D's id; 0 for granules outside any texture). Both sum to the replay's misses.
struct TextureReplayDetail {
  std::vector<uint64_t> misses_per_tile;
  std::map<uint64_t, uint64_t> misses_per_region;
};

// Feeds every tile's texture granules through the cache, tiles in index order, with the counts
// of a serial per-access replay at any thread count (texture_replay.cpp). Fills `detail` when
// given.
TextureTraffic replay_texture_traces(TextureCache& cache, const std::vector<TileTrace>& traces,
                                     TextureReplayDetail* detail = nullptr);

}  // namespace ontile
