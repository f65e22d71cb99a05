// The inner loop of the texture-cache replay (texture_replay.cpp): one stream of traced granules
// through a SetArray, most-recent-way hits tested on SIMD lanes (texture_replay_simd.cpp, Highway
// with runtime dispatch), everything else one access at a time in stream order, so the counts
// are those of a plain per-access loop on every target.
#pragma once
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "memory/texture_cache.h"
#include "memory/trace_repeats.h"

namespace ontile {

// Texture region id (traced granule >> kRegionShiftGranules) -> frame offset (what
// TextureCache::place returns), direct-mapped by the id's low bits. A region missing from its
// slot is asked of `resolve` (in stream order, so a serial replay places regions in first-use
// order) and replaces the slot's previous region.
//
// The SIMD hit test adds offsets[id % kSlots] without comparing ids: for a granule whose region
// is not the slot's the sum can never be a cached line. Proof: every real frame granule is below
// 2^39 (region 0 below 2^34, placed regions below TextureCache::kFrameGranuleLimit = 2^38 plus
// their 34-bit offset). A slot holding region X gives a granule of region Y != X (Y = X mod 64,
// ids < 2^30) the frame base_X + low + (Y - X) 2^34: congruent to a value below 2^39 mod 2^40 but
// not equal to it, so some bit >= 40 is set. An empty slot s holds kEmptySlotFrameBase -
// s 2^34 (kEmptySlotFrameBase = 2^39), giving region Y = s mod 64 a frame with bit 39 set. Both
// differ from every real frame granule in a bit >= 39, above any line shift (line bytes < 2^25
// B), so the lines differ; neither can be the empty tag ~0 (its low 40 bits would be all ones).
struct RegionTable {
  static constexpr size_t kSlots = 64;
  static constexpr uint64_t kEmptySlotFrameBase = uint64_t{1} << 39;
  alignas(64) uint64_t ids[kSlots];
  alignas(64) uint64_t offsets[kSlots];
  // Misses of each slot's region since it entered the slot; a region leaving its slot adds
  // them to `spilled_misses` (id, misses), so every miss is attributed to its texture.
  uint64_t misses[kSlots];
  std::vector<std::pair<uint64_t, uint64_t>> spilled_misses;
  uint64_t (*resolve)(void* context, uint64_t id) = nullptr;
  void* context = nullptr;

  RegionTable(uint64_t (*resolve_offset)(void*, uint64_t), void* resolve_context)
      : resolve(resolve_offset), context(resolve_context) {
    for (size_t slot = 0; slot < kSlots; ++slot) {
      ids[slot] = ~uint64_t{0};  // no region: ids are below 2^30
      offsets[slot] = kEmptySlotFrameBase - (uint64_t{slot} << TextureCache::kRegionShiftGranules);
      misses[slot] = 0;
    }
  }
  uint64_t offset(uint64_t id) {
    const size_t slot = id & (kSlots - 1);
    if (ids[slot] != id) {
      if (misses[slot] != 0) spilled_misses.emplace_back(ids[slot], misses[slot]);
      misses[slot] = 0;
      offsets[slot] = resolve(context, id);
      ids[slot] = id;
    }
    return offsets[slot];
  }
  // Called after offset(id): one more miss of region id.
  void count_miss(uint64_t id) { ++misses[id & (kSlots - 1)]; }
  // Adds every region's misses so far to `by_region` (id -> misses).
  void add_misses_to(std::map<uint64_t, uint64_t>& by_region) const {
    for (const auto& [id, count] : spilled_misses) by_region[id] += count;
    for (size_t slot = 0; slot < kSlots; ++slot) {
      if (misses[slot] != 0) by_region[ids[slot]] += misses[slot];
    }
  }
};

// What a replay of a trace counted: its accesses (repeat entries expanded) and misses.
struct ReplayedGranules {
  uint64_t accesses = 0;
  uint64_t misses = 0;
};

// Every entry of the trace [granules, granules + count) in order (a repeat entry, trace_repeats.h,
// standing for its window's accesses again): frame granule = granule + its region's offset, then
// sets.access. The misses are also counted per region in `regions`. A repeat entry's window must
// lie in [granules, granules + count); here any window size >= 1 is accepted (the parallel
// replay's set groups keep a window's granules of their group, which may be one).
ReplayedGranules replay_granules(const SetArray& sets, RegionTable& regions,
                                 const uint64_t* granules, size_t count);

}  // namespace ontile
