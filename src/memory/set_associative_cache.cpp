// The shared set-associative LRU cache (see set_associative_cache.h).
#include "memory/set_associative_cache.h"

#include <bit>

namespace ontile {

SetAssociativeCache::SetAssociativeCache(uint32_t sets, uint32_t ways, int line_shift) {
  tags_.assign(static_cast<size_t>(sets) * ways, kEmpty);
  state_.assign(tags_.size(), 0);  // flush() reads and clears it, also before any access
  sets_.tags = tags_.data();
  sets_.sets = sets;
  sets_.ways = ways;
  sets_.line_shift = line_shift;
  sets_.sets_are_power_of_two = std::has_single_bit(sets);
}

// The same move-to-front pass as SetArray::access_line, carrying each way's state with its tag
// (state_ has tags_'s layout).
bool SetAssociativeCache::access_line_write_back(uint64_t line, uint32_t owner, bool write,
                                                 WriteBack& evicted) {
  evicted = WriteBack{};
  const uint32_t set = sets_.index_of_line(line);
  uint64_t* tag = tags_.data() + set;
  uint32_t* state = state_.data() + set;
  const uint32_t written = write ? kDirty : 0;
  if (*tag == line) {
    *state |= written;
    return true;
  }
  uint32_t* front = state;
  uint64_t carried = *tag;
  uint32_t carried_state = *state;
  *tag = line;
  const size_t older = sets_.slot_of(set, 1);
  tag = tags_.data() + older;
  state = state_.data() + older;
  for (uint32_t position = 1; position < sets_.ways; ++position, ++tag, ++state) {
    const uint64_t held = *tag;
    const uint32_t held_state = *state;
    *tag = carried;
    *state = carried_state;
    if (held == line) {
      *front = held_state | written;
      return true;
    }
    carried = held;
    carried_state = held_state;
  }
  *front = owner << 1 | written;
  if (carried != kEmpty && (carried_state & kDirty)) evicted = WriteBack{true, carried_state >> 1};
  return false;
}

}  // namespace ontile
