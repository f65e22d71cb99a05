// The pool of texel-trace buffers (see granule_buffer_pool.h).
#include "memory/granule_buffer_pool.h"

#include <mutex>
#include <new>
#include <utility>

namespace ontile {
namespace {

struct Pool {
  std::mutex mutex;
  std::vector<std::vector<uint64_t>> free;
};

Pool& pool() {
  static Pool instance;
  return instance;
}

}  // namespace

std::vector<uint64_t> take_granule_buffer() {
  const std::lock_guard<std::mutex> lock(pool().mutex);
  if (pool().free.empty()) return {};
  std::vector<uint64_t> buffer = std::move(pool().free.back());
  pool().free.pop_back();
  return buffer;
}

void give_back_granule_buffer(std::vector<uint64_t>& buffer) {
  if (buffer.capacity() == 0) return;
  buffer.clear();
  const std::lock_guard<std::mutex> lock(pool().mutex);
  try {
    pool().free.push_back(std::move(buffer));
  } catch (const std::bad_alloc&) {
    // No room to keep it: the buffer is freed with its owner instead.
  }
  buffer = std::vector<uint64_t>();
}

}  // namespace ontile
