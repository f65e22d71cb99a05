// The texture-cache model written from its definition (texture_cache.h), with no attention to
// speed, for tests to compare the model's replay with: each set a list of lines, most recent
// first; regions placed in the frame in first-use order.
#pragma once
#include <cstdint>
#include <list>
#include <map>
#include <vector>

#include "raster/texture.h"
#include "memory/texture_cache.h"
#include "memory/trace_repeats.h"

namespace ontile {

// The definition, with no attention to speed: each set a list of lines, most recent first.
class ReferenceLru {
 public:
  explicit ReferenceLru(const TextureCacheConfig& c)
      : granules_per_line_(c.line_bytes / 64), ways_(c.ways),
        sets_(c.size_bytes / (c.line_bytes * c.ways)) {}
  bool access(uint64_t frame_granule) {
    const uint64_t line = frame_granule / granules_per_line_;
    std::list<uint64_t>& set = sets_[line % sets_.size()];
    for (auto it = set.begin(); it != set.end(); ++it) {
      if (*it == line) {
        set.erase(it);
        set.push_front(line);
        return true;
      }
    }
    set.push_front(line);
    if (set.size() > ways_) set.pop_back();
    return false;
  }
  // Frame granule of a traced one: regions (id = granule >> 34) placed one after another, from
  // granule 2^34, in the order of their first access, each its reserved size rounded to 64 B.
  uint64_t frame_granule(uint64_t traced) {
    const uint64_t id = traced >> 34;
    if (id == 0) return traced;
    auto it = base_.find(id);
    if (it == base_.end()) {
      it = base_.emplace(id, next_).first;
      next_ += (Texture2D::reserved_bytes_of(id) + 63) / 64;
    }
    return it->second + (traced & ((uint64_t{1} << 34) - 1));
  }
  // Tiles in index order, each a range of traced granules (repeat entries expanded,
  // trace_repeats.h); fills `detail` (misses per tile and per region id) when given.
  template <class Tiles>
  TextureTraffic replay(const Tiles& tiles, uint32_t line_bytes,
                        TextureReplayDetail* detail = nullptr) {
    TextureTraffic t;
    if (detail) *detail = TextureReplayDetail{};
    for (const auto& tile : tiles) {
      uint64_t tile_misses = 0;
      for (const uint64_t g : expand_trace_repeats(std::span<const uint64_t>(tile.data(), tile.size()))) {
        ++t.accesses;
        if (access(frame_granule(g))) {
          ++t.hits;
        } else {
          ++t.misses;
          ++tile_misses;
          if (detail) ++detail->misses_per_region[g >> 34];
        }
      }
      if (detail) detail->misses_per_tile.push_back(tile_misses);
    }
    t.bytes_read = t.misses * line_bytes;
    return t;
  }

 private:
  uint64_t granules_per_line_;
  size_t ways_;
  std::vector<std::list<uint64_t>> sets_;
  std::map<uint64_t, uint64_t> base_;
  uint64_t next_ = uint64_t{1} << 34;
};

}  // namespace ontile
