// The texture replay's inner loop (memory/texture_replay_kernel.h, replay_granules) against a
// plain per-access LRU written here, on streams made to defeat its shortcuts: lines of one set
// alternating (hits in way 1 and deeper, inside vectors too), more regions than the region table's 64 slots (ids
// sharing a slot, interleaved), power-of-two and other set counts, 1 to 16 ways, wide lines, and
// set indices taken above a shift (as the parallel replay's groups do). Every call's misses, the
// misses of every region and the final order of every set's ways must be the reference's.
#include <gtest/gtest.h>

#include <cstdint>
#include <list>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "memory/set_associative_cache.h"
#include "memory/texture_cache.h"
#include "memory/texture_replay_kernel.h"
#include "memory/trace_repeats.h"
#include "raster/cell_raster.h"

namespace ontile {
namespace {

constexpr int kRegionShift = TextureCache::kRegionShiftGranules;

struct Shape {
  uint32_t sets, ways;
  int line_shift, index_shift;
};

std::string name_of(const Shape& s) {
  return std::to_string(s.sets) + " sets x " + std::to_string(s.ways) + " ways, line shift " +
         std::to_string(s.line_shift) + ", index shift " + std::to_string(s.index_shift);
}

// Region id -> frame offset: regions 4 KiB apart from granule 2^34 on, in first-use order, as
// TextureCache places them; the order of first use is recorded.
struct Placement {
  std::map<uint64_t, uint64_t> offsets;
  std::vector<uint64_t> order;
  uint64_t offset(uint64_t id) {
    if (id == 0) return 0;
    auto it = offsets.find(id);
    if (it == offsets.end()) {
      const uint64_t base = (uint64_t{1} << kRegionShift) + 64 * 37 * offsets.size();
      it = offsets.emplace(id, base - (id << kRegionShift)).first;
      order.push_back(id);
    }
    return it->second;
  }
  static uint64_t resolve(void* self, uint64_t id) { return static_cast<Placement*>(self)->offset(id); }
};

// The definition: each set a list of lines, most recent first.
class PlainLru {
 public:
  explicit PlainLru(const Shape& s) : shape_(s), sets_(s.sets) {}
  bool access(uint64_t frame_granule) {
    const uint64_t line = frame_granule >> shape_.line_shift;
    std::list<uint64_t>& set = sets_[(line >> shape_.index_shift) % shape_.sets];
    for (auto it = set.begin(); it != set.end(); ++it) {
      if (*it == line) {
        set.erase(it);
        set.push_front(line);
        return true;
      }
    }
    set.push_front(line);
    if (set.size() > shape_.ways) set.pop_back();
    return false;
  }
  const std::list<uint64_t>& set(uint32_t index) const { return sets_[index]; }

