// The replay of a pass's texture traces through the texture-cache model (texture_cache.h), in
// parallel yet with the counts of the serial replay: textures are placed in the frame in
// first-use order (tiles in index order), then each thread replays the whole sequence for a
// disjoint group of cache sets. A set's hits and misses depend only on the order of its own
// accesses, which every thread sees in tile-index order, so the sums never depend on threads.
#include <algorithm>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "tiler/texture_cache.h"

namespace ontile {
namespace {

constexpr uint64_t kOffsetMask = (uint64_t{1} << TextureCache::kRegionShiftGranules) - 1;

// Texture region ids of one tile's trace in first-use order (a tile reads few textures).
std::vector<uint64_t> ids_in_first_use_order(const std::vector<uint64_t>& granules) {
  std::vector<uint64_t> ids;
  uint64_t last = 0;
  for (const uint64_t g : granules) {
    const uint64_t id = g >> TextureCache::kRegionShiftGranules;
    if (id == 0 || id == last) continue;
    last = id;
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  }
  return ids;
}

}  // namespace

TextureTraffic replay_texture_traces(TextureCache& cache, const std::vector<TileTrace>& traces) {
  const uint32_t groups = std::min<uint32_t>(
      std::max(1, tbb::this_task_arena::max_concurrency()), cache.set_count());
  TextureTraffic traffic;
  if (groups == 1) {  // one thread: a single pass, no copy of the frame's accesses
    for (const TileTrace& trace : traces) {
      for (const uint64_t granule : trace.texture_granules) {
        ++traffic.accesses;
        if (cache.access(cache.frame_granule(granule))) {
          ++traffic.hits;
        } else {
          ++traffic.misses;
        }
      }
    }
    traffic.bytes_read = traffic.misses * cache.config().line_bytes;
    return traffic;
  }
  const int tiles = static_cast<int>(traces.size());
  // 1. Placement: distinct ids per tile in parallel, then assigned in tile order.
  std::vector<std::vector<uint64_t>> tile_ids(tiles);
  tbb::parallel_for(0, tiles, [&](int t) { tile_ids[t] = ids_in_first_use_order(traces[t].texture_granules); });
  std::vector<std::pair<uint64_t, uint64_t>> bases;  // (id, frame base granule), sorted by id
  for (const auto& ids : tile_ids) {
    for (const uint64_t id : ids) bases.emplace_back(id, cache.frame_base_granule(id));
  }
  std::sort(bases.begin(), bases.end());
  bases.erase(std::unique(bases.begin(), bases.end()), bases.end());
  // 2. Frame granules of every access, tiles concatenated in index order.
  std::vector<size_t> offsets(tiles + 1, 0);
  for (int t = 0; t < tiles; ++t) offsets[t + 1] = offsets[t] + traces[t].texture_granules.size();
  std::vector<uint64_t> frame(offsets[tiles]);
  tbb::parallel_for(0, tiles, [&](int t) {
    uint64_t last_id = 0, last_base = 0;
    uint64_t* out = frame.data() + offsets[t];
    for (const uint64_t g : traces[t].texture_granules) {
      const uint64_t id = g >> TextureCache::kRegionShiftGranules;
      if (id == 0) {
        *out++ = g;
        continue;
      }
      if (id != last_id) {
        last_id = id;
        last_base = std::lower_bound(bases.begin(), bases.end(), std::make_pair(id, uint64_t{0}))->second;
      }
      *out++ = last_base + (g & kOffsetMask);
    }
  });
  // 3. LRU replay, sets partitioned among threads.
  std::vector<TextureTraffic> partial(groups);
  tbb::parallel_for(uint32_t{0}, groups, [&](uint32_t group) {
    TextureTraffic& traffic = partial[group];
    for (const uint64_t granule : frame) {
      if (cache.set_of(granule) % groups != group) continue;
      ++traffic.accesses;
      if (cache.access(granule)) {
        ++traffic.hits;
      } else {
        ++traffic.misses;
      }
    }
  });
  for (const TextureTraffic& p : partial) traffic.add(p);
  traffic.bytes_read = traffic.misses * cache.config().line_bytes;
  return traffic;
}

}  // namespace ontile
