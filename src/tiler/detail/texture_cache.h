// The texture cache model: set-associative, LRU, fed with the 64-byte granules every tile's
// texture fetches touched, replayed in tile-index order so hits and misses are deterministic.
#pragma once
#include <cstdint>
#include <map>
#include <vector>

#include "tiler/detail/tile_trace.h"

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

// The ways of a group of cache sets and the mapping of lines onto them. Each set keeps its lines
// ordered from most to least recently used (exact LRU). Storage is way-major, way w of set index
// i at tags[w * sets + i], so the most recent ways of all sets are one array: replay loops test
// "is this line its set's most recent one" (about 96 % of the benchmark scenes' accesses) with
// one load, on SIMD lanes by a gather (texture_replay_kernel.h). A SetArray is a view: copies
// share the ways.
struct SetArray {
  uint64_t* tags = nullptr;  // sets x ways, ~0 = empty
  uint32_t sets = 0, ways = 0;
  int line_shift = 0;          // line = frame granule >> line_shift (log2(line_bytes / 64))
  int index_shift = 0;         // set index = (line >> index_shift) % sets
  bool sets_are_power_of_two = false;

  uint32_t index_of_line(uint64_t line) const {
    const uint64_t above = line >> index_shift;
    return static_cast<uint32_t>(sets_are_power_of_two ? above & (sets - 1) : above % sets);
  }
  // Looks up the line holding frame granule `granule`; true on a hit. Misses fill the LRU way.
  bool access(uint64_t granule) const { return access_line(granule >> line_shift); }
  // A hit in the most recent way is one compare and no reordering. Otherwise the line moves to
  // the front in one pass: on a hit at position p ways 0..p-1 move to 1..p; on a miss every way
  // moves and the last (the least recent, or an empty way: lines only ever enter at the front,
  // so empty ways stay at the back) drops out. Inline, so replay loops make no call per access.
  bool access_line(uint64_t line) const {
    uint64_t* way = tags + index_of_line(line);
    if (*way == line) return true;
    uint64_t carried = *way;
    *way = line;
    for (uint32_t position = 1; position < ways; ++position) {
      way += sets;
      const uint64_t held = *way;
      *way = carried;
      if (held == line) return true;
      carried = held;
    }
    return false;
  }
};

// Mapping (plain modulo, no hashing, so tests can place lines in sets by hand):
//   line = granule / (line_bytes / 64), set = line % sets, tag = line.
// Keeping the whole line number as the tag makes a hit unambiguous whatever the set count.
class TextureCache {
 public:
  explicit TextureCache(const TextureCacheConfig& config);  // throws ontile::Error if invalid
  // Moves keep the ways' storage, which sets_ points at; a copy would share it.
  TextureCache(TextureCache&&) = default;
  TextureCache& operator=(TextureCache&&) = default;
  TextureCache(const TextureCache&) = delete;
  TextureCache& operator=(const TextureCache&) = delete;

  // Every set of the cache (index_shift 0, so set index = set number).
  const SetArray& sets() const { return sets_; }
  bool access(uint64_t granule) { return sets_.access(granule); }
  uint32_t set_of(uint64_t frame_granule) const {
    return sets_.index_of_line(frame_granule >> sets_.line_shift);
  }
  uint32_t set_count() const { return sets_.sets; }
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

 private:
  TextureCacheConfig config_;
  std::vector<uint64_t> tags_;  // the ways of every set (see SetArray)
  SetArray sets_;
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
