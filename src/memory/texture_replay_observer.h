// A test seam of the texture-cache replay: an observer that sees the cache before a pass's replay
// starts (TextureReplayStream: while the tiles still run) and every trace of the pass with the
// counts after it, so tests can check the counts against a replay of their own
// (tests/tiler/texture_replay_pipelines_test.cpp).
#pragma once
#include <vector>

#include "memory/texture_cache.h"

namespace ontile {

class TextureReplayObserver {
 public:
  virtual ~TextureReplayObserver() = default;
  // Called by the replaying thread; passes of different contexts may replay at the same time.
  virtual void before_replay(const TextureCache& cache) = 0;
  virtual void after_replay(const TextureCache& cache, const std::vector<TileTrace>& traces,
                            const TextureTraffic& traffic) = 0;
};

// Installs `observer` (nullptr: none) for every later replay; the caller keeps it alive until it
// is replaced. Not to be called while a pass is replaying.
void set_texture_replay_observer(TextureReplayObserver* observer);

}  // namespace ontile
