// The texture replay's pooled working memory (see replay_scratch.h).
#include "memory/replay_scratch.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "util/free_list.h"

namespace ontile {
namespace {

FreeList<std::unique_ptr<ReplayScratch>>& pool() {
  static FreeList<std::unique_ptr<ReplayScratch>> instance;
  return instance;
}

}  // namespace

uint64_t* GranuleBuffer::reserve_tail(size_t count) {
  if (size_ + count > capacity_) {
    const size_t capacity = std::max(size_ + count, 2 * capacity_);
    std::unique_ptr<uint64_t[]> grown = std::make_unique_for_overwrite<uint64_t[]>(capacity);
    if (size_ > 0) std::memcpy(grown.get(), data_.get(), size_ * sizeof(uint64_t));
    data_ = std::move(grown);
    capacity_ = capacity;
  }
  return data_.get() + size_;
}

void ReplayScratch::prepare(size_t tile_count, size_t worker_count, size_t group_count) {
  if (workers.size() < worker_count) workers.resize(worker_count);
  for (Worker& worker : workers) {
    if (worker.groups.size() < group_count) worker.groups.resize(group_count);
    for (GranuleBuffer& group : worker.groups) group.clear();
    worker.region_ids.clear();
  }
  tiles.assign(tile_count, Tile{});
  group_ranges.assign(2 * tile_count * group_count, 0);
  if (group_tags.size() < group_count) group_tags.resize(group_count);
}

ReplayScratchLease::ReplayScratchLease() : scratch_(pool().take()) {
  if (!scratch_) scratch_ = std::make_unique<ReplayScratch>();
}

ReplayScratchLease::~ReplayScratchLease() { pool().give_back(std::move(scratch_)); }

}  // namespace ontile
