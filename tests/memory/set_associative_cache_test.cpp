// The shared set-associative cache (memory/set_associative_cache.h): its write-back accesses
// give the hits, evictions and flushes of a plain timestamp-LRU write-back cache (the IMR
// render-target cache's former implementation) on random streams, and its read accesses the
// same hits as the write-back ones.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "memory/set_associative_cache.h"

namespace ontile {
namespace {

// Timestamp LRU, empty ways first: what a write-back cache with per-line state does by the book.
class ReferenceWriteBack {
 public:
  ReferenceWriteBack(uint32_t sets, uint32_t ways) : sets_(sets), ways_(ways), lines_(sets * ways) {}
  // Returns hit; adds a dirty victim's owner to `written_back`.
  bool access(uint64_t line, uint32_t owner, bool write, std::map<uint32_t, int>& written_back) {
    ++clock_;
    Line* set = &lines_[(line % sets_) * ways_];
    Line* victim = set;
    for (uint32_t w = 0; w < ways_; ++w) {
      if (set[w].valid && set[w].tag == line) {
        set[w].last_use = clock_;
        set[w].dirty = set[w].dirty || write;
        return true;
      }
      if (!victim->valid) continue;
      if (!set[w].valid || set[w].last_use < victim->last_use) victim = &set[w];
    }
    if (victim->valid && victim->dirty) ++written_back[victim->owner];
    *victim = Line{line, clock_, owner, true, write};
    return false;
  }
  void flush(std::map<uint32_t, int>& written_back) {
    for (Line& l : lines_) {
      if (l.valid && l.dirty) ++written_back[l.owner];
      l = Line{};
    }
  }

 private:
  struct Line {
    uint64_t tag = 0, last_use = 0;
    uint32_t owner = 0;
    bool valid = false, dirty = false;
  };
  uint32_t sets_, ways_;
  std::vector<Line> lines_;
  uint64_t clock_ = 0;
};

TEST(SetAssociativeCache, WriteBackMatchesATimestampLru) {
  for (const auto [sets, ways] : {std::pair{1u, 1u}, std::pair{4u, 2u}, std::pair{3u, 4u}, std::pair{8u, 16u}}) {
    SetAssociativeCache cache(sets, ways, 0);
    ReferenceWriteBack reference(sets, ways);
    std::mt19937 rng(sets * 100 + ways);
    std::map<uint32_t, int> ours, theirs;
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
      const uint64_t line = rng() % (sets * ways * 3);
      const uint32_t owner = static_cast<uint32_t>(line % 5);  // a line's owner never changes
      const bool write = rng() % 3 == 0;
      SetAssociativeCache::WriteBack evicted;
      const bool hit = cache.access_line_write_back(line, owner, write, evicted);
      ASSERT_EQ(hit, reference.access(line, owner, write, theirs)) << sets << "x" << ways << " access " << i;
      if (evicted.happened) ++ours[evicted.owner];
      hits += hit ? 1 : 0;
    }
    cache.flush([&](uint32_t owner) { ++ours[owner]; });
    reference.flush(theirs);
    EXPECT_EQ(ours, theirs) << sets << "x" << ways;
    EXPECT_GT(hits, 0);
  }
}

TEST(SetAssociativeCache, ReadAccessesHitLikeWriteBackOnes) {
  SetAssociativeCache reads(16, 4, 0), writes(16, 4, 0);
  std::mt19937 rng(3);
  for (int i = 0; i < 5000; ++i) {
    const uint64_t line = rng() % 200;
    SetAssociativeCache::WriteBack evicted;
    EXPECT_EQ(reads.access_line(line), writes.access_line_write_back(line, 0, false, evicted));
    EXPECT_FALSE(evicted.happened) << "nothing was written";
  }
}

}  // namespace
}  // namespace ontile
