// replay_granules (texture_replay_kernel.h), compiled per target by Highway's foreach_target.
// Vectors of granules whose lines are all the most recent way of their sets are runs of hits that
// change no state, so they are counted at once; at the first lane that is not, that one granule
// takes the per-access path (its older ways searched and shifted on SIMD lanes) and the vectors
// resume after it. Integer operations only: every target gives the counts of the per-access loop.
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
using D = hn::ScalableTag<uint64_t>;

// The position of `line` among the `count` ways of `row` (count if absent): whole vectors, the
// last one overlapping the one before so no lane reads past the row. Absent (a miss) is the
// common outcome, so all vectors are compared before any is searched.
HWY_INLINE size_t PositionInRow(const uint64_t* row, size_t count, uint64_t line) {
  const D d;
  const size_t lanes = hn::Lanes(d);
  if (count < lanes) {
    size_t position = 0;
    while (position < count && row[position] != line) ++position;
    return position;
  }
  const auto wanted = hn::Set(d, line);
  auto found = hn::Eq(hn::LoadU(d, row + count - lanes), wanted);
  for (size_t start = 0; start + lanes < count; start += lanes) {
    found = hn::Or(found, hn::Eq(hn::LoadU(d, row + start), wanted));
  }
  if (hn::AllFalse(d, found)) return count;
  size_t start = 0;
  for (; start + lanes < count; start += lanes) {
    const intptr_t lane = hn::FindFirstTrue(d, hn::Eq(hn::LoadU(d, row + start), wanted));
    if (lane >= 0) return start + static_cast<size_t>(lane);
  }
  start = count - lanes;
  return start + hn::FindKnownFirstTrue(d, hn::Eq(hn::LoadU(d, row + start), wanted));
}

// row[0..count) moves to row[1..count]. Every lane is loaded before anything overwrites it: the
// first vector is held in a register, the others are moved from the top down (a count known at
// compile time unrolls).
HWY_INLINE void ShiftUpOne(uint64_t* row, size_t count) {
  const D d;
  const size_t lanes = hn::Lanes(d);
  if (count < lanes) {
    for (size_t j = count; j > 0; --j) row[j] = row[j - 1];
    return;
  }
  const auto first = hn::LoadU(d, row);
  for (size_t k = 1; k * lanes < count; ++k) {
    const size_t start = count - k * lanes;
    hn::StoreU(hn::LoadU(d, row + start), d, row + start + 1);
  }
  hn::StoreU(first, d, row + 1);
}

// One granule the long way, in stream order: its region's offset (resolved if new), then the full
// LRU access (set_associative_cache.h: a hit at position p moves ways 0..p-1 back by one, a miss
// all of them, the last dropping out); a miss is counted against its region.
// kPlain: power-of-two sets, line_shift and index_shift 0; kOlderWays: ways - 1 when known at
// compile time (the default 16-way cache), else 0.
template <bool kPlain, size_t kOlderWays>
HWY_INLINE bool AccessOne(const SetArray& sets, RegionTable& regions, uint64_t granule) {
  const uint64_t id = granule >> kRegionShift;
  uint64_t line = granule + regions.offset(id);
  uint32_t set;
  if constexpr (kPlain) {
    set = static_cast<uint32_t>(line & (sets.sets - 1));
  } else {
    line >>= sets.line_shift;
    set = sets.index_of_line(line);
  }
  uint64_t* const recent = sets.tags + set;
  if (*recent == line) return true;
  const size_t older_ways = kOlderWays != 0 ? kOlderWays : sets.ways - 1;
  uint64_t* const row = sets.tags + sets.sets + static_cast<size_t>(set) * older_ways;  // older_of
  if (older_ways > 0 && row[0] == line) {  // way 1: the two swap (the stream alternates often)
    row[0] = *recent;
    *recent = line;
    return true;
  }
  const size_t position = PositionInRow(row, older_ways, line);
  const bool hit = position < older_ways;
  if (older_ways > 0) {
    if (hit) {
      ShiftUpOne(row, position);
    } else {
      ShiftUpOne(row, older_ways - 1);  // unrolled for kOlderWays
    }
    row[0] = *recent;
  }
  *recent = line;
  if (!hit) regions.count_miss(id);
  return hit;
}

