// replay_granules (texture_replay_kernel.h), compiled per target by Highway's foreach_target.
// Vectors of granules whose lines are all the most recent way of their sets are runs of hits that
// change no state, so they are counted at once; from the first lane that is not, the vector's
// lanes are taken one by one while they hit way 0 or way 1 (a swap); the first that hits neither
// takes the per-access path (its older ways searched and shifted on SIMD lanes) and the vectors
// resume after it; its region in its slot, that access is made in place (the lane's line and set
// are the vector's) and the lanes go on. Integer operations only: every target gives the counts
// of the per-access loop.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "memory/texture_replay_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "memory/texture_replay_kernel.h"
#include "raster/lane_bits-inl.h"

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

// The LRU access of `line` in a set whose two most recent ways (`recent`, then row[0]) do not
// hold it: a hit at position p of the older ways moves ways 0..p-1 back by one, a miss all of
// them, the last dropping out (set_associative_cache.h). Returns whether it hit.
template <size_t kOlderWays>
HWY_INLINE bool AccessPastTopTwo(uint64_t* recent, uint64_t* row, size_t older_ways,
                                 uint64_t line) {
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
  return hit;
}

// AccessPastTopTwo for the default 16-way cache without a branch on where the line is: every
// older way compared at once, then ways 0..p-1 move to 1..p in one select per vector (p: the
// hit's way, or the last way on a miss, whose line drops out). Where a hit lands is as random as
// the texture footprint, so the branches of the search-then-shift form mispredict often
// (bench/texture_replay_bench.cpp: about 30 ns per access that misses the two most recent ways).
// Whole vectors over the 15 older ways, the last one overlapping the one before: every new value
// is computed from the loaded row before anything is stored, so the overlap stores equal values.
HWY_INLINE bool AccessAllWays(uint64_t* recent, uint64_t* row, uint64_t line) {
  constexpr size_t kOlderWays = 15;
  const D d;
  const hn::RebindToSigned<D> di;
  constexpr size_t kMaxVectors = kOlderWays;  // 1-lane targets need one per way
  const size_t lanes = hn::Lanes(d);
  const size_t vectors = (kOlderWays + lanes - 1) / lanes;
  const auto wanted = hn::Set(d, line);
  hn::Vec<D> old[kMaxVectors];
  size_t start[kMaxVectors];
  uint64_t hits = 0;
  for (size_t k = 0; k < vectors; ++k) {
    start[k] = k + 1 < vectors ? k * lanes : kOlderWays - lanes;
    old[k] = hn::LoadU(d, row + start[k]);
    hits |= mask_bits(d, hn::Eq(old[k], wanted)) << start[k];
  }
  const bool hit = hits != 0;
  // Row positions 0..last take the way before theirs (position 0 takes way 0, *recent).
  const uint64_t last = hit ? static_cast<uint64_t>(__builtin_ctzll(hits)) : kOlderWays - 1;
  const auto moved_end = hn::Set(di, static_cast<int64_t>(last) + 1);
  for (size_t k = 0; k < vectors; ++k) {
    hn::Vec<D> before;
    if (start[k] == 0) {
      // Lanes 0, 0, 1, 2, ...: the row moved up one lane, then lane 0 takes way 0.
      alignas(64) static constexpr int64_t kLaneBefore[16] = {0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14};
      const auto up = hn::TableLookupLanes(old[0], hn::SetTableIndices(d, kLaneBefore));
      before = hn::IfThenElse(hn::FirstN(d, 1), hn::Set(d, *recent), up);
    } else {
      before = hn::LoadU(d, row + start[k] - 1);
    }
    const auto moved = hn::RebindMask(d, hn::Lt(hn::Iota(di, static_cast<int64_t>(start[k])), moved_end));
    old[k] = hn::IfThenElse(moved, before, old[k]);
  }
  for (size_t k = 0; k < vectors; ++k) hn::StoreU(old[k], d, row + start[k]);
  *recent = line;
  return hit;
}

