// Repeat entries of a texture trace (TileTrace::texture_granules): one entry standing for "the W
// entries before me, R more times", so a full-screen pass whose fragments read the same few
// granules over and over records and replays each run once. Lossless: expand_trace_repeats gives
// back the trace a plain recorder writes, and the replay counts every expanded access.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace ontile {

// A granule is a byte address / 64, so below 2^58: an entry with bit 63 set is never a granule.
// Layout: bit 63, window size W in bits 32..62, repeat count R in bits 0..31.
// Rules a trace keeps (the replay and expand_trace_repeats rely on them):
//  - W >= 2 and R >= 1; the W entries before a repeat entry are granules (no repeat entry among
//    them) and lie in the same tile's trace;
//  - the expansion is what the plain recorder writes: granules with consecutive repeats dropped
//    (so a window's first granule differs from its last).
inline constexpr uint64_t kTraceRepeatBit = uint64_t{1} << 63;
inline constexpr uint32_t kTraceRepeatMaxCount = 0xffffffffu;

inline constexpr uint64_t trace_repeat(uint32_t window, uint32_t repeats) {
  return kTraceRepeatBit | uint64_t{window} << 32 | repeats;
}
inline constexpr bool is_trace_repeat(uint64_t entry) { return (entry & kTraceRepeatBit) != 0; }
inline constexpr uint32_t trace_repeat_window(uint64_t entry) {
  return static_cast<uint32_t>(entry >> 32) & 0x7fffffffu;
}
inline constexpr uint32_t trace_repeat_count(uint64_t entry) { return static_cast<uint32_t>(entry); }

// The number of accesses a trace stands for (its expanded length).
inline uint64_t traced_accesses(std::span<const uint64_t> trace) {
  uint64_t accesses = 0;
  for (const uint64_t entry : trace) {
    accesses += is_trace_repeat(entry)
                    ? uint64_t{trace_repeat_window(entry)} * trace_repeat_count(entry)
                    : 1;
  }
  return accesses;
}

// The trace with every repeat entry replaced by the entries it stands for.
inline std::vector<uint64_t> expand_trace_repeats(std::span<const uint64_t> trace) {
  std::vector<uint64_t> expanded;
  expanded.reserve(trace.size());
  for (const uint64_t entry : trace) {
    if (!is_trace_repeat(entry)) {
      expanded.push_back(entry);
      continue;
    }
    const size_t window = trace_repeat_window(entry);
    const size_t begin = expanded.size() - window;
    for (uint32_t r = 0; r < trace_repeat_count(entry); ++r) {
      for (size_t k = 0; k < window; ++k) expanded.push_back(expanded[begin + k]);
    }
  }
  return expanded;
}

// Folds chunks a producer appends into repeat entries: after appending a chunk of granules (one
// quad's or one fragment's reads, consecutive repeats already dropped) at [chunk_begin, end), the
// producer calls fold. Chunks equal to the one before them (same size, >= 2 granules, adjacent)
// are copies of it; once the copies stand for at least `min_folded_accesses` accesses they become
// one repeat entry, and later copies add one to it. Fewer copies stay plain: the replay takes a
// repeat entry at about the cost of 20 most-recent-way hits (texture_replay_simd.cpp), so a short
// run is cheaper replayed than folded. Returns the trace's new end.
// One folder per trace: reset() where the trace starts (a new tile). Entries appended without
// fold only break adjacency, which fold notices.
class TraceRepeatFolder {
 public:
  static constexpr size_t kDefaultMinFoldedAccesses = 24;
  explicit TraceRepeatFolder(size_t min_folded_accesses = kDefaultMinFoldedAccesses)
      : min_folded_accesses_(min_folded_accesses) {}

  void reset() { window_size_ = 0; }

  size_t fold(uint64_t* trace, size_t chunk_begin, size_t end) {
    const size_t size = end - chunk_begin;
    if (size >= 2 && size == window_size_) {
      const size_t adjacent = window_begin_ + size * (1 + plain_copies_) + (repeated_ ? 1 : 0);
      if (chunk_begin == adjacent &&
          std::memcmp(trace + window_begin_, trace + chunk_begin, size * sizeof(uint64_t)) == 0) {
        uint64_t& repeat = trace[window_begin_ + size];
        if (!repeated_) {
          ++plain_copies_;
          if (plain_copies_ * size < min_folded_accesses_) return end;
          repeat = trace_repeat(static_cast<uint32_t>(size), static_cast<uint32_t>(plain_copies_));
          repeated_ = true;
          plain_copies_ = 0;
          return window_begin_ + size + 1;
        }
        if (trace_repeat_count(repeat) < kTraceRepeatMaxCount) {
          ++repeat;
          return chunk_begin;
        }
      }
    }
    window_begin_ = chunk_begin;
    window_size_ = size;
    plain_copies_ = 0;
    repeated_ = false;
    return end;
  }
  // fold for a chunk appended to a vector (resized to the new end).
  void fold(std::vector<uint64_t>& trace, size_t chunk_begin) {
    trace.resize(fold(trace.data(), chunk_begin, trace.size()));
  }

 private:
  size_t min_folded_accesses_;
  size_t window_begin_ = 0;
  size_t window_size_ = 0;   // 0: no chunk to compare with
  size_t plain_copies_ = 0;  // copies of the window kept as plain entries after it
  bool repeated_ = false;    // a repeat entry follows the window
};

}  // namespace ontile
