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

// Mapping (plain modulo, no hashing, so tests can place lines in sets by hand):
//   line = granule / (line_bytes / 64), set = line % sets, tag = line.
// Keeping the whole line number as the tag makes a hit unambiguous whatever the set count.
class TextureCache {
 public:
  explicit TextureCache(const TextureCacheConfig& config);  // throws ontile::Error if invalid
  // Moves keep the ways' storage, which lookup_ points at; a copy would share it.
  TextureCache(TextureCache&&) = default;
  TextureCache& operator=(TextureCache&&) = default;
  TextureCache(const TextureCache&) = delete;
  TextureCache& operator=(const TextureCache&) = delete;

  // The mapping and the LRU state's address, by value: what a lookup reads, held in registers
  // by replay loops (through a TextureCache reference the compiler reloads them every access).
  // Copies share the cache's ways; ways of different sets may be accessed concurrently.
  class Lookup {
   public:
    // Looks up the line holding frame granule `granule`; returns true on a hit. Misses fill the
    // LRU way.
    bool access(uint64_t granule) const {
      return sets_are_power_of_two_ ? access_in<true>(granule) : access_in<false>(granule);
    }
    // access() for a cache whose set count is (kPowerOfTwoSets) or is not a power of two:
    // replay loops are specialised on it (a mask instead of a division).
    template <bool kPowerOfTwoSets>
    bool access_in(uint64_t granule) const {
      const uint64_t line = line_of(granule);
      return access_line(line, set_in<kPowerOfTwoSets>(line));
    }
    // access() for a line whose set the caller already computed (the replay filters by set).
    // Replacement is LRU: each set keeps its lines ordered from most to least recently used.
    // Texture streams mostly touch the line they touched last in that set (about 96 % of the
    // accesses of the benchmark scenes), which is one compare and no reordering.
    bool access_line(uint64_t line, uint32_t set) const {
      uint64_t* ways = tags_ + static_cast<size_t>(set) * ways_;
      return ways[0] == line || access_older(ways, ways_, line);
    }
    uint64_t line_of(uint64_t granule) const { return granule >> line_shift_; }
    // The set a line maps to: accesses to different sets never interact, so the replay hands
    // disjoint groups of sets to different threads.
    uint32_t set_of_line(uint64_t line) const {
      return sets_are_power_of_two_ ? set_in<true>(line) : set_in<false>(line);
    }
    template <bool kPowerOfTwoSets>
    uint32_t set_in(uint64_t line) const {
      return static_cast<uint32_t>(kPowerOfTwoSets ? line & (sets_ - 1) : line % sets_);
    }
    bool sets_are_power_of_two() const { return sets_are_power_of_two_; }

   private:
    friend class TextureCache;
    // A miss, or a hit below the most recent way: moves the line to the front of its set in
    // one pass. On a hit at position p ways 0..p-1 move to 1..p; on a miss every way moves and
    // the last (the least recent, or an empty way: lines only ever enter at the front, so empty
    // ways stay at the back) drops out. Inline, so replay loops make no call per access.
    static bool access_older(uint64_t* ways, uint32_t way_count, uint64_t line) {
      uint64_t carried = ways[0];
      ways[0] = line;
      for (uint32_t position = 1; position < way_count; ++position) {
        const uint64_t held = ways[position];
        ways[position] = carried;
        if (held == line) return true;
        carried = held;
      }
      return false;
    }

    uint64_t* tags_ = nullptr;  // sets x ways, each set most recently used first, ~0 = empty
    uint32_t ways_ = 0, sets_ = 0;
    int line_shift_ = 0;        // log2(line_bytes / 64)
    bool sets_are_power_of_two_ = false;
  };

  Lookup lookup() { return lookup_; }
  bool access(uint64_t granule) { return lookup_.access(granule); }
  uint32_t set_of(uint64_t frame_granule) const {
    return lookup_.set_of_line(lookup_.line_of(frame_granule));
  }
  uint32_t set_count() const { return lookup_.sets_; }
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
  std::vector<uint64_t> tags_;  // the ways of every set (see Lookup)
  Lookup lookup_;
  std::map<uint64_t, uint64_t> frame_base_granule_;  // texture id -> first granule this frame
  uint64_t next_frame_granule_ = 0;
};

// Feeds every tile's texture granules through the cache, tiles in index order
// (texture_replay.cpp).
TextureTraffic replay_texture_traces(TextureCache& cache, const std::vector<TileTrace>& traces);

}  // namespace ontile
