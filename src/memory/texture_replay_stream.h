// The texture-cache replay of one pass, run while the pass's tiles still execute: each tile is
// replayed, in tile-index order, as soon as it and every tile before it are recorded, so at 2 to 5
// threads the serial replay overlaps the other threads' tiles instead of following them.
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "memory/texture_cache.h"
#include "memory/texture_replay_kernel.h"

namespace ontile {

class TextureReplayObserver;

// Counts, misses per tile and per region are those of replay_texture_traces: the serial replay in
// tile order, or (from kMinimumParallelThreads threads, where one replaying thread would fall
// behind the tiles) the parallel one by set groups, which needs every tile and runs in finish().
// `traces` and `detail` must outlive the stream; `traces` is sized before and filled while the
// tiles run, each tile's granules in a vector of its own (tile_trace.h) that nothing writes once
// its tile ran, so whichever thread holds the replay may read any recorded tile.
class TextureReplayStream {
 public:
  // Replays `traces` and leaves them as they are (replay_texture_traces, tests).
  TextureReplayStream(TextureCache& cache, const std::vector<TileTrace>& traces,
                      TextureReplayDetail& detail);
  // Also gives every tile's granules back to the pool (granule_buffer_pool.h): each as soon as it
  // is replayed when nothing reads them later (a serial replay, no replay observer), the others
  // in finish(), so a pass's traces circulate through a few warm buffers.
  struct GiveBackBuffers {};
  TextureReplayStream(TextureCache& cache, std::vector<TileTrace>& traces,
                      TextureReplayDetail& detail, GiveBackBuffers);
  ~TextureReplayStream();
  TextureReplayStream(const TextureReplayStream&) = delete;
  TextureReplayStream& operator=(const TextureReplayStream&) = delete;

  // Tile `tile` ran: its trace is complete. If no other thread is replaying, replays on this
  // thread every tile from the first one not replayed yet while they are recorded, then returns.
  void tile_recorded(size_t tile);
  // Every tile ran and every tile_recorded call returned: replays the rest, returns the counts.
  TextureTraffic finish();

 private:
  TextureReplayStream(TextureCache& cache, const std::vector<TileTrace>& traces,
                      std::vector<TileTrace>* buffers_to_give_back, TextureReplayDetail& detail);
  void replay_tile(size_t tile);
  bool next_is_recorded() const;

  TextureCache& cache_;
  const std::vector<TileTrace>& traces_;
  std::vector<TileTrace>* const buffers_to_give_back_;  // traces_, when its buffers go back
  TextureReplayDetail& detail_;
  TextureReplayObserver* const observer_;
  const int threads_;
  const int group_bits_;  // > 0: replayed in finish(), in parallel by 2^group_bits_ set groups
  const bool give_back_when_replayed_;
  std::unique_ptr<std::atomic<bool>[]> recorded_;
  // The replay token: the thread that sets it is the only one to replay and to move next_tile_.
  std::atomic<bool> replaying_{false};
  std::atomic<size_t> next_tile_{0};  // the first tile not replayed
  RegionTable regions_;
  uint64_t accesses_ = 0, misses_ = 0;  // written under the token
};

}  // namespace ontile