// A traced granule in the cache: its region's table slot (the region resolved if new), its line
// and its set's two places (way 0 in `recent`, ways 1.. in `row`). kPlain: power-of-two sets,
// line_shift and index_shift 0. kOlderWays: ways - 1 when known at compile time, else 0.
struct PlacedGranule {
  size_t slot;
  uint64_t line;
  uint64_t* recent;
  uint64_t* row;
};
template <bool kPlain, size_t kOlderWays>
HWY_INLINE PlacedGranule PlaceAt(const SetArray& sets, uint64_t granule, uint64_t offset) {
  const uint64_t id = granule >> kRegionShift;
  uint64_t line = granule + offset;
  uint32_t set;
  if constexpr (kPlain) {
    set = static_cast<uint32_t>(line & (sets.sets - 1));
  } else {
    line >>= sets.line_shift;
    set = sets.index_of_line(line);
  }
  const size_t older_ways = kOlderWays != 0 ? kOlderWays : sets.ways - 1;
  return {id & (RegionTable::kSlots - 1), line, sets.tags + set,
          sets.tags + sets.sets + static_cast<size_t>(set) * older_ways};  // older_of
}
// Place with the region's offset resolved (if new) from the table.
template <bool kPlain, size_t kOlderWays>
HWY_INLINE PlacedGranule Place(const SetArray& sets, RegionTable& regions, uint64_t granule) {
  return PlaceAt<kPlain, kOlderWays>(sets, granule, regions.offset(granule >> kRegionShift));
}

// One granule the long way, in stream order: its region's offset (resolved if new), then the full
// LRU access; a miss is counted against its region.
// kPlain: power-of-two sets, line_shift and index_shift 0; kOlderWays: ways - 1 when known at
// compile time (the default 16-way cache), else 0. With `past_top_two` the caller knows that the
// granule, taken with its slot's offset, is in neither of its set's two most recent ways.
template <bool kPlain, size_t kOlderWays>
HWY_INLINE bool AccessOne(const SetArray& sets, RegionTable& regions, uint64_t granule,
                          bool past_top_two = false) {
  // A region already in its slot had the offset the caller tested the ways with.
  const uint64_t id = granule >> kRegionShift;
  past_top_two = past_top_two && regions.ids[id & (RegionTable::kSlots - 1)] == id;
  const auto [slot, line, recent, row] = Place<kPlain, kOlderWays>(sets, regions, granule);
  const size_t older_ways = kOlderWays != 0 ? kOlderWays : sets.ways - 1;
  if (!past_top_two) {
    if (*recent == line) return true;
    if (older_ways > 0 && row[0] == line) {  // way 1: the two swap (the stream alternates often)
      row[0] = *recent;
      *recent = line;
      return true;
    }
  }
  bool hit;
  if constexpr (kOlderWays == 15) {
    hit = AccessAllWays(recent, row, line);
  } else {
    hit = AccessPastTopTwo<kOlderWays>(recent, row, older_ways, line);
  }
  regions.misses[slot] += hit ? 0 : 1;  // count_miss without a branch
  return hit;
}

// The granules from `granules` on, replayed in order while their regions are in their slots;
// returns how many there were and adds their misses to `misses`. Runs of most-recent-way hits
// change no state and are skipped a vector at a time. Streams that alternate two lines of one set
// (a texture whose rows lie a multiple of the cache's span apart: 37 % of the universal forward
// pass's accesses hit way 1) would otherwise leave the vector loop every few granules: a vector
// with a lane that misses way 0 is finished here, its lanes in order, each a way-0 hit (nothing
// changes), a way-1 hit (the set's two lines swap) or, its region being the slot's, AccessOne's
// full access with the lane's line and set (a full-screen copy's trace misses twice in every
// 8 or 16 granules; leaving the loop for each miss cost about 30 instructions more). Offsets
// come from the region table without comparing ids: a granule of a region not in its slot can
// never hit (RegionTable), so it stops the run and AccessOne resolves it. kPlain: line_shift and
// index_shift 0 (the serial texture replay), line = frame. kOlderWays: ways - 1 when known at
// compile time, else 0.
template <bool kPlain, size_t kOlderWays>
class RecentHits {
 public:
  RecentHits(const SetArray& sets, RegionTable& regions)
      : regions_(regions),
        offsets_(regions.offsets),
        recent_(sets.tags),
        way1_(sets.tags + sets.sets),
        older_ways_(kOlderWays != 0 ? kOlderWays : sets.ways - 1),
        slot_mask_(hn::Set(d_, RegionTable::kSlots - 1)),
        index_mask_(hn::Set(d_, sets.sets - 1)),
        last_set_(sets.sets - 1),
        line_shift_(sets.line_shift),
        index_shift_(sets.line_shift + sets.index_shift) {}

