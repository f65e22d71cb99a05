// The traces of a pass's tiles (memory/tile_trace.h), taken from a process-wide pool: each tile
// records into vectors of its own, and their capacity is reused by later passes and frames, so
// recording a trace allocates only while a tile's trace outgrows what that tile had before.
#pragma once
#include <cstddef>
#include <vector>

#include "memory/tile_trace.h"

namespace ontile {

// While alive, holds `tile_count` empty traces (capacity kept) that no other lease holds, so
// passes running at the same time (several contexts) never share one. Given back to the pool on
// destruction with their memory: the pool keeps what the largest traces needed. A set whose size
// is the pass's tile count is preferred, so a tile usually gets back its own vectors.
class TileTracesLease {
 public:
  explicit TileTracesLease(size_t tile_count);
  ~TileTracesLease();
  TileTracesLease(const TileTracesLease&) = delete;
  TileTracesLease& operator=(const TileTracesLease&) = delete;
  std::vector<TileTrace>& traces() { return traces_; }

 private:
  std::vector<TileTrace> traces_;
};

}  // namespace ontile