// The granules from `granules` on, while they hit the most recent way of their power-of-two set;
// returns how many did. Offsets come from the region table without comparing ids: a granule of
// a region not in its slot can never hit (RegionTable), so it stops the run and AccessOne
// resolves it. kPlain: line_shift and index_shift 0 (the serial texture replay), line = frame.
template <bool kPlain>
class RecentHits {
 public:
  RecentHits(const SetArray& sets, const RegionTable& regions)
      : offsets_(regions.offsets),
        recent_(sets.tags),
        slot_mask_(hn::Set(d_, RegionTable::kSlots - 1)),
        index_mask_(hn::Set(d_, sets.sets - 1)),
        last_set_(sets.sets - 1),
        line_shift_(sets.line_shift),
        index_shift_(sets.line_shift + sets.index_shift) {}

  HWY_INLINE size_t Leading(const uint64_t* granules, size_t count) const {
    const size_t lanes = hn::Lanes(d_);
    size_t i = 0;
    // Two vectors per branch: runs of most-recent-way hits average about 20 granules.
    for (; i + 2 * lanes <= count; i += 2 * lanes) {
      const auto first = Hit(granules + i);
      const auto second = Hit(granules + i + lanes);
      if (HWY_UNLIKELY(!hn::AllTrue(d_, hn::And(first, second)))) {
        if (!hn::AllTrue(d_, first)) return i + hn::FindKnownFirstTrue(d_, hn::Not(first));
        return i + lanes + hn::FindKnownFirstTrue(d_, hn::Not(second));
      }
    }
    for (; i + lanes <= count; i += lanes) {
      const auto hit = Hit(granules + i);
      if (!hn::AllTrue(d_, hit)) return i + hn::FindKnownFirstTrue(d_, hn::Not(hit));
    }
    for (; i < count; ++i) {
      const uint64_t slot = (granules[i] >> kRegionShift) & (RegionTable::kSlots - 1);
      const uint64_t frame = granules[i] + offsets_[slot];
      if (recent_[(frame >> index_shift_) & last_set_] != frame >> line_shift_) return i;
    }
    return count;
  }

 private:
  // Lanes whose line is its set's most recent way. Set indices stay in range for every lane.
  HWY_INLINE auto Hit(const uint64_t* granules) const {
    const hn::RebindToSigned<D> di;
    const auto granule = hn::LoadU(d_, granules);
    const auto slot = hn::And(hn::ShiftRight<kRegionShift>(granule), slot_mask_);
    const auto frame = hn::Add(granule, hn::GatherIndex(d_, offsets_, hn::BitCast(di, slot)));
    if constexpr (kPlain) {
      const auto index = hn::And(frame, index_mask_);
      return hn::Eq(hn::GatherIndex(d_, recent_, hn::BitCast(di, index)), frame);
    } else {
      const auto line = hn::ShiftRightSame(frame, line_shift_);
      const auto index = hn::And(hn::ShiftRightSame(frame, index_shift_), index_mask_);
      return hn::Eq(hn::GatherIndex(d_, recent_, hn::BitCast(di, index)), line);
    }
  }

  D d_;
  const uint64_t* offsets_;
  const uint64_t* recent_;
  hn::Vec<D> slot_mask_, index_mask_;
  uint64_t last_set_;
  int line_shift_, index_shift_;
};

template <bool kPlain, size_t kOlderWays>
uint64_t ReplayPowerOfTwoSets(const SetArray& sets, RegionTable& regions,
                              const uint64_t* granules, size_t count) {
  const RecentHits<kPlain> recent_hits(sets, regions);
  uint64_t misses = 0;
  size_t i = 0;
  while (true) {
    i += recent_hits.Leading(granules + i, count - i);
    if (i == count) return misses;
    misses += !AccessOne<kPlain, kOlderWays>(sets, regions, granules[i]);
    ++i;
  }
}

uint64_t ReplayGranulesKernel(const SetArray& sets, RegionTable& regions,
                              const uint64_t* granules, size_t count) {
  if (!sets.sets_are_power_of_two) {
    uint64_t misses = 0;
    for (size_t i = 0; i < count; ++i) misses += !AccessOne<false, 0>(sets, regions, granules[i]);
    return misses;
  }
  if (sets.line_shift == 0 && sets.index_shift == 0) {
    if (sets.ways == 16) return ReplayPowerOfTwoSets<true, 15>(sets, regions, granules, count);
    return ReplayPowerOfTwoSets<true, 0>(sets, regions, granules, count);
  }
  if (sets.ways == 16) return ReplayPowerOfTwoSets<false, 15>(sets, regions, granules, count);
  return ReplayPowerOfTwoSets<false, 0>(sets, regions, granules, count);
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