  // `breaks` counts the vectors that were not all most-recent-way hits.
  HWY_INLINE size_t Leading(const uint64_t* granules, size_t count, size_t& breaks,
                            uint64_t& misses) const {
    const size_t lanes = hn::Lanes(d_);
    size_t i = 0;
    // Two vectors per branch: runs of most-recent-way hits average about 20 granules.
    while (i + 2 * lanes <= count) {
      hn::Vec<D> line, index;
      const auto first = Hit(granules + i, line, index);
      hn::Vec<D> second_line, second_index;
      const auto second = Hit(granules + i + lanes, second_line, second_index);
      if (HWY_LIKELY(hn::AllTrue(d_, hn::And(first, second)))) {
        i += 2 * lanes;
        continue;
      }
      if (hn::AllTrue(d_, first)) {  // the first vector changed nothing: the second's test holds
        ++breaks;
        const size_t replayed =
            TopTwo(granules + i + lanes, second, second_line, second_index, misses);
        i += lanes + replayed;
        if (replayed < lanes) return i;
        continue;
      }
      // The second vector is tested again against the state the first leaves.
      ++breaks;
      const size_t replayed = TopTwo(granules + i, first, line, index, misses);
      i += replayed;
      if (replayed < lanes) return i;
    }
    for (; i + lanes <= count; i += lanes) {
      hn::Vec<D> line, index;
      const auto hit = Hit(granules + i, line, index);
      if (hn::AllTrue(d_, hit)) continue;
      ++breaks;
      const size_t replayed = TopTwo(granules + i, hit, line, index, misses);
      if (replayed < lanes) return i + replayed;
    }
    for (; i < count; ++i) {
      const uint64_t slot = (granules[i] >> kRegionShift) & (RegionTable::kSlots - 1);
      const uint64_t frame = granules[i] + offsets_[slot];
      if (!Step(granules[i], frame >> line_shift_, (frame >> index_shift_) & last_set_, misses)) {
        return i;
      }
    }
    return count;
  }

 private:
  // Lanes whose line is its set's most recent way; `line` and `index` (set index) of every lane.
  // Set indices stay in range for every lane.
  HWY_INLINE auto Hit(const uint64_t* granules, hn::Vec<D>& line, hn::Vec<D>& index) const {
    const auto granule = hn::LoadU(d_, granules);
    const auto slot = hn::And(hn::ShiftRight<kRegionShift>(granule), slot_mask_);
    const auto frame = hn::Add(granule, hn::GatherIndex(d_, offsets_, hn::BitCast(di_, slot)));
    if constexpr (kPlain) {
      line = frame;
      index = hn::And(frame, index_mask_);
    } else {
      line = hn::ShiftRightSame(frame, line_shift_);
      index = hn::And(hn::ShiftRightSame(frame, index_shift_), index_mask_);
    }
    return hn::Eq(hn::GatherIndex(d_, recent_, hn::BitCast(di_, index)), line);
  }

  // Replays the lanes of a vector (`granules`) in order from its first lane that missed way 0
  // (`recent`: the lanes that hit way 0 of the state before the vector, not all of them; the
  // lanes before that one changed nothing) while Step takes them; returns how many lanes were
  // replayed.
  HWY_INLINE size_t TopTwo(const uint64_t* granules, hn::Mask<D> recent, hn::Vec<D> line,
                           hn::Vec<D> index, uint64_t& misses) const {
    const size_t lanes = hn::Lanes(d_);
    size_t j = hn::FindKnownFirstTrue(d_, hn::Not(recent));
    if (older_ways_ == 0) return j;
    HWY_ALIGN uint64_t lane_line[hn::MaxLanes(D())];
    HWY_ALIGN uint64_t lane_set[hn::MaxLanes(D())];
    hn::Store(line, d_, lane_line);
    hn::Store(index, d_, lane_set);
    for (; j < lanes; ++j) {
      if (!Step(granules[j], lane_line[j], lane_set[j], misses)) return j;
    }
    return lanes;
  }

