// The pool of texel-trace buffers (see granule_buffer_pool.h).
#include "memory/granule_buffer_pool.h"

#include <utility>

#include "util/free_list.h"

namespace ontile {
namespace {

FreeList<std::vector<uint64_t>>& pool() {
  static FreeList<std::vector<uint64_t>> instance;
  return instance;
}

}  // namespace

std::vector<uint64_t> take_granule_buffer() { return pool().take(); }

void give_back_granule_buffer(std::vector<uint64_t>& buffer) {
  if (buffer.capacity() == 0) return;
  buffer.clear();
  pool().give_back(std::move(buffer));
  buffer = std::vector<uint64_t>();
}

}  // namespace ontile
