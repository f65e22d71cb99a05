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

// Counts, misses per tile and per region are those of replay_texture_traces (the same serial
// replay in tile order, or the parallel one by set groups, which needs every tile and runs in
// finish()). `traces` and `detail` must outlive the stream; `traces` is sized before, filled while
// the tiles run.
//
// Tiles append to their thread's trace buffer (tiler/trace_buffers.h), which may move its storage
// whenever it grows, so a tile's granules are read only by the thread whose buffer holds them,
// between its tiles (tile_recorded), or after every tile ran (finish). The replay itself is
// serial: one thread at a time (a flag; a thread that finds it taken goes back to its tiles).
class TextureReplayStream {
 public:
  TextureReplayStream(TextureCache& cache, const std::vector<TileTrace>& traces,
                      TextureReplayDetail& detail);
  ~TextureReplayStream();
  TextureReplayStream(const TextureReplayStream&) = delete;
  TextureReplayStream& operator=(const TextureReplayStream&) = delete;

  // Tile `tile`'s trace is complete; called by the thread that recorded it into `thread_buffer`,
  // before it starts another tile. Replays the recorded tiles from the first one not replayed yet
  // while they are in `thread_buffer` (or have no granules).
  void tile_recorded(size_t tile, const std::vector<uint64_t>& thread_buffer);
  // Every tile was recorded (and every tile_recorded call returned): replays the rest.
  TextureTraffic finish();

 private:
  void replay_tile(size_t tile);

  TextureCache& cache_;
  const std::vector<TileTrace>& traces_;
  TextureReplayDetail& detail_;
  TextureReplayObserver* const observer_;
  const bool streamed_;  // false: replayed in finish(), in parallel by set groups
  const int threads_;
  std::unique_ptr<std::atomic<bool>[]> recorded_;
  std::atomic<bool> replaying_{false};
  size_t next_tile_ = 0;  // the first tile not replayed; read and written under replaying_
  RegionTable regions_;
  uint64_t accesses_ = 0, misses_ = 0;
};

}  // namespace ontile