 private:
  Shape shape_;
  std::vector<std::list<uint64_t>> sets_;
};

SetArray set_array(const Shape& s, std::vector<uint64_t>& storage) {
  storage.assign(size_t{s.sets} * s.ways, SetAssociativeCache::kEmpty);
  SetArray sets;
  sets.tags = storage.data();
  sets.sets = s.sets;
  sets.ways = s.ways;
  sets.line_shift = s.line_shift;
  sets.index_shift = s.index_shift;
  sets.sets_are_power_of_two = (s.sets & (s.sets - 1)) == 0;
  return sets;
}

// The traced granule of line `line_in_region` of region `id` (a whole line: its first granule
// plus `granule_in_line`).
uint64_t granule(const Shape& s, uint64_t id, uint64_t line_in_region, uint64_t granule_in_line) {
  return (id << kRegionShift) + (line_in_region << s.line_shift) + granule_in_line;
}

// Streams of traced granules, cut into calls ("tiles") of random lengths. Lines of one set are
// `sets << index_shift` lines apart.
std::vector<std::vector<uint64_t>> adversarial_calls(const Shape& s, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const uint64_t set_stride = uint64_t{s.sets} << s.index_shift;  // lines between same-set lines
  const uint64_t granules_per_line = uint64_t{1} << s.line_shift;
  std::vector<uint64_t> stream;
  const auto push = [&](uint64_t g) {
    if (stream.empty() || stream.back() != g) stream.push_back(g);  // the recorder merges repeats
  };
  for (int block = 0; block < 400; ++block) {
    const uint64_t id = rng() % 4 == 0 ? 0 : 1 + rng() % 3;
    switch (rng() % 7) {
      case 0: {  // two or three lines of one set alternating: way-1 and way-2 hits
        const uint64_t base = rng() % 64, count = 2 + rng() % 2;
        for (int i = 0; i < 40; ++i) push(granule(s, id, base + (i % count) * set_stride, 0));
        break;
      }
      case 1: {  // ways + 1 lines of one set in a cycle: LRU thrashes, every access misses
        const uint64_t base = rng() % 64;
        for (uint64_t i = 0; i < 3 * (s.ways + 1); ++i) {
          push(granule(s, id, base + (i % (s.ways + 1)) * set_stride, 0));
        }
        break;
      }
      case 2: {  // 200 regions, many sharing a table slot (id = k mod 64), interleaved
        for (int i = 0; i < 60; ++i) {
          const uint64_t region = 1 + (rng() % 4) * 64 + rng() % 50;
          push(granule(s, region, rng() % 8, rng() % granules_per_line));
        }
        break;
      }
      case 3: {  // a long run of recent hits with one deeper hit at a random lane
        const uint64_t base = rng() % 256;
        for (int i = 0; i < 70; ++i) push(granule(s, id, base + (i % 3), rng() % granules_per_line));
        push(granule(s, id, base + 5 * set_stride, 0));
        break;
      }
      case 4: {  // several regions' lines landing in one set, each region alternating
        for (int i = 0; i < 48; ++i) push(granule(s, 1 + i % 4, (i / 4) % 3 * set_stride, 0));
        break;
      }
      case 5: {  // two lines of one set alternating (way-1 hits inside vectors), every fifth
                 // granule of a region sharing the table slot: the way-1 steps meet a region
                 // that must be resolved, and the region they use leaves its slot
        const uint64_t base = rng() % 64;
        for (int i = 0; i < 60; ++i) {
          const uint64_t region = i % 5 == 4 ? id + 64 : id;
          push(granule(s, region, base + (i % 2) * set_stride, 0));
        }
        break;
      }
      default: {  // random lines of a small pool: hits at every depth and misses
        for (int i = 0; i < 50; ++i) {
          push(granule(s, id, rng() % (uint64_t{s.sets} * s.ways * 2 + 3) << s.index_shift,
                       rng() % granules_per_line));
        }
      }
    }
  }
  std::vector<std::vector<uint64_t>> calls;
  for (size_t at = 0; at < stream.size();) {
    const size_t length = std::min<size_t>(stream.size() - at, rng() % 90);
    calls.emplace_back(stream.begin() + static_cast<std::ptrdiff_t>(at),
                       stream.begin() + static_cast<std::ptrdiff_t>(at + length));
    at += length;
  }
  return calls;
}

// Replays `calls` in order through the kernel and through PlainLru: every call's misses, the
// misses per region, the order of first use and the final ways of every set must agree.
void expect_replays_as_plain_lru(const Shape& shape, const std::vector<std::vector<uint64_t>>& calls,
                                 const std::string& what) {
  std::vector<uint64_t> storage;
  const SetArray sets = set_array(shape, storage);
  Placement placement, reference_placement;
  RegionTable regions(&Placement::resolve, &placement);
  PlainLru reference(shape);
  std::map<uint64_t, uint64_t> expected_by_region;
  uint64_t hits = 0, misses = 0;
  for (const std::vector<uint64_t>& call : calls) {
    uint64_t expected = 0;
    const std::vector<uint64_t> expanded = expand_trace_repeats(call);
    for (const uint64_t g : expanded) {
      const uint64_t id = g >> kRegionShift;
      if (!reference.access(g + reference_placement.offset(id))) {
        ++expected;
        ++expected_by_region[id];
      }
    }
    const ReplayedGranules replayed = replay_granules(sets, regions, call.data(), call.size());
    ASSERT_EQ(replayed.misses, expected) << what;
    ASSERT_EQ(replayed.accesses, expanded.size()) << what;
    misses += expected;
    hits += expanded.size() - expected;
  }
  // Both outcomes occur (but a cache of one line never hits: repeats are merged when traced).
  if (shape.sets * shape.ways > 1) EXPECT_GT(hits, 500u) << what;
  EXPECT_GT(misses, 500u) << what;
  std::map<uint64_t, uint64_t> by_region;
  regions.add_misses_to(by_region);
  EXPECT_EQ(by_region, expected_by_region) << what;
  EXPECT_EQ(placement.order, reference_placement.order) << what << ": first-use placement";
  for (uint32_t set = 0; set < shape.sets; ++set) {
    std::vector<uint64_t> ways;
    for (uint32_t way = 0; way < shape.ways; ++way) {
      const uint64_t tag = sets.tags[sets.slot_of(set, way)];
      if (tag != SetAssociativeCache::kEmpty) ways.push_back(tag);
    }
    const std::list<uint64_t>& expected = reference.set(set);
    ASSERT_EQ(ways, std::vector<uint64_t>(expected.begin(), expected.end())) << what << ", set " << set;
  }
}

TEST(TextureReplayKernel, AdversarialStreamsReplayAsThePlainLru) {
  const Shape shapes[] = {{256, 16, 0, 0}, {16, 16, 0, 0}, {64, 4, 0, 0}, {8, 2, 0, 0},
                          {32, 1, 0, 0},   {1, 16, 0, 0},  {1, 1, 0, 0},  {48, 16, 0, 0},
                          {7, 3, 0, 0},    {5, 1, 0, 0},   {64, 16, 2, 0}, {32, 8, 1, 2},
                          {128, 16, 0, 1}, {12, 5, 2, 1},  {4, 9, 0, 0},  {2, 17, 0, 0}};
  for (const Shape& shape : shapes) {
    for (uint64_t seed = 1; seed <= 3; ++seed) {
      expect_replays_as_plain_lru(shape, adversarial_calls(shape, seed),
                                  name_of(shape) + ", seed " + std::to_string(seed));
    }
  }
}

// Restores the automatic SIMD target however the test ends.
struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

// Long calls whose stretches alternate between breaking the most-recent-way runs at almost every
// granule (a pair of lines of one set, ways + 1 lines thrashing) and long runs of most-recent-way
// hits, so the 16-way kernel switches between its vector and scalar loops inside a call and
// from call to call (blocks of 512 granules). On every SIMD target the machine runs.
TEST(TextureReplayKernel, LongCallsSwitchingLoopsReplayAsThePlainLruOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  const Shape shapes[] = {{256, 16, 0, 0}, {16, 16, 0, 0}, {64, 16, 2, 0}, {128, 16, 0, 1}};
  for (const std::string& target : simd_targets()) {
    force_simd_target(target);
    for (const Shape& shape : shapes) {
      std::mt19937_64 rng(7);
      const uint64_t set_stride = uint64_t{shape.sets} << shape.index_shift;
      std::vector<uint64_t> stream;
      const auto push = [&](uint64_t g) {
        if (stream.empty() || stream.back() != g) stream.push_back(g);
      };
      for (int stretch = 0; stretch < 24; ++stretch) {
        const uint64_t id = 1 + rng() % 3, base = rng() % 64;
        const int kind = stretch % 3;
        for (int i = 0; i < 1500; ++i) {
          if (kind == 0) {  // two or three lines of one set alternating: way-1 and way-2 hits
            push(granule(shape, id, base + (i % (2 + stretch % 2)) * set_stride, 0));
          } else if (kind == 1) {  // ways + 1 lines of one set in a cycle, every few with a fresh line
            const uint64_t line = i % 7 == 6 ? rng() % 4096 : base + (i % (shape.ways + 1)) * set_stride;
            push(granule(shape, id, line, 0));
          } else {  // runs of most-recent-way hits: three lines of different sets, now and then a new one
            push(granule(shape, id, base + i / 200 * 3 + i % 3, 0));
          }
        }
      }
      std::vector<std::vector<uint64_t>> calls;
      for (size_t at = 0; at < stream.size();) {
        const size_t length = std::min<size_t>(stream.size() - at, 700 + rng() % 5000);
        calls.emplace_back(stream.begin() + static_cast<std::ptrdiff_t>(at),
                           stream.begin() + static_cast<std::ptrdiff_t>(at + length));
        at += length;
      }
      expect_replays_as_plain_lru(shape, calls, name_of(shape) + ", target " + target);
    }
  }
}

// Full-screen copy traces (each quad row's two new lines A B, then A B repeated: 2 misses in
// every 8 or 16 granules, inside the vectors, which the kernel replays in place), with now and
// then a granule of a region sharing the table slot (a miss and a region to resolve in one
// vector) or a line of a row before (a deeper hit). On every SIMD target the machine runs.
TEST(TextureReplayKernel, CopyTracesMissingInsideVectorsReplayAsThePlainLruOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  const Shape shapes[] = {{256, 16, 0, 0}, {64, 16, 0, 0}, {64, 16, 2, 0}, {128, 16, 0, 1},
                          {64, 4, 0, 0},   {48, 16, 0, 0}, {32, 1, 0, 0}};
  for (const std::string& target : simd_targets()) {
    force_simd_target(target);
    for (const Shape& shape : shapes) {
      std::mt19937_64 rng(11);
      const uint64_t granules_per_line = uint64_t{1} << shape.line_shift;
      std::vector<uint64_t> stream;
      const auto push = [&](uint64_t g) {
        if (stream.empty() || stream.back() != g) stream.push_back(g);
      };
      const uint64_t row_lines = 241 + shape.sets / 2;  // the next row: another set
      for (uint64_t row = 0; row < 300; ++row) {
        const uint64_t repeats = row % 2 == 0 ? 4 : 8;
        for (uint64_t column = 0; column < 6; ++column) {
          const uint64_t a = 2 * row * row_lines + column, b = a + row_lines;
          for (uint64_t k = 0; k < repeats; ++k) {
            push(granule(shape, 1, a, k % granules_per_line));
            push(granule(shape, 1, b, k % granules_per_line));
            if (rng() % 29 == 0) push(granule(shape, 1 + 64 * (1 + rng() % 2), rng() % 64, 0));
            if (rng() % 31 == 0 && row > 0) push(granule(shape, 1, a - 2 * row_lines, 0));
          }
        }
      }
      std::vector<std::vector<uint64_t>> calls;
      for (size_t at = 0; at < stream.size();) {
        const size_t length = std::min<size_t>(stream.size() - at, 300 + rng() % 2000);
        calls.emplace_back(stream.begin() + static_cast<std::ptrdiff_t>(at),
                           stream.begin() + static_cast<std::ptrdiff_t>(at + length));
        at += length;
      }
      expect_replays_as_plain_lru(shape, calls, name_of(shape) + ", copy trace, target " + target);
    }
  }
}

// `calls` with repeat entries (trace_repeats.h) put in at random points: the last W entries of
// the call so far (1 to 40 of them, none a repeat entry) again R times (1 to 12). Windows of one
// line per set (whose passes after the first all hit), of lines sharing sets or a region slot
// (replayed pass by pass), of one entry (as the parallel replay's groups may hold).
std::vector<std::vector<uint64_t>> with_repeats(const std::vector<std::vector<uint64_t>>& calls,
                                                uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::vector<uint64_t>> folded;
  for (const std::vector<uint64_t>& call : calls) {
    std::vector<uint64_t> out;
    size_t granules_since_repeat = 0;
    for (const uint64_t g : call) {
      out.push_back(g);
      ++granules_since_repeat;
      if (rng() % 6 == 0) {
        const size_t window = 1 + rng() % std::min<size_t>(granules_since_repeat, 40);
        out.push_back(trace_repeat(static_cast<uint32_t>(window), static_cast<uint32_t>(1 + rng() % 12)));
        granules_since_repeat = 0;
      }
    }
    folded.push_back(std::move(out));
  }
  return folded;
}

TEST(TextureReplayKernel, RepeatEntriesReplayAsTheirExpansionOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  const Shape shapes[] = {{256, 16, 0, 0}, {16, 16, 0, 0}, {64, 4, 0, 0}, {32, 1, 0, 0},
                          {48, 16, 0, 0},  {7, 3, 0, 0},   {64, 16, 2, 0}, {128, 16, 0, 1},
                          {12, 5, 2, 1},   {1, 16, 0, 0}};
  for (const std::string& target : simd_targets()) {
    force_simd_target(target);
    for (const Shape& shape : shapes) {
      for (uint64_t seed = 1; seed <= 2; ++seed) {
        expect_replays_as_plain_lru(shape, with_repeats(adversarial_calls(shape, seed), seed),
                                    name_of(shape) + ", repeats, seed " + std::to_string(seed) +
                                        ", target " + target);
      }
    }
  }
}

TEST(TraceRepeats, FolderMakesRepeatEntriesThatExpandToTheChunks) {
  // Chunks as a producer appends them: A B twice, then A B three more times, C D, C D, a chunk
  // of one granule (never folded), E F, E F, then E F written without fold (adjacency broken).
  const std::vector<std::vector<uint64_t>> chunks = {{1, 2}, {1, 2}, {1, 2}, {1, 2}, {1, 2},
                                                     {3, 4}, {3, 4}, {5},    {6, 7}, {6, 7}};
  std::vector<uint64_t> trace, plain;
  TraceRepeatFolder folder(1);  // every copy folded
  for (const std::vector<uint64_t>& chunk : chunks) {
    const size_t begin = trace.size();
    trace.insert(trace.end(), chunk.begin(), chunk.end());
    plain.insert(plain.end(), chunk.begin(), chunk.end());
    folder.fold(trace, begin);
  }
  trace.push_back(6);
  trace.push_back(7);
  plain.push_back(6);
  plain.push_back(7);
  folder.fold(trace, trace.size() - 2);  // adjacent to the repeat entry after 6 7: folded
  const std::vector<uint64_t> expected = {1, 2, trace_repeat(2, 4), 3, 4, trace_repeat(2, 1),
                                          5, 6, 7, trace_repeat(2, 2)};
  EXPECT_EQ(trace, expected);
  EXPECT_EQ(expand_trace_repeats(trace), plain);
  EXPECT_EQ(traced_accesses(trace), plain.size());
  // A granule appended without fold breaks adjacency: the next equal chunk is not folded.
  trace.push_back(9);
  plain.push_back(9);
  const size_t begin = trace.size();
  trace.insert(trace.end(), {6, 7});
  plain.insert(plain.end(), {6, 7});
  folder.fold(trace, begin);
  EXPECT_EQ(trace.size(), expected.size() + 3);
  EXPECT_EQ(expand_trace_repeats(trace), plain);
}

TEST(TraceRepeats, FolderKeepsShortRunsPlain) {
  // Chunks of 3: two copies (6 accesses) stay plain under a minimum of 8; the third copy (9)
  // turns the copies into one repeat entry, and the fourth adds one to it.
  TraceRepeatFolder folder(8);
  std::vector<uint64_t> trace, plain;
  for (int copy = 0; copy < 5; ++copy) {
    const size_t begin = trace.size();
    trace.insert(trace.end(), {4, 5, 6});
    plain.insert(plain.end(), {4, 5, 6});
    folder.fold(trace, begin);
    if (copy == 2) EXPECT_EQ(trace, (std::vector<uint64_t>{4, 5, 6, 4, 5, 6, 4, 5, 6}));
  }
  EXPECT_EQ(trace, (std::vector<uint64_t>{4, 5, 6, trace_repeat(3, 4)}));
  EXPECT_EQ(expand_trace_repeats(trace), plain);
  // A different chunk after two plain copies starts a new window; nothing is folded.
  TraceRepeatFolder other(8);
  std::vector<uint64_t> short_run;
  for (const std::vector<uint64_t>& chunk : {std::vector<uint64_t>{1, 2}, {1, 2}, {1, 2}, {3, 4}, {3, 4}}) {
    const size_t begin = short_run.size();
    short_run.insert(short_run.end(), chunk.begin(), chunk.end());
    other.fold(short_run, begin);
  }
  EXPECT_EQ(short_run, (std::vector<uint64_t>{1, 2, 1, 2, 1, 2, 3, 4, 3, 4}));
}

}  // namespace
}  // namespace ontile
