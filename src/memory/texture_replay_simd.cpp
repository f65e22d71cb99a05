// replay_granules (texture_replay_kernel.h), compiled per target by Highway's foreach_target.
// A vector of granules whose regions are in the table and whose lines are all the most recent
// way of their sets is a run of hits that changes no state, so it is counted at once; at the
// first lane that is not, that one granule takes the per-access path and the vectors resume after
// it. Integer operations only: every target gives the counts of the per-access loop.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "memory/texture_replay_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "memory/texture_replay_kernel.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

constexpr int kRegionShift = TextureCache::kRegionShiftGranules;

// One granule the long way: its region's offset (resolved if new), then the full LRU access; a
// miss is counted against its region.
HWY_INLINE bool access_one(const SetArray& sets, RegionTable& regions, uint64_t granule) {
  const uint64_t id = granule >> kRegionShift;
  const bool hit = sets.access(granule + regions.offset(id));
  if (!hit) regions.count_miss(id);
  return hit;
}

// The number of leading granules of [granules, granules + count) that hit the most recent way
// of their set with their region in the table (count if all do). Power-of-two set counts only.
// Inline: it runs again after every access that is not such a hit (about 1 in 40).
HWY_INLINE size_t LeadingRecentHits(const SetArray& sets, const RegionTable& regions,
                         const uint64_t* granules, size_t count) {
  const hn::ScalableTag<uint64_t> d;
  const hn::RebindToSigned<decltype(d)> di;
  const size_t lanes = hn::Lanes(d);
  const auto slot_mask = hn::Set(d, RegionTable::kSlots - 1);
  const auto index_mask = hn::Set(d, sets.sets - 1);
  const int line_shift = sets.line_shift, index_shift = sets.index_shift;
  const uint64_t* const recent_ways = sets.tags;
  size_t i = 0;
  for (; i + lanes <= count; i += lanes) {
    const auto granule = hn::LoadU(d, granules + i);
    const auto id = hn::ShiftRight<kRegionShift>(granule);
    const auto slot = hn::BitCast(di, hn::And(id, slot_mask));
    const auto known = hn::Eq(hn::GatherIndex(d, regions.ids, slot), id);
    const auto frame = hn::Add(granule, hn::GatherIndex(d, regions.offsets, slot));
    const auto line = hn::ShiftRightSame(frame, line_shift);
    // In range for every lane, also those whose offset was not their region's.
    const auto index = hn::And(hn::ShiftRightSame(line, index_shift), index_mask);
    const auto recent = hn::Eq(hn::GatherIndex(d, recent_ways, hn::BitCast(di, index)), line);
    const auto hit = hn::And(known, recent);
    if (!hn::AllTrue(d, hit)) return i + hn::FindKnownFirstTrue(d, hn::Not(hit));
  }
  for (; i < count; ++i) {
    const uint64_t granule = granules[i];
    const uint64_t id = granule >> kRegionShift;
    const size_t slot = id & (RegionTable::kSlots - 1);
    if (regions.ids[slot] != id) return i;
    const uint64_t line = (granule + regions.offsets[slot]) >> line_shift;
    if (recent_ways[sets.index_of_line(line)] != line) return i;
  }
  return count;
}

uint64_t ReplayGranulesKernel(const SetArray& sets, RegionTable& regions,
                              const uint64_t* granules, size_t count) {
  uint64_t misses = 0;
  if (!sets.sets_are_power_of_two) {
    for (size_t i = 0; i < count; ++i) misses += !access_one(sets, regions, granules[i]);
    return misses;
  }
  size_t i = 0;
  while (true) {
    i += LeadingRecentHits(sets, regions, granules + i, count - i);
    if (i == count) return misses;
    misses += !access_one(sets, regions, granules[i]);
    ++i;
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(ReplayGranulesKernel);

uint64_t replay_granules(const SetArray& sets, RegionTable& regions, const uint64_t* granules,
                         size_t count) {
  return HWY_DYNAMIC_DISPATCH(ReplayGranulesKernel)(sets, regions, granules, count);
}

}  // namespace ontile
#endif  // HWY_ONCE
