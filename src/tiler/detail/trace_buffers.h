// Per-thread buffers for the texel traces of a pass's tiles: every tile appends to its thread's
// buffer (tile_trace.h's GranuleRange names its part), and the buffers' memory is reused by
// later passes and frames, so recording a trace allocates only while a buffer outgrows itself.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

namespace ontile {

using ThreadTraceBuffers = tbb::enumerable_thread_specific<std::vector<uint64_t>>;

// While alive, holds one set of per-thread buffers taken from a process-wide pool, all emptied
// (capacity kept). Passes running at the same time (several contexts) take different sets.
// Returned to the pool on destruction, with their memory: the pool keeps what the largest
// traces needed.
class TraceBuffersLease {
 public:
  TraceBuffersLease();
  ~TraceBuffersLease();
  TraceBuffersLease(const TraceBuffersLease&) = delete;
  TraceBuffersLease& operator=(const TraceBuffersLease&) = delete;
  // The calling thread's buffer.
  std::vector<uint64_t>& local() const { return buffers_->local(); }

 private:
  std::unique_ptr<ThreadTraceBuffers> buffers_;
};

}  // namespace ontile
