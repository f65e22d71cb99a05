// The replay of a pass's texture traces through the texture-cache model (texture_cache.h), in
// parallel yet with the counts of the serial replay: textures are placed in the frame in
// first-use order (tiles in index order), then each thread replays the whole sequence for a
// disjoint group of cache sets. A set's hits and misses depend only on the order of its own
// accesses, which every thread sees in tile-index order, so the sums never depend on threads.
#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include <tbb/task_arena.h>

#include "tiler/texture_cache.h"
#include "util/parallel_for.h"

namespace ontile {
namespace {

constexpr int kRegionShift = TextureCache::kRegionShiftGranules;

// Region id -> frame offset (TextureCache::place), kept in a small direct-mapped table: shaders
// that sample several textures per quad switch region every 4-15 granules (deferred, cartoon and
// forward frames of the benchmark scenes), and find the few regions of a frame here rather than
// in the cache's map. Entries start as {0, 0}, which is region 0's offset.
template <class Place>
class OffsetMemo {
 public:
  explicit OffsetMemo(Place place) : place_(place) {}
  uint64_t offset(uint64_t id) {
    Entry& entry = entries_[id % kEntries];
    if (entry.id != id) entry = Entry{id, place_(id)};
    return entry.offset;
  }

 private:
  static constexpr size_t kEntries = 64;
  struct Entry {
    uint64_t id = 0, offset = 0;
  };
  std::array<Entry, kEntries> entries_{};
  Place place_;
};

// Calls visit(frame granule) for every traced granule, tiles in index order, and returns how
// many calls returned true. The offset is looked up once per run of granules of one region; the
// inner loop over a run calls nothing out of line, so its state stays in registers.
template <class Place, class Visit>
uint64_t count_frame_granules(const std::vector<TileTrace>& traces, Place place, Visit visit) {
  OffsetMemo<Place> memo(place);
  uint64_t count = 0;
  for (const TileTrace& trace : traces) {
    const std::span<const uint64_t> granules = trace.texture_granules.granules();
    const uint64_t* next = granules.data();
    const uint64_t* const end = next + granules.size();
    while (next != end) {
      const uint64_t id = *next >> kRegionShift;
      const uint64_t offset = memo.offset(id);
      uint64_t run_count = 0;
      for (; next != end && (*next >> kRegionShift) == id; ++next) {
        run_count += visit(*next + offset);
      }
      count += run_count;
    }
  }
  return count;
}

// Texture region ids of one tile's trace in first-use order (a tile reads few textures).
std::vector<uint64_t> ids_in_first_use_order(std::span<const uint64_t> granules) {
  std::vector<uint64_t> ids;
  uint64_t last = 0;
  for (const uint64_t g : granules) {
    const uint64_t id = g >> kRegionShift;
    if (id == 0 || id == last) continue;
    last = id;
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  }
  return ids;
}

TextureTraffic traffic_of(uint64_t accesses, uint64_t hits, const TextureCache& cache) {
  TextureTraffic traffic;
  traffic.accesses = accesses;
  traffic.hits = hits;
  traffic.misses = accesses - hits;
  traffic.bytes_read = traffic.misses * cache.config().line_bytes;
  return traffic;
}

// One thread: places regions as it meets them, a single pass.
template <bool kPowerOfTwoSets>
TextureTraffic replay_serial(TextureCache& cache, const std::vector<TileTrace>& traces) {
  uint64_t accesses = 0;
  for (const TileTrace& trace : traces) accesses += trace.texture_granules.granules().size();
  const TextureCache::Lookup lookup = cache.lookup();
  // Counts misses, the rare outcome, so a hit in the most recent way costs no addition.
  const uint64_t misses = count_frame_granules(
      traces, [&](uint64_t id) { return cache.place(id); },
      [lookup](uint64_t frame_granule) {
        return !lookup.access_in<kPowerOfTwoSets>(frame_granule);
      });
  return traffic_of(accesses, accesses - misses, cache);
}

// The accesses to the sets of one group (group_of_set[set] == group), regions already placed.
template <bool kPowerOfTwoSets>
TextureTraffic replay_group(const TextureCache& cache, TextureCache::Lookup lookup,
                            const std::vector<TileTrace>& traces,
                            const std::vector<uint32_t>& group_of_set, uint32_t group) {
  const uint32_t* group_of = group_of_set.data();
  uint64_t accesses = 0;
  const uint64_t hits = count_frame_granules(
      traces, [&](uint64_t id) { return cache.placed_offset(id); },
      [&accesses, lookup, group_of, group](uint64_t frame_granule) {
        const uint64_t line = lookup.line_of(frame_granule);
        const uint32_t set = lookup.set_in<kPowerOfTwoSets>(line);
        if (group_of[set] != group) return false;
        ++accesses;
        return lookup.access_line(line, set);
      });
  return traffic_of(accesses, hits, cache);
}

}  // namespace

TextureTraffic replay_texture_traces(TextureCache& cache, const std::vector<TileTrace>& traces) {
  const uint32_t groups = std::min<uint32_t>(
      std::max(1, tbb::this_task_arena::max_concurrency()), cache.set_count());
  const bool power_of_two_sets = cache.lookup().sets_are_power_of_two();
  if (groups == 1) {
    return power_of_two_sets ? replay_serial<true>(cache, traces)
                             : replay_serial<false>(cache, traces);
  }
  const int tiles = static_cast<int>(traces.size());
  // 1. Placement: distinct ids per tile in parallel, then placed in tile order.
  std::vector<std::vector<uint64_t>> tile_ids(tiles);
  ontile::parallel_for(0, tiles, [&](int t) {
    tile_ids[t] = ids_in_first_use_order(traces[t].texture_granules.granules());
  });
  for (const auto& ids : tile_ids) {
    for (const uint64_t id : ids) cache.place(id);
  }
  // 2. LRU replay, sets partitioned among threads; each reads the placement, none changes it.
  std::vector<uint32_t> group_of_set(cache.set_count());
  for (uint32_t set = 0; set < cache.set_count(); ++set) group_of_set[set] = set % groups;
  std::vector<TextureTraffic> partial(groups);
  const TextureCache::Lookup lookup = cache.lookup();
  ontile::parallel_for(uint32_t{0}, groups, [&](uint32_t group) {
    partial[group] = power_of_two_sets
                         ? replay_group<true>(cache, lookup, traces, group_of_set, group)
                         : replay_group<false>(cache, lookup, traces, group_of_set, group);
  });
  TextureTraffic traffic;
  for (const TextureTraffic& p : partial) traffic.add(p);
  return traffic;
}

}  // namespace ontile
