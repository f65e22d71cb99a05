// Proves the texture-cache model's counts equal a plain LRU written here from the definition
// (texture_cache.h: line = granule / (line_bytes / 64), set = line % sets, regions placed in
// first-use order), for long random and sampler-recorded traces, several textures, set
// conflicts, non-power-of-two set counts, and the replay at several thread counts.
#include "memory/texture_cache.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tbb/task_arena.h>

#include "raster/texel_trace.h"
#include "raster/texture.h"
#include "memory/texture_replay_stream.h"
#include "memory/granule_buffer_pool.h"
#include "memory/trace_repeats.h"
#include "util/parallel_for.h"
#include "tiler/reference_lru.h"

namespace ontile {
namespace {

TextureCacheConfig config(uint32_t sets, uint32_t line_bytes, uint32_t ways) {
  return TextureCacheConfig{sets * line_bytes * ways, line_bytes, ways};
}

// Power-of-two and other set counts, 1 to 16 ways, 64- to 256-byte lines.
std::vector<TextureCacheConfig> configs() {
  return {config(256, 64, 16), config(16, 64, 16), config(48, 64, 16), config(3, 64, 4),
          config(5, 128, 2),   config(7, 64, 3),   config(1, 64, 16),  config(1, 64, 1),
          config(64, 256, 1),  config(100, 64, 8)};
}

std::string name_of(const TextureCacheConfig& c) {
  return std::to_string(c.size_bytes / (c.line_bytes * c.ways)) + " sets x " +
         std::to_string(c.ways) + " ways x " + std::to_string(c.line_bytes) + " B";
}

std::shared_ptr<const Texture2D> texture(int width, int height) {
  return Texture2D::from_rgba8(width, height,
                               std::vector<uint8_t>(static_cast<size_t>(width) * height * 4, 128),
                               false, "lru");
}

// The textures the traces read: several sizes, so regions differ in reserved size.
const std::vector<std::shared_ptr<const Texture2D>>& textures() {
  static const std::vector<std::shared_ptr<const Texture2D>> all = {
      texture(256, 256), texture(64, 32), texture(512, 128), texture(17, 9), texture(128, 128)};
  return all;
}

// Random granules: texels of random textures, raw (region 0) granules, recent granules again,
// and 40 lines 2^16 granules apart, which share one set in every power-of-two configuration
// (and spread over a few sets in the others).
std::vector<std::vector<uint64_t>> random_tiles(uint64_t seed, int tile_count) {
  std::mt19937_64 rng(seed);
  std::vector<std::vector<uint64_t>> tiles(tile_count);
  for (auto& tile : tiles) {
    const int length = static_cast<int>(rng() % 700);  // some tiles empty
    for (int i = 0; i < length; ++i) {
      const uint64_t kind = rng() % 10;
      const Texture2D& t = *textures()[rng() % textures().size()];
      uint64_t g;
      if (kind < 5) {  // any texel of any level
        const int level = static_cast<int>(rng() % t.level_count());
        g = t.texel_address(level, static_cast<int>(rng() % t.width(level)),
                            static_cast<int>(rng() % t.height(level))) / 64;
      } else if (kind < 7 && !tile.empty()) {  // a recent granule again
        g = tile[tile.size() - 1 - rng() % std::min<size_t>(tile.size(), 40)];
      } else if (kind < 9) {  // set conflicts: one of 40 lines 2^16 granules apart
        g = t.base_address() / 64 + (rng() % 40) * (uint64_t{1} << 16);
      } else {  // region 0: used as they are
        g = rng() % 100000;
      }
      if (tile.empty() || tile.back() != g) tile.push_back(g);  // as the recorder merges
    }
  }
  return tiles;
}

// Traces recorded by the real samplers: each 16x16 tile of a 256x128 screen shades its quads
// with bilinear/trilinear lookups of 3 textures (as a material shader interleaves them), each
// with its own uv scale, so the levels and footprints vary across the screen.
std::vector<std::vector<uint64_t>> sampled_tiles() {
  constexpr int kTile = 16, kWidth = 256, kHeight = 128;
  std::vector<std::vector<uint64_t>> tiles;
  SamplerDesc sampler;  // linear, linear mips, repeat
  const float scales[3] = {0.7f, 3.1f, 11.0f};
  const int ids[3] = {0, 2, 4};
  for (int ty = 0; ty < kHeight; ty += kTile) {
    for (int tx = 0; tx < kWidth; tx += kTile) {
      std::vector<uint64_t> granules;
      {
        const TexelTraceScope scope(&granules);
        for (int y = ty; y < ty + kTile; y += 2) {
          for (int x = tx; x < tx + kTile; x += 2) {
            for (int k = 0; k < 3; ++k) {
              glm::vec2 uv[4];
              for (int lane = 0; lane < 4; ++lane) {
                const float px = static_cast<float>(x + (lane & 1)) + 0.5f;
                const float py = static_cast<float>(y + (lane >> 1)) + 0.5f;
                const float s = scales[k] * (1.0f + px / kWidth);  // minification grows
                uv[lane] = glm::vec2(px * s / kWidth + 0.1f * py / kHeight, py * s / kHeight);
              }
              glm::vec4 out[4];
              textures()[ids[k]]->sample_quad(sampler, uv, out);
            }
          }
        }
      }
      tiles.push_back(std::move(granules));
    }
  }
  return tiles;
}

// One trace per tile, each tile's granules in a vector of its own (as tiles record them).
std::vector<TileTrace> traces_of(const std::vector<std::vector<uint64_t>>& tiles) {
  std::vector<TileTrace> traces(tiles.size());
  for (size_t t = 0; t < tiles.size(); ++t) traces[t].texture_granules = tiles[t];
  return traces;
}

TextureTraffic replay_with_threads(TextureCache& cache, const std::vector<TileTrace>& traces,
                                   int threads, TextureReplayDetail* detail = nullptr) {
  tbb::task_arena arena(threads);
  return arena.execute([&] { return replay_texture_traces(cache, traces, detail); });
}

// The replay streamed as a pass runs it: `threads` workers report the tiles recorded in a
// shuffled order (tiles complete out of order), then finish() replays what is left.
TextureTraffic replay_streamed(TextureCache& cache, const std::vector<TileTrace>& traces,
                               int threads, uint64_t seed, TextureReplayDetail& detail) {
  std::vector<size_t> order(traces.size());
  for (size_t t = 0; t < order.size(); ++t) order[t] = t;
  std::mt19937_64 rng(seed);
  // Mostly in order with local swaps, as tiles taken in index order complete, and a few far moves.
  for (size_t t = 0; t + 1 < order.size(); ++t) {
    const size_t reach = rng() % 16 == 0 ? order.size() - t : 4;
    std::swap(order[t], order[t + rng() % std::min(reach, order.size() - t)]);
  }
  tbb::task_arena arena(threads);
  return arena.execute([&] {
    TextureReplayStream stream(cache, traces, detail);
    ontile::parallel_for(size_t{0}, order.size(), [&](size_t i) { stream.tile_recorded(order[i]); });
    return stream.finish();
  });
}

void expect_equal(const TextureTraffic& a, const TextureTraffic& b, const std::string& what) {
  EXPECT_EQ(a.accesses, b.accesses) << what;
  EXPECT_EQ(a.hits, b.hits) << what;
  EXPECT_EQ(a.misses, b.misses) << what;
  EXPECT_EQ(a.bytes_read, b.bytes_read) << what;
}

void expect_equal(const TextureReplayDetail& a, const TextureReplayDetail& b,
                  const std::string& what) {
  EXPECT_EQ(a.misses_per_tile, b.misses_per_tile) << what;
  EXPECT_EQ(a.misses_per_region, b.misses_per_region) << what;
}

// Replays two frames' worth of passes (the second pass continues the first one's cache state)
// at each thread count, against the reference: totals, misses per tile and per region.
void expect_replay_matches_reference(const std::vector<std::vector<uint64_t>>& first,
                                     const std::vector<std::vector<uint64_t>>& second) {
  const std::vector<TileTrace> a = traces_of(first), b = traces_of(second);
  for (const TextureCacheConfig& c : configs()) {
    ReferenceLru reference(c);
    TextureReplayDetail expected_detail_a, expected_detail_b;
    const TextureTraffic expected_a = reference.replay(first, c.line_bytes, &expected_detail_a);
    const TextureTraffic expected_b = reference.replay(second, c.line_bytes, &expected_detail_b);
    // Both outcomes occur (but a cache of one line never hits: repeats are merged when traced).
    if (c.size_bytes > c.line_bytes) {
      ASSERT_GT(expected_a.hits, 0u) << name_of(c);
    }
    ASSERT_GT(expected_a.misses, 0u) << name_of(c);
    for (int threads : {1, 2, 3, 7}) {
      TextureCache cache(c);
      const std::string what = name_of(c) + ", " + std::to_string(threads) + " threads";
      TextureReplayDetail detail_a, detail_b;
      expect_equal(replay_with_threads(cache, a, threads, &detail_a), expected_a,
                   what + ", pass 1");
      expect_equal(detail_a, expected_detail_a, what + ", pass 1");
      expect_equal(replay_with_threads(cache, b, threads, &detail_b), expected_b,
                   what + ", pass 2");
      expect_equal(detail_b, expected_detail_b, what + ", pass 2");
      TextureCache streamed_cache(c);
      TextureReplayDetail streamed_a, streamed_b;
      expect_equal(replay_streamed(streamed_cache, a, threads, threads, streamed_a), expected_a,
                   what + ", streamed pass 1");
      expect_equal(streamed_a, expected_detail_a, what + ", streamed pass 1");
      expect_equal(replay_streamed(streamed_cache, b, threads, threads + 100, streamed_b), expected_b,
                   what + ", streamed pass 2");
      expect_equal(streamed_b, expected_detail_b, what + ", streamed pass 2");
    }
  }
}

TEST(TextureCacheLru, EveryAccessHitsOrMissesAsThePlainLru) {
  for (const TextureCacheConfig& c : configs()) {
    std::mt19937_64 rng(c.size_bytes * 31 + c.ways);
    TextureCache cache(c);
    ReferenceLru reference(c);
    const uint64_t sets = c.size_bytes / (c.line_bytes * c.ways);
    const uint64_t granules_per_line = c.line_bytes / 64;
    uint64_t hits = 0;
    for (int i = 0; i < 200000; ++i) {
      // Lines from a pool a little larger than the cache, crowding a few sets.
      const uint64_t line = rng() % 4 == 0 ? (rng() % 3) + sets * (rng() % (2 * c.ways + 2))
                                           : rng() % (sets * c.ways * 5 / 4 + 3);
      const uint64_t granule = line * granules_per_line + rng() % granules_per_line;
      const bool expected = reference.access(granule);
      ASSERT_EQ(cache.access(granule), expected) << name_of(c) << ", access " << i;
      hits += expected;
    }
    EXPECT_GT(hits, 1000u) << name_of(c);
    EXPECT_LT(hits, 199000u) << name_of(c);
  }
}

TEST(TextureCacheLru, RandomTracesReplayAsThePlainLruAtAnyThreadCount) {
  expect_replay_matches_reference(random_tiles(1, 300), random_tiles(2, 200));
}

TEST(TextureCacheLru, SampledTracesReplayAsThePlainLruAtAnyThreadCount) {
  const std::vector<std::vector<uint64_t>> tiles = sampled_tiles();
  size_t granules = 0;
  for (const auto& tile : tiles) granules += tile.size();
  ASSERT_GT(granules, 50000u);
  // The second pass reads the same textures again, partly from the cache.
  expect_replay_matches_reference(
      tiles, std::vector<std::vector<uint64_t>>(tiles.rbegin(), tiles.rend()));
}

// Tiles with repeat entries (memory/trace_repeats.h): after a random granule, now and then the
// last 2 to 24 granules of the tile again 1 to 6 times, so the parallel replay's set groups
// split windows (a group may keep one granule of a window, or none).
TEST(TextureCacheLru, TracesWithRepeatEntriesReplayAsThePlainLruAtAnyThreadCount) {
  std::mt19937_64 rng(5);
  const auto folded = [&](std::vector<std::vector<uint64_t>> tiles) {
    for (std::vector<uint64_t>& tile : tiles) {
      std::vector<uint64_t> out;
      size_t since_repeat = 0;
      for (const uint64_t g : tile) {
        out.push_back(g);
        if (++since_repeat >= 2 && rng() % 5 == 0) {
          const size_t window = 2 + rng() % std::min<size_t>(since_repeat - 1, 23);
          out.push_back(trace_repeat(static_cast<uint32_t>(window), static_cast<uint32_t>(1 + rng() % 6)));
          since_repeat = 0;
        }
      }
      tile = std::move(out);
    }
    return tiles;
  };
  expect_replay_matches_reference(folded(random_tiles(3, 200)), folded(random_tiles(4, 100)));
}

TEST(GranuleBufferPool, GivenBackBuffersComeBackEmptyWithTheirCapacity) {
  std::vector<uint64_t> held = take_granule_buffer();
  held.assign(10, 5);
  std::vector<uint64_t> given = take_granule_buffer();
  given.assign(1000, 7);
  const uint64_t* memory = given.data();
  give_back_granule_buffer(given);
  EXPECT_EQ(given.capacity(), 0u);  // the pool holds its memory now
  const std::vector<uint64_t> again = take_granule_buffer();  // the last one given back
  EXPECT_TRUE(again.empty());
  EXPECT_GE(again.capacity(), 1000u);
  EXPECT_EQ(again.data(), memory);
  EXPECT_EQ(held, std::vector<uint64_t>(10, 5));  // a buffer still taken is never handed out
}

// The replay of a pass gives every tile's buffer back, replayed in streaming or in finish().
TEST(GranuleBufferPool, AStreamedReplayGivesEveryTileBufferBack) {
  const std::vector<std::vector<uint64_t>> tiles = random_tiles(3, 40);
  for (int threads : {1, 2, 7}) {
    std::vector<TileTrace> traces = traces_of(tiles);
    TextureCache cache(config(64, 64, 4));
    TextureReplayDetail detail;
    tbb::task_arena arena(threads);
    const TextureTraffic traffic = arena.execute([&] {
      TextureReplayStream stream(cache, traces, detail, TextureReplayStream::GiveBackBuffers{});
      ontile::parallel_for(size_t{0}, traces.size(), [&](size_t t) { stream.tile_recorded(t); });
      return stream.finish();
    });
    TextureCache reference_cache(config(64, 64, 4));
    const std::vector<TileTrace> kept = traces_of(tiles);
    expect_equal(traffic, replay_texture_traces(reference_cache, kept), std::to_string(threads) + " threads");
    for (const TileTrace& trace : traces) EXPECT_EQ(trace.texture_granules.capacity(), 0u);
  }
}

}  // namespace
}  // namespace ontile
