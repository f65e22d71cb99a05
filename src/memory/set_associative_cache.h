// The one set-associative LRU cache behind every cache model of the memory layer: the texture
// cache (read-only, SIMD replay fast path), the parameter-buffer read cache and the IMR
// render-target cache (write-back: a line remembers its owner and whether it is dirty).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ontile {

// The ways of a group of cache sets and the mapping of lines onto them. Each set keeps its lines
// ordered from most to least recently used (exact LRU). Storage: the most recent way of every set
// first, one array (recent[set]), so replay loops test "is this line its set's most recent one"
// (about 96 % of the benchmark scenes' texture accesses) with one load, on SIMD lanes by a gather
// (texture_replay_kernel.h); then each set's older ways 1..ways-1 side by side (older_of(set)),
// so the move to the front that a miss or an older hit makes is one contiguous shift. A SetArray
// is a view: copies share the ways.
struct SetArray {
  uint64_t* tags = nullptr;  // sets x ways, ~0 = empty: recent ways, then older rows
  uint32_t sets = 0, ways = 0;
  int line_shift = 0;          // line = address unit >> line_shift (texture: log2(line / 64))
  int index_shift = 0;         // set index = (line >> index_shift) % sets
  bool sets_are_power_of_two = false;

  uint32_t index_of_line(uint64_t line) const {
    const uint64_t above = line >> index_shift;
    return static_cast<uint32_t>(sets_are_power_of_two ? above & (sets - 1) : above % sets);
  }
  // Way 0 of set `set` is tags[set]; way w >= 1 is older_of(set)[w - 1].
  uint64_t* recent() const { return tags; }
  uint64_t* older_of(uint32_t set) const {
    return tags + sets + static_cast<size_t>(set) * (ways - 1);
  }
  size_t slot_of(uint32_t set, uint32_t way) const {
    return way == 0 ? set : sets + static_cast<size_t>(set) * (ways - 1) + (way - 1);
  }
  // Looks up the line holding address unit `unit`; true on a hit. Misses fill the LRU way.
  bool access(uint64_t unit) const { return access_line(unit >> line_shift); }
  // A hit in the most recent way is one compare and no reordering. Otherwise the line moves to
  // the front in one pass: on a hit at position p ways 0..p-1 move to 1..p; on a miss every way
  // moves and the last (the least recent, or an empty way: lines only ever enter at the front,
  // so empty ways stay at the back) drops out. Inline, so replay loops make no call per access.
  bool access_line(uint64_t line) const {
    const uint32_t set = index_of_line(line);
    uint64_t* front = tags + set;
    if (*front == line) return true;
    uint64_t carried = *front;
    *front = line;
    uint64_t* way = older_of(set);
    for (uint32_t position = 1; position < ways; ++position, ++way) {
      const uint64_t held = *way;
      *way = carried;
      if (held == line) return true;
      carried = held;
    }
    return false;
  }
};

// A cache of `sets` x `ways` lines (mapping: plain modulo, no hashing, so tests can place lines
// in sets by hand; the whole line number is the tag, so a hit is unambiguous). Owns the ways that
// sets() views. The write-back accesses keep, beside each way's tag, the line's owner (an index
// the caller chooses, e.g. an attachment) and dirty bit, moved with the tag, so an eviction or a
// flush knows whom to charge; LRU order is the same as access_line's.
class SetAssociativeCache {
 public:
  static constexpr uint64_t kEmpty = ~uint64_t{0};

  SetAssociativeCache(uint32_t sets, uint32_t ways, int line_shift);
  // Moves keep the ways' storage, which sets_ points at; a copy would share it.
  SetAssociativeCache(SetAssociativeCache&&) = default;
  SetAssociativeCache& operator=(SetAssociativeCache&&) = default;
  SetAssociativeCache(const SetAssociativeCache&) = delete;
  SetAssociativeCache& operator=(const SetAssociativeCache&) = delete;

  const SetArray& sets() const { return sets_; }
  bool access_line(uint64_t line) { return sets_.access_line(line); }

  // A dirty line the cache gave up (evicted or flushed): who owns it.
  struct WriteBack {
    bool happened = false;
    uint32_t owner = 0;
  };
  // Read-only or write access to `line` owned by `owner`: true on a hit (a write makes the line
  // dirty). A miss fills the line (write-allocate) and reports in `evicted` whether the line it
  // replaced was dirty.
  bool access_line_write_back(uint64_t line, uint32_t owner, bool write, WriteBack& evicted);
  // Every dirty line's owner, once per dirty line (in storage order); then the cache is empty.
  template <typename Visit>
  void flush(Visit&& visit) {
    for (size_t i = 0; i < tags_.size(); ++i) {
      if (tags_[i] != kEmpty && (state_[i] & kDirty)) visit(state_[i] >> 1);
      tags_[i] = kEmpty;
      state_[i] = 0;
    }
  }

 private:
  static constexpr uint32_t kDirty = 1;  // state = owner << 1 | dirty
  std::vector<uint64_t> tags_;
  std::vector<uint32_t> state_;  // one per way, beside tags_
  SetArray sets_;
};

}  // namespace ontile