  // The access of `granule` (`line` in set `set`, by its slot's offset) when the set's two most
  // recent ways hold it (a way-1 hit swaps the two) or its region is its slot's (then the full
  // access, as AccessOne makes it, a miss counted against the region): true. False, nothing
  // changed, for a region not in its slot (whose lines are never cached, RegionTable) or a miss
  // of a one-way cache.
  HWY_INLINE bool Step(uint64_t granule, uint64_t line, uint64_t set, uint64_t& misses) const {
    if (StepTopTwo(line, set)) return true;
    const uint64_t id = granule >> kRegionShift;
    const size_t slot = id & (RegionTable::kSlots - 1);
    if (older_ways_ == 0 || regions_.ids[slot] != id) return false;
    uint64_t* const recent = recent_ + set;
    uint64_t* const row = way1_ + set * older_ways_;  // SetArray::older_of
    bool hit;
    if constexpr (kOlderWays == 15) {
      hit = AccessAllWays(recent, row, line);
    } else {
      hit = AccessPastTopTwo<kOlderWays>(recent, row, older_ways_, line);
    }
    regions_.misses[slot] += hit ? 0 : 1;
    misses += hit ? 0 : 1;
    return true;
  }

  // The access of `line` in set `set` if the set's two most recent ways hold it (then true: a
  // way-1 hit swaps the two); false, and nothing changed, if they do not.
  HWY_INLINE bool StepTopTwo(uint64_t line, uint64_t set) const {
    uint64_t* const most_recent = recent_ + set;
    if (*most_recent == line) return true;
    if (older_ways_ == 0) return false;
    uint64_t* const way1 = way1_ + set * older_ways_;  // SetArray::older_of
    if (*way1 != line) return false;
    *way1 = *most_recent;
    *most_recent = line;
    return true;
  }

  D d_;
  hn::RebindToSigned<D> di_;
  RegionTable& regions_;
  const uint64_t* offsets_;
  uint64_t* recent_;
  uint64_t* way1_;
  size_t older_ways_;
  hn::Vec<D> slot_mask_, index_mask_;
  uint64_t last_set_;
  int line_shift_, index_shift_;
};

template <bool kPlain, size_t kOlderWays>
uint64_t ReplayPowerOfTwoSets(const SetArray& sets, RegionTable& regions,
                              const uint64_t* granules, size_t count, uint64_t& extra_accesses);

// Whether every granule of [granules, granules + count), taken with its slot's offset, is its
// set's most recent way (power-of-two sets). A granule whose region is not its slot's never is
// (RegionTable). Whole vectors as RecentHits::Hit tests them, then the rest one by one.
template <bool kPlain>
HWY_INLINE bool AllMostRecent(const SetArray& sets, const RegionTable& regions,
                              const uint64_t* granules, size_t count) {
  const D d;
  const hn::RebindToSigned<D> di;
  const size_t lanes = hn::Lanes(d);
  const int line_shift = kPlain ? 0 : sets.line_shift;
  const int index_shift = kPlain ? 0 : sets.line_shift + sets.index_shift;
  const auto slot_mask = hn::Set(d, RegionTable::kSlots - 1);
  const auto index_mask = hn::Set(d, sets.sets - 1);
  size_t k = 0;
  for (; k + lanes <= count; k += lanes) {
    const auto granule = hn::LoadU(d, granules + k);
    const auto slot = hn::And(hn::ShiftRight<kRegionShift>(granule), slot_mask);
    const auto frame = hn::Add(granule, hn::GatherIndex(d, regions.offsets, hn::BitCast(di, slot)));
    const auto line = hn::ShiftRightSame(frame, line_shift);
    const auto index = hn::And(hn::ShiftRightSame(frame, index_shift), index_mask);
    if (!hn::AllTrue(d, hn::Eq(hn::GatherIndex(d, sets.tags, hn::BitCast(di, index)), line))) return false;
  }
  for (; k < count; ++k) {
    const uint64_t granule = granules[k];
    const uint64_t frame =
        granule + regions.offsets[(granule >> kRegionShift) & (RegionTable::kSlots - 1)];
    const uint64_t line = frame >> line_shift;
    if (sets.tags[(frame >> index_shift) & (sets.sets - 1)] != line) return false;
  }
  return true;
}

