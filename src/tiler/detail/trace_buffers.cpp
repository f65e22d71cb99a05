// The pool of tile traces (see trace_buffers.h).
#include "tiler/detail/trace_buffers.h"

#include <mutex>
#include <new>

namespace ontile {
namespace {

struct Pool {
  std::mutex mutex;
  std::vector<std::vector<TileTrace>> free;
};

Pool& pool() {
  static Pool instance;
  return instance;
}

}  // namespace

TileTracesLease::TileTracesLease(size_t tile_count) {
  {
    const std::lock_guard<std::mutex> lock(pool().mutex);
    std::vector<std::vector<TileTrace>>& free = pool().free;
    if (!free.empty()) {
      size_t pick = free.size() - 1;
      for (size_t i = 0; i < free.size(); ++i) {
        if (free[i].size() == tile_count) pick = i;
      }
      traces_ = std::move(free[pick]);
      free.erase(free.begin() + static_cast<std::ptrdiff_t>(pick));
    }
  }
  traces_.resize(tile_count);
  for (TileTrace& trace : traces_) {
    trace.texture_granules.clear();
    trace.fragments.clear();
  }
}

TileTracesLease::~TileTracesLease() {
  const std::lock_guard<std::mutex> lock(pool().mutex);
  try {
    pool().free.push_back(std::move(traces_));
  } catch (const std::bad_alloc&) {
    // No room to keep them: the traces are freed instead, the next lease makes new ones.
  }
}

}  // namespace ontile
