// Working memory of the parallel texture-cache replay (texture_replay.cpp): each worker's
// granules split by group of cache sets, the texture regions each tile uses, and each group's
// private copy of its sets. Taken from a process-wide pool and given back with its memory, so
// steady-state passes and frames allocate nothing.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace ontile {

// A growable array of granules that is never zero-filled (the replay writes every slot it keeps).
class GranuleBuffer {
 public:
  // Room for `count` more granules after the first size(); returns where they go.
  uint64_t* reserve_tail(size_t count);
  void resize_within_capacity(size_t size) { size_ = size; }
  void clear() { size_ = 0; }
  const uint64_t* data() const { return data_.get(); }
  size_t size() const { return size_; }

 private:
  std::unique_ptr<uint64_t[]> data_;
  size_t size_ = 0, capacity_ = 0;
};

struct ReplayScratch {
  struct Worker {
    std::vector<GranuleBuffer> groups;  // this worker's tiles' granules, by set group
    std::vector<uint64_t> region_ids;   // its tiles' regions in first-use order, tile after tile
  };
  struct Tile {
    uint32_t worker = 0;
    uint32_t region_ids_begin = 0, region_ids_end = 0;
  };
  std::vector<Worker> workers;           // by task-arena thread index
  std::vector<Tile> tiles;
  std::vector<size_t> group_ranges;      // tile t, group k: [2 (t G + k)], [2 (t G + k) + 1]
  std::vector<std::vector<uint64_t>> group_tags;  // each group's sets (SetArray storage)

  // Emptied for `tiles` tiles, `workers` workers and `groups` groups, capacity kept.
  void prepare(size_t tile_count, size_t worker_count, size_t group_count);
};

// While alive, holds one ReplayScratch from the pool (passes replaying at the same time in
// different contexts take different ones); returns it, memory kept, on destruction.
class ReplayScratchLease {
 public:
  ReplayScratchLease();
  ~ReplayScratchLease();
  ReplayScratchLease(const ReplayScratchLease&) = delete;
  ReplayScratchLease& operator=(const ReplayScratchLease&) = delete;
  ReplayScratch& operator*() const { return *scratch_; }
  ReplayScratch* operator->() const { return scratch_.get(); }

 private:
  std::unique_ptr<ReplayScratch> scratch_;
};

}  // namespace ontile