// The passes of a repeat entry's window that ReplayRepeat's first test did not settle (granules
// of the window sharing a set), replayed one by one until one of them misses nowhere: in an LRU
// set, a pass over the window without a miss leaves the window's lines on top in the order of
// their last access and the other lines below them in their order, so every later pass hits
// again and leaves the same state (the window's lines are then all within the top ways).
template <bool kPlain, size_t kOlderWays>
HWY_NOINLINE uint64_t ReplayRepeatPasses(const SetArray& sets, RegionTable& regions,
                                         const uint64_t* window, uint32_t size, uint32_t repeats) {
  uint64_t misses = 0;
  for (uint32_t pass = 0; pass < repeats; ++pass) {
    uint64_t none = 0;  // a window holds no repeat entry
    const uint64_t pass_misses =
        ReplayPowerOfTwoSets<kPlain, kOlderWays>(sets, regions, window, size, none);
    misses += pass_misses;
    if (pass_misses == 0) break;
  }
  return misses;
}

// The repeat entry at `entry` (trace_repeats.h), its window just replayed before it: the window
// again, as many times as the entry says. Where every granule of the window is its set's most
// recent way, another pass hits every time and changes nothing, so the passes are counted as
// hits without replaying them: one SIMD test, inline (the usual case, the window's granules in
// sets of their own). Otherwise passes are replayed until one misses nowhere
// (ReplayRepeatPasses). Adds the accesses the entry stands for, less the one its entry was
// counted as, to `extra_accesses`; returns the misses.
template <bool kPlain, size_t kOlderWays>
HWY_INLINE uint64_t ReplayRepeat(const SetArray& sets, RegionTable& regions,
                                 const uint64_t* entry, uint64_t& extra_accesses) {
  const uint32_t size = trace_repeat_window(*entry), repeats = trace_repeat_count(*entry);
  const uint64_t* const window = entry - size;
  extra_accesses += uint64_t{size} * repeats - 1;
  if (HWY_LIKELY(AllMostRecent<kPlain>(sets, regions, window, size))) return 0;
  return ReplayRepeatPasses<kPlain, kOlderWays>(sets, regions, window, size, repeats);
}

// Granules [i, end) one at a time for the default 16-way cache with power-of-two sets: a hit in
// either of the set's two most recent ways is taken without a branch on which (a way-1 hit
// swaps the two), so the only data-dependent branch is the one into AccessAllWays. For streams
// where the vector test of RecentHits breaks every few granules (a trilinear footprint
// alternating two rows of one set), which costs a mispredicted branch or two per break.
// Returns the misses; `breaks` counts the accesses that missed the most recent way.
template <bool kPlain>
HWY_INLINE uint64_t ReplayTopTwoScalar(const SetArray& sets, RegionTable& regions,
                                       const uint64_t* granules, size_t count, size_t& breaks,
                                       uint64_t& extra_accesses) {
  constexpr size_t kOlderWays = 15;
  uint64_t misses = 0;
  for (size_t i = 0; i < count; ++i) {
    // A repeat entry's "region" is never in its slot, so it is looked for only there.
    const uint64_t id = granules[i] >> kRegionShift;
    const size_t id_slot = id & (RegionTable::kSlots - 1);
    uint64_t offset = regions.offsets[id_slot];
    if (HWY_UNLIKELY(regions.ids[id_slot] != id)) {
      if (is_trace_repeat(granules[i])) {
        misses += ReplayRepeat<kPlain, kOlderWays>(sets, regions, granules + i, extra_accesses);
        continue;
      }
      offset = regions.offset(id);
    }
    const auto [slot, line, recent, row] = PlaceAt<kPlain, kOlderWays>(sets, granules[i], offset);
    const uint64_t way0 = *recent, way1 = row[0];
    const bool in_way1 = way1 == line;
    breaks += way0 == line ? 0 : 1;
    if (HWY_LIKELY((way0 == line) | in_way1)) {
      row[0] = in_way1 ? way0 : way1;
      *recent = line;
      continue;
    }
    const bool hit = AccessAllWays(recent, row, line);
    regions.misses[slot] += hit ? 0 : 1;
    misses += hit ? 0 : 1;
  }
  return misses;
}

