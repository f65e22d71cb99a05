// The replay of a pass's texture traces through the texture-cache model (texture_cache.h), with
// the counts of a serial per-access replay in tile-index order at any thread count.
//
// Serial (TextureReplayStream, texture_replay_stream.h): one pass over the tiles while they are
// recorded, regions placed as they are met (first-use order).
// Parallel: a set's hits and misses depend only on the order of its own accesses, so the sets are
// split into G = 2^b groups, replayed by different threads, each seeing its accesses in tile
// order. The group of a granule is the low b bits of its line, which are also bits of its set
// (set counts that are powers of two >= G), and are the same in the traced and the frame address
// (regions are placed on 4 KiB = 64-granule boundaries, so for lines of 64 << s bytes b <= 6 - s
// bits are placement-independent). So, all in parallel over tiles, each tile's granules are
// split by group into its worker's buffers while the regions it uses are listed; the regions are
// then placed in tile order (serially, a few per tile), and each group replays its buffers in
// tile order on a private copy of its sets. Other set counts and line sizes, and fewer than
// kMinimumParallelThreads threads, replay serially.
#include <algorithm>
#include <atomic>
#include <bit>
#include <map>
#include <span>
#include <vector>

#include <tbb/task_arena.h>

#include "memory/granule_buffer_pool.h"
#include "memory/replay_scratch.h"
#include "memory/texture_cache.h"
#include "memory/texture_replay_kernel.h"
#include "memory/texture_replay_observer.h"
#include "memory/texture_replay_stream.h"
#include "memory/trace_repeats.h"
#include "util/parallel_for.h"

