// The pool of per-thread texel-trace buffers (see trace_buffers.h).
#include "tiler/detail/trace_buffers.h"

#include <mutex>
#include <new>

namespace ontile {
namespace {

struct Pool {
  std::mutex mutex;
  std::vector<std::unique_ptr<ThreadTraceBuffers>> free;
};

Pool& pool() {
  static Pool instance;
  return instance;
}

}  // namespace

TraceBuffersLease::TraceBuffersLease() {
  {
    const std::lock_guard<std::mutex> lock(pool().mutex);
    if (!pool().free.empty()) {
      buffers_ = std::move(pool().free.back());
      pool().free.pop_back();
    }
  }
  if (!buffers_) buffers_ = std::make_unique<ThreadTraceBuffers>();
  for (std::vector<uint64_t>& buffer : *buffers_) buffer.clear();
}

TraceBuffersLease::~TraceBuffersLease() {
  const std::lock_guard<std::mutex> lock(pool().mutex);
  try {
    pool().free.push_back(std::move(buffers_));
  } catch (const std::bad_alloc&) {
    // No room to keep them: the buffers are freed instead, the next lease makes new ones.
  }
}

}  // namespace ontile