// Blocks of granules, each replayed by whichever loop suits the stream as the block before saw
// it: RecentHits' vectors where runs of most-recent-way hits are long (a vector costs about what
// one scalar access does), ReplayTopTwoScalar where the runs break more than once in
// kScalarBreakRatio granules. Both give the counts of the per-access loop, so the choice changes
// only the time (bench/texture_replay_bench.cpp: DamagedHelmet's lambert trace breaks every 3-4
// granules, the demo's every 20-30). The scalar loop executes more instructions per access than a
// vector of hits does, but mispredicts less: 1 break in 8 was as fast as or faster than 1 in 16
// or 32 on every captured frame.
template <bool kPlain, size_t kOlderWays>
uint64_t ReplayPowerOfTwoSets(const SetArray& sets, RegionTable& regions,
                              const uint64_t* granules, size_t count, uint64_t& extra_accesses) {
  constexpr size_t kBlock = 512;
  constexpr size_t kScalarBreakRatio = 8;
  const RecentHits<kPlain, kOlderWays> recent_hits(sets, regions);
  uint64_t misses = 0;
  bool scalar = false;
  size_t i = 0;
  while (i < count) {
    const size_t end = count - i > kBlock ? i + kBlock : count;
    size_t breaks = 0;
    if (scalar) {
      misses += ReplayTopTwoScalar<kPlain>(sets, regions, granules + i, end - i, breaks, extra_accesses);
      i = end;
    } else {
      while (true) {
        i += recent_hits.Leading(granules + i, end - i, breaks, misses);
        if (i == end) break;
        // Leading stopped at a granule whose region is not in its slot (or, in a one-way
        // cache, that missed), or at a repeat entry (its "region" is never a slot's).
        // A repeat entry is no break of the stream's hits: it does not count towards the
        // scalar loop.
        if (is_trace_repeat(granules[i])) {
          misses += ReplayRepeat<kPlain, kOlderWays>(sets, regions, granules + i, extra_accesses);
        } else {
          misses += !AccessOne<kPlain, kOlderWays>(sets, regions, granules[i], true);
          ++breaks;
        }
        ++i;
      }
    }
    scalar = kOlderWays == 15 && breaks * kScalarBreakRatio > kBlock;  // the scalar loop is 16-way
  }
  return misses;
}

// The general sets (not a power of two): every access the long way, a repeat entry's window
// replayed again as many times as it says.
uint64_t ReplayAnySets(const SetArray& sets, RegionTable& regions, const uint64_t* granules,
                       size_t count, uint64_t& extra_accesses) {
  uint64_t misses = 0;
  for (size_t i = 0; i < count; ++i) {
    if (!is_trace_repeat(granules[i])) {
      misses += !AccessOne<false, 0>(sets, regions, granules[i]);
      continue;
    }
    const uint32_t size = trace_repeat_window(granules[i]), repeats = trace_repeat_count(granules[i]);
    extra_accesses += uint64_t{size} * repeats - 1;
    for (uint32_t pass = 0; pass < repeats; ++pass) {
      for (size_t k = i - size; k < i; ++k) misses += !AccessOne<false, 0>(sets, regions, granules[k]);
    }
  }
  return misses;
}

ReplayedGranules ReplayGranulesKernel(const SetArray& sets, RegionTable& regions,
                                      const uint64_t* granules, size_t count) {
  uint64_t extra = 0, misses;
  if (!sets.sets_are_power_of_two) {
    misses = ReplayAnySets(sets, regions, granules, count, extra);
  } else if (sets.line_shift == 0 && sets.index_shift == 0) {
    misses = sets.ways == 16 ? ReplayPowerOfTwoSets<true, 15>(sets, regions, granules, count, extra)
                             : ReplayPowerOfTwoSets<true, 0>(sets, regions, granules, count, extra);
  } else {
    misses = sets.ways == 16 ? ReplayPowerOfTwoSets<false, 15>(sets, regions, granules, count, extra)
                             : ReplayPowerOfTwoSets<false, 0>(sets, regions, granules, count, extra);
  }
  return {count + extra, misses};
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(ReplayGranulesKernel);

ReplayedGranules replay_granules(const SetArray& sets, RegionTable& regions,
                                 const uint64_t* granules, size_t count) {
  return HWY_DYNAMIC_DISPATCH(ReplayGranulesKernel)(sets, regions, granules, count);
}

}  // namespace ontile
#endif  // HWY_ONCE