namespace ontile {
namespace {

std::atomic<TextureReplayObserver*> observer{nullptr};

constexpr int kRegionShift = TextureCache::kRegionShiftGranules;
// Granules per placement boundary: texture regions start on 4 KiB boundaries.
constexpr int kPlacementAlignmentBits = 6;

uint64_t place_region(void* cache, uint64_t id) {
  return static_cast<TextureCache*>(cache)->place(id);
}
uint64_t placed_region(void* cache, uint64_t id) {
  return static_cast<const TextureCache*>(cache)->placed_offset(id);
}

TextureTraffic traffic_of(uint64_t accesses, uint64_t misses, const TextureCache& cache) {
  TextureTraffic traffic;
  traffic.accesses = accesses;
  traffic.hits = accesses - misses;
  traffic.misses = misses;
  traffic.bytes_read = misses * cache.config().line_bytes;
  return traffic;
}

// Splitting the granules by group costs several times what replaying them costs (callgrind,
// demo cartoon 1920x1080, 26 M accesses: split_tile 570 M instructions, the serial replay 178 M,
// the groups' replays 217 M), so the parallel replay's (570 + 217) / T only beats the serial
// 178 from T = 4.4 threads with perfect scaling; below this many threads the replay is serial.
constexpr int kMinimumParallelThreads = 6;

// log2 of the number of set groups for `threads` threads: enough groups for every thread, no
// more than the placement-independent bits and the sets allow; 0 = replay serially.
int group_bits_for(const SetArray& sets, int threads) {
  if (threads < kMinimumParallelThreads || !sets.sets_are_power_of_two) return 0;
  const int wanted = std::bit_width(static_cast<unsigned>(threads - 1));  // ceil(log2(threads))
  const int placement_independent = std::max(0, kPlacementAlignmentBits - sets.line_shift);
  return std::min({wanted, placement_independent, std::countr_zero(sets.sets)});
}

// One tile: its granules appended to its worker's group buffers (group = low bits of the line),
// its regions (id != 0) appended to the worker's list in first-use order.
void split_tile(std::span<const uint64_t> granules, int line_shift, int group_bits,
                ReplayScratch::Worker& worker, size_t* ranges) {
  const size_t groups = size_t{1} << group_bits;
  uint64_t* write[size_t{1} << kPlacementAlignmentBits];
  for (size_t k = 0; k < groups; ++k) {
    write[k] = worker.groups[k].reserve_tail(granules.size());
    ranges[2 * k] = worker.groups[k].size();
  }
  const uint64_t group_mask = groups - 1;
  const size_t ids_begin = worker.region_ids.size();
  // Shaders sampling two textures alternate between them every few granules: the region before
  // the last one is checked before the tile's list.
  uint64_t last_id = ~uint64_t{0}, previous_id = ~uint64_t{0};
  for (size_t i = 0; i < granules.size(); ++i) {
    const uint64_t granule = granules[i];
    if (is_trace_repeat(granule)) {
      // A repeat of the window before it: each group repeats the window's granules of its own
      // (a group's accesses in order are then exactly what the expanded trace gives it).
      const uint32_t window = trace_repeat_window(granule);
      uint32_t in_group[size_t{1} << kPlacementAlignmentBits] = {};
      for (size_t k = i - window; k < i; ++k) ++in_group[(granules[k] >> line_shift) & group_mask];
      for (size_t k = 0; k < groups; ++k) {
        if (in_group[k] != 0) *write[k]++ = trace_repeat(in_group[k], trace_repeat_count(granule));
      }
      continue;
    }
    const uint64_t id = granule >> kRegionShift;
    if (id != last_id) {
      const uint64_t left = last_id;
      last_id = id;
      if (id != previous_id) {
        const auto first = worker.region_ids.begin() + static_cast<std::ptrdiff_t>(ids_begin);
        if (id != 0 && std::find(first, worker.region_ids.end(), id) == worker.region_ids.end()) {
          worker.region_ids.push_back(id);
        }
      }
      previous_id = left;
    }
    *write[(granule >> line_shift) & group_mask]++ = granule;
  }
  for (size_t k = 0; k < groups; ++k) {
    const size_t end = static_cast<size_t>(write[k] - worker.groups[k].data());
    ranges[2 * k + 1] = end;
    worker.groups[k].resize_within_capacity(end);
  }
}

// Group k's sets (set & (G - 1) == k), as set index j = set >> b in a SetArray of their own, so
// no two threads write one cache line of ways.
SetArray group_sets(const SetArray& all, int group_bits, std::vector<uint64_t>& storage) {
  SetArray group = all;
  group.sets = all.sets >> group_bits;
  group.index_shift = group_bits;
  storage.resize(static_cast<size_t>(group.sets) * all.ways);
  group.tags = storage.data();
  return group;
}

// Copies group k's ways between the cache's SetArray and the group's own (to_group: into it).
void copy_group_ways(const SetArray& all, const SetArray& group, uint32_t k, int group_bits,
                     bool to_group) {
  for (uint32_t j = 0; j < group.sets; ++j) {
    const uint32_t set = j << group_bits | k;
    for (uint32_t way = 0; way < all.ways; ++way) {
      uint64_t& in_cache = all.tags[all.slot_of(set, way)];
      uint64_t& in_group = group.tags[group.slot_of(j, way)];
      if (to_group) {
        in_group = in_cache;
      } else {
        in_cache = in_group;
      }
    }
  }
}

TextureTraffic replay_parallel(TextureCache& cache, const std::vector<TileTrace>& traces,
                               int threads, int group_bits, TextureReplayDetail& detail) {
  const SetArray& sets = cache.sets();
  const size_t groups = size_t{1} << group_bits;
  const size_t tile_count = traces.size();
  const ReplayScratchLease scratch;
  scratch->prepare(tile_count, static_cast<size_t>(threads), groups);
  // 1. Split every tile's granules by group, listing the regions each tile uses.
  ontile::parallel_for(size_t{0}, tile_count, [&](size_t t) {
    const auto worker = static_cast<uint32_t>(tbb::this_task_arena::current_thread_index());
    ReplayScratch::Worker& w = scratch->workers[worker];
    const SlotObjectUse slot_use(&w);
    ReplayScratch::Tile& tile = scratch->tiles[t];
    tile.worker = worker;
    tile.region_ids_begin = static_cast<uint32_t>(w.region_ids.size());
    split_tile(traces[t].texture_granules, sets.line_shift, group_bits, w,
               &scratch->group_ranges[2 * t * groups]);
    tile.region_ids_end = static_cast<uint32_t>(w.region_ids.size());
  });
  // 2. Regions placed in first-use order: tiles in index order, each tile's in its order.
  uint64_t accesses = 0;
  for (size_t t = 0; t < tile_count; ++t) {
    const ReplayScratch::Tile& tile = scratch->tiles[t];
    const std::vector<uint64_t>& ids = scratch->workers[tile.worker].region_ids;
    for (uint32_t i = tile.region_ids_begin; i < tile.region_ids_end; ++i) cache.place(ids[i]);
    accesses += traced_accesses(traces[t].texture_granules);
  }
  // 3. Each group's accesses in tile order, on its own copy of its sets.
  std::vector<uint64_t> group_misses(groups, 0);
  std::vector<std::vector<uint64_t>> group_tile_misses(groups, std::vector<uint64_t>(tile_count, 0));
  std::vector<std::map<uint64_t, uint64_t>> group_region_misses(groups);
  ontile::parallel_for(size_t{0}, groups, [&](size_t k) {
    const SetArray group = group_sets(sets, group_bits, scratch->group_tags[k]);
    copy_group_ways(sets, group, static_cast<uint32_t>(k), group_bits, true);
    RegionTable regions(placed_region, &cache);
    uint64_t misses = 0;
    for (size_t t = 0; t < tile_count; ++t) {
      const size_t* range = &scratch->group_ranges[2 * (t * groups + k)];
      const uint64_t* granules = scratch->workers[scratch->tiles[t].worker].groups[k].data();
      const uint64_t tile_misses =
          replay_granules(group, regions, granules + range[0], range[1] - range[0]).misses;
      group_tile_misses[k][t] = tile_misses;
      misses += tile_misses;
    }
    copy_group_ways(sets, group, static_cast<uint32_t>(k), group_bits, false);
    regions.add_misses_to(group_region_misses[k]);
    group_misses[k] = misses;
  });
  uint64_t misses = 0;
  for (size_t k = 0; k < groups; ++k) {
    misses += group_misses[k];
    for (size_t t = 0; t < tile_count; ++t) detail.misses_per_tile[t] += group_tile_misses[k][t];
    for (const auto& [id, count] : group_region_misses[k]) detail.misses_per_region[id] += count;
  }
  return traffic_of(accesses, misses, cache);
}

}  // namespace

void set_texture_replay_observer(TextureReplayObserver* replay_observer) {
  observer.store(replay_observer);
}

TextureReplayStream::TextureReplayStream(TextureCache& cache, const std::vector<TileTrace>& traces,
                                         TextureReplayDetail& detail)
    : TextureReplayStream(cache, traces, nullptr, detail) {}

TextureReplayStream::TextureReplayStream(TextureCache& cache, std::vector<TileTrace>& traces,
                                         TextureReplayDetail& detail, GiveBackBuffers)
    : TextureReplayStream(cache, traces, &traces, detail) {}

TextureReplayStream::TextureReplayStream(TextureCache& cache, const std::vector<TileTrace>& traces,
                                         std::vector<TileTrace>* buffers_to_give_back,
                                         TextureReplayDetail& detail)
    : cache_(cache),
      traces_(traces),
      buffers_to_give_back_(buffers_to_give_back),
      detail_(detail),
      observer_(observer.load()),
      threads_(std::max(1, tbb::this_task_arena::max_concurrency())),
      group_bits_(group_bits_for(cache.sets(), threads_)),
      give_back_when_replayed_(buffers_to_give_back != nullptr && group_bits_ == 0 && observer_ == nullptr),
      recorded_(new std::atomic<bool>[traces.size()]),
      regions_(place_region, &cache) {
  for (size_t t = 0; t < traces.size(); ++t) recorded_[t].store(false, std::memory_order_relaxed);
  detail_.misses_per_tile.assign(traces.size(), 0);
  detail_.misses_per_region.clear();
  if (observer_ != nullptr) observer_->before_replay(cache_);
}

TextureReplayStream::~TextureReplayStream() = default;

void TextureReplayStream::replay_tile(size_t tile) {
  const std::vector<uint64_t>& granules = traces_[tile].texture_granules;
  const ReplayedGranules replayed = replay_granules(cache_.sets(), regions_, granules.data(), granules.size());
  accesses_ += replayed.accesses;
  detail_.misses_per_tile[tile] = replayed.misses;
  misses_ += replayed.misses;
  if (give_back_when_replayed_) give_back_granule_buffer((*buffers_to_give_back_)[tile].texture_granules);
}

bool TextureReplayStream::next_is_recorded() const {
  const size_t next = next_tile_.load();
  return next < traces_.size() && recorded_[next].load();
}

// The flag, the recorded marks and next_tile_ use sequentially consistent operations, so no
// recorded tile is left behind: either the holder's last check after letting the flag go sees
// the mark, or the recording thread's exchange comes after that release and takes the flag.
void TextureReplayStream::tile_recorded(size_t tile) {
  recorded_[tile].store(true);
  if (group_bits_ != 0) return;
  while (next_is_recorded() && !replaying_.exchange(true)) {
    size_t next = next_tile_.load();
    while (next < traces_.size() && recorded_[next].load()) replay_tile(next++);
    next_tile_.store(next);
    replaying_.store(false);
  }
}

TextureTraffic TextureReplayStream::finish() {
  TextureTraffic traffic;
  if (group_bits_ == 0) {
    for (size_t t = next_tile_.load(); t < traces_.size(); ++t) replay_tile(t);
    next_tile_.store(traces_.size());
    regions_.add_misses_to(detail_.misses_per_region);
    traffic = traffic_of(accesses_, misses_, cache_);
  } else {
    traffic = replay_parallel(cache_, traces_, threads_, group_bits_, detail_);
  }
  if (observer_ != nullptr) observer_->after_replay(cache_, traces_, traffic);
  if (buffers_to_give_back_ != nullptr) {
    for (TileTrace& trace : *buffers_to_give_back_) give_back_granule_buffer(trace.texture_granules);
  }
  return traffic;
}

TextureTraffic replay_texture_traces(TextureCache& cache, const std::vector<TileTrace>& traces,
                                     TextureReplayDetail* detail) {
  TextureReplayDetail local_detail;
  TextureReplayStream stream(cache, traces, detail ? *detail : local_detail);
  return stream.finish();
}

}  // namespace ontile
