// Proves the texture-cache counts of real frames (accesses, hits, misses, bytes) equal a plain
// serial replay written from the model's definition (reference_lru.h: every traced granule of
// every tile, tiles in index order, one list-LRU access each): every pipeline, on the demo scene
// and a small generated atrium, at 1, 2, 6 and 7 threads (the replay is parallel from 6), and with
// cache shapes whose set counts are not powers of two or whose lines are wider than 64 bytes
// (which the parallel replay splits into fewer groups or not at all).
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

#include "pipelines/kit/render_frame.h"
#include "scene/gen/scene_generator.h"
#include "scene/gltf_loader.h"
#include "support/generated_scene.h"
#include "tiler/reference_lru.h"
#include "memory/texture_replay_observer.h"

namespace ontile {
namespace {

// Replays every pass's traces through a ReferenceLru of its own (one per frame cache, carried
// from pass to pass as the model's state is) and compares the model's counts with it.
class ReferenceReplay : public TextureReplayObserver {
 public:
  void before_replay(const TextureCache& cache) override {
    // A cache whose ways are all empty holds no state (no placed region either: placing one
    // needs an access): a new frame's, whose reference starts afresh.
    const SetArray& sets = cache.sets();
    bool empty = true;
    for (size_t i = 0; i < size_t{sets.sets} * sets.ways; ++i) empty = empty && sets.tags[i] == ~0ull;
    auto it = references_.find(&cache);
    if (empty || it == references_.end()) {
      references_.erase(&cache);
      it = references_.emplace(&cache, ReferenceLru(cache.config())).first;
    }
  }
  void after_replay(const TextureCache& cache, const std::vector<TileTrace>& traces,
                    const TextureTraffic& traffic) override {
    std::vector<std::span<const uint64_t>> tiles;
    for (const TileTrace& trace : traces) tiles.push_back(trace.texture_granules);
    const TextureTraffic expected = references_.at(&cache).replay(tiles, cache.config().line_bytes);
    EXPECT_EQ(traffic.accesses, expected.accesses) << what;
    EXPECT_EQ(traffic.hits, expected.hits) << what;
    EXPECT_EQ(traffic.misses, expected.misses) << what;
    EXPECT_EQ(traffic.bytes_read, expected.bytes_read) << what;
    ++passes_compared;
    accesses_compared += traffic.accesses;
  }

  std::string what;
  int passes_compared = 0;
  uint64_t accesses_compared = 0;

 private:
  std::map<const TextureCache*, ReferenceLru> references_;
};

struct ObserverInstalled {
  explicit ObserverInstalled(TextureReplayObserver* o) { set_texture_replay_observer(o); }
  ~ObserverInstalled() { set_texture_replay_observer(nullptr); }
};

using test::generated_scene;

const char* const kPipelines[] = {"lambert", "forward",           "deferred-subpass",
                                  "deferred-classic", "cartoon", "cartoon-multipass",
                                  "cartoon-hull", "universal"};

TextureCacheConfig cache_of(uint32_t sets, uint32_t line_bytes, uint32_t ways) {
  return TextureCacheConfig{sets * line_bytes * ways, line_bytes, ways};
}

// Renders every pipeline at each thread count with `cache`; returns the texture accesses compared.
uint64_t check_every_pipeline(const Scene& scene, const std::string& scene_name,
                              const TextureCacheConfig& cache, const std::vector<int>& threads) {
  ReferenceReplay reference;
  const ObserverInstalled installed(&reference);
  for (const char* pipeline : kPipelines) {
    for (const int thread_count : threads) {
      RenderSettings settings;
      settings.pipeline = pipeline;
      settings.width_px = 200;
      settings.height_px = 120;
      settings.context.threads = thread_count;
      settings.context.tiler.texture_cache = cache;
      reference.what = scene_name + ", " + pipeline + ", " + std::to_string(thread_count) +
                       " threads, " + std::to_string(cache.line_bytes) + " B lines";
      const int passes_before = reference.passes_compared;
      render_frame(scene, settings);
      EXPECT_GT(reference.passes_compared, passes_before) << reference.what;
    }
  }
  return reference.accesses_compared;
}

TEST(TextureReplayPipelines, DemoCountsEqualTheSerialReferenceOnEveryPipeline) {
  const Scene scene = generated_scene("demo", 1.0);
  EXPECT_GT(check_every_pipeline(scene, "demo", TextureCacheConfig{}, {1, 2, 7}), 100000u);
}

TEST(TextureReplayPipelines, AtriumCountsEqualTheSerialReferenceOnEveryPipeline) {
  const Scene scene = generated_scene("atrium", 0.1);
  EXPECT_GT(check_every_pipeline(scene, "atrium", TextureCacheConfig{}, {1, 2, 6}), 100000u);
}

TEST(TextureReplayPipelines, OtherCacheShapesCountAsTheSerialReference) {
  const Scene scene = generated_scene("demo", 1.0);
  // 48 sets (not a power of two), 128-byte lines (fewer placement-independent group bits),
  // 4 KiB lines (none) and 8 KiB lines (wider than the placement alignment), 1 way.
  for (const TextureCacheConfig& cache :
       {cache_of(48, 64, 16), cache_of(128, 128, 8), cache_of(16, 4096, 4), cache_of(8, 8192, 2),
        cache_of(512, 64, 1)}) {
    EXPECT_GT(check_every_pipeline(scene, "demo", cache, {1, 7}), 100000u);
  }
}

}  // namespace
}  // namespace ontile
