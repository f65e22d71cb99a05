// Tests for the texture-traffic model: exact hits/misses of the set-associative LRU cache,
// config validation, the texel addresses Texture2D reports while sampling, and an end-to-end
// textured full-screen quad whose texture traffic is known exactly at any thread count.
#include "memory/texture_cache.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "raster/texel_trace.h"
#include "raster/texture.h"
#include "support/raster_harness.h"
#include "support/textured_quad.h"
#include "util/error.h"

namespace ontile {
namespace {

TextureCacheConfig cache_config(uint32_t size_bytes, uint32_t line_bytes, uint32_t ways) {
  TextureCacheConfig c;
  c.size_bytes = size_bytes;
  c.line_bytes = line_bytes;
  c.ways = ways;
  return c;
}

// One TileTrace per granule list.
std::vector<TileTrace> traces_of(const std::vector<std::vector<uint64_t>>& tiles) {
  std::vector<TileTrace> traces(tiles.size());
  for (size_t t = 0; t < tiles.size(); ++t) traces[t].texture_granules = tiles[t];
  return traces;
}

// Hit (true) or miss (false) of each access, in order.
std::vector<bool> access_all(TextureCache& cache, const std::vector<uint64_t>& granules) {
  std::vector<bool> hits;
  for (uint64_t g : granules) hits.push_back(cache.access(g));
  return hits;
}

TEST(TextureCache, ColdMissesThenAllHitsWhenTheWorkingSetFits) {
  TextureCache cache(TextureCacheConfig{});  // 256 KiB, 64-byte lines, 16 ways: 4096 lines
  std::vector<std::vector<uint64_t>> granules(1);
  for (uint64_t g = 0; g < 4096; ++g) granules[0].push_back(1000 + g);
  const std::vector<TileTrace> traces = traces_of(granules);
  const TextureTraffic first = replay_texture_traces(cache, traces);
  EXPECT_EQ(first.accesses, 4096u);
  EXPECT_EQ(first.hits, 0u);
  EXPECT_EQ(first.misses, 4096u);
  EXPECT_EQ(first.bytes_read, 4096u * 64u);
  const TextureTraffic second = replay_texture_traces(cache, traces);  // state carries over
  EXPECT_EQ(second.accesses, 4096u);
  EXPECT_EQ(second.hits, 4096u);
  EXPECT_EQ(second.misses, 0u);
  EXPECT_EQ(second.bytes_read, 0u);
}

TEST(TextureCache, OneMoreLinePerSetThanWaysThrashesUnderLru) {
  // 2 sets x 2 ways; lines 0, 2, 4 all map to set 0. Cycling through 3 lines in a 2-way LRU
  // set misses every time.
  TextureCache cache(cache_config(256, 64, 2));
  const std::vector<bool> hits = access_all(cache, {0, 2, 4, 0, 2, 4});
  EXPECT_EQ(hits, std::vector<bool>(6, false));
}

TEST(TextureCache, LruEvictsTheLeastRecentlyUsedWayInExactOrder) {
  TextureCache cache(cache_config(256, 64, 2));  // 2 sets x 2 ways
  // A=0, B=2, C=4 conflict in set 0; line 1 lives in set 1 and must never be disturbed.
  const std::vector<uint64_t> stream = {0, 2, 1, 0, 4, 2, 0, 0, 4, 2, 1};
  const std::vector<bool> expected = {
      false,  // A cold
      false,  // B cold
      false,  // line 1 cold (set 1)
      true,   // A hit; B is now LRU
      false,  // C evicts B (set 0: A, C)
      false,  // B evicts A, the LRU (set 0: B, C)
      false,  // A evicts C (set 0: A, B)
      true,   // A hit
      false,  // C evicts B (set 0: A, C)
      false,  // B evicts A (set 0: B, C)
      true,   // line 1 still in set 1
  };
  EXPECT_EQ(access_all(cache, stream), expected);
}

TEST(TextureCache, WideLinesHoldSeveralGranulesAndReplayCountsLineBytes) {
  // 128-byte lines: granules 2k and 2k+1 share line k. 1 set x 4 ways.
  TextureCache cache(cache_config(512, 128, 4));
  const std::vector<std::vector<uint64_t>> granules = {
      {0, 1, 2, 3},  // lines 0, 0, 1, 1
      {5, 4, 0},     // lines 2, 2, 0
  };
  const TextureTraffic t = replay_texture_traces(cache, traces_of(granules));
  EXPECT_EQ(t.accesses, 7u);
  EXPECT_EQ(t.misses, 3u);
  EXPECT_EQ(t.hits, 4u);
  EXPECT_EQ(t.bytes_read, 3u * 128u);
}

TEST(TextureCache, ReplayVisitsTilesInIndexOrder) {
  // 1 set x 1 way: tile 0 leaves line 7 resident, so tile 1's first access hits.
  TextureCache cache(cache_config(64, 64, 1));
  const std::vector<std::vector<uint64_t>> granules = {{3, 7}, {7, 3}};
  const TextureTraffic t = replay_texture_traces(cache, traces_of(granules));
  EXPECT_EQ(t.hits, 1u);
  EXPECT_EQ(t.misses, 3u);
}

TEST(TextureTraffic, AddSumsEveryCounter) {
  TextureTraffic a{1, 2, 3, 4};
  a.add(TextureTraffic{10, 20, 30, 40});
  EXPECT_EQ(a.accesses, 11u);
  EXPECT_EQ(a.hits, 22u);
  EXPECT_EQ(a.misses, 33u);
  EXPECT_EQ(a.bytes_read, 44u);
}

// Constructs the cache and returns the Error message ("" if none was thrown).
std::string config_error(const TextureCacheConfig& config) {
  try {
    TextureCache cache(config);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(TextureCache, RejectsInvalidConfigsNamingTheField) {
  EXPECT_EQ(config_error(cache_config(256 * 1024, 64, 16)), "");
  EXPECT_EQ(config_error(cache_config(3 * 128, 128, 1)), "");  // 3 sets: need not be 2^n
  EXPECT_NE(config_error(cache_config(4096, 32, 1)).find("line_bytes 32"), std::string::npos);
  EXPECT_NE(config_error(cache_config(96 * 4, 96, 1)).find("line_bytes 96"), std::string::npos);
  EXPECT_NE(config_error(cache_config(4096, 64, 0)).find("ways"), std::string::npos);
  EXPECT_NE(config_error(cache_config(1000, 64, 2)).find("size_bytes 1000"), std::string::npos);
  EXPECT_NE(config_error(cache_config(0, 64, 2)).find("size_bytes 0"), std::string::npos);
}

// ---- Texture2D addresses and the texel trace ----

// width x height RGBA8 texture with distinct texels.
std::shared_ptr<const Texture2D> rgba8_texture(int width, int height) {
  std::vector<uint8_t> rgba;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      rgba.insert(rgba.end(), {uint8_t(x), uint8_t(y), uint8_t(x ^ y), 255});
    }
  }
  return Texture2D::from_rgba8(width, height, std::move(rgba), false, "trace");
}

SamplerDesc sampler_of(FilterMode filter, MipmapMode mip) {
  SamplerDesc s;
  s.mag_filter = s.min_filter = filter;
  s.mipmap_mode = mip;
  return s;
}

uint64_t granule_of(const Texture2D& t, int level, int x, int y) {
  return t.texel_address(level, x, y) / 64;
}

TEST(TextureAddresses, EachTextureOwnsARegionAndReservesItsMipChain) {
  const auto a = rgba8_texture(64, 64);
  const auto b = rgba8_texture(3, 5);
  const auto c = rgba8_texture(8, 8);
  EXPECT_EQ(a->base_address() % 4096, 0u);
  EXPECT_EQ(a->memory_bytes_per_texel(), 4);
  EXPECT_EQ(a->level_offset_bytes(0), 0u);
  EXPECT_EQ(a->level_offset_bytes(1), 64u * 64 * 4);
  EXPECT_EQ(a->level_offset_bytes(2), 64u * 64 * 4 + 32 * 32 * 4);
  const uint64_t id_a = a->base_address() >> Texture2D::kTextureIdShift;
  EXPECT_EQ(b->base_address() >> Texture2D::kTextureIdShift, id_a + 1) << "ids in creation order";
  EXPECT_EQ(c->base_address() >> Texture2D::kTextureIdShift, id_a + 2);
  // 64x64 chain: 4 * (4096 + 1024 + 256 + 64 + 16 + 4 + 1) = 21844 bytes -> 6 pages.
  EXPECT_EQ(Texture2D::reserved_bytes_of(id_a), 6u * 4096);
  EXPECT_EQ(Texture2D::reserved_bytes_of(id_a + 1), 4096u);  // 3x5 chain fits one page
  EXPECT_EQ(a->texel_address(1, 3, 2), a->base_address() + 64 * 64 * 4 + (2 * 32 + 3) * 4);
  const auto f = Texture2D::from_rgba32f(2, 2, std::vector<float>(16, 0.0f), "f");
  EXPECT_EQ(f->memory_bytes_per_texel(), 16);
  EXPECT_EQ(f->texel_address(0, 1, 1), f->base_address() + 3 * 16);
}

TEST(TextureAddresses, FramePlacementFollowsFirstUseNotCreationOrder) {
  // Textures used in the order c, a: c lands first in the frame, a right after c's reserve.
  const auto a = rgba8_texture(64, 64);
  const auto c = rgba8_texture(8, 8);
  TextureCache cache(TextureCacheConfig{});
  const uint64_t c0 = cache.frame_granule(granule_of(*c, 0, 0, 0));
  const uint64_t a0 = cache.frame_granule(granule_of(*a, 0, 0, 0));
  EXPECT_EQ(a0, c0 + 4096 / 64);
  EXPECT_EQ(cache.frame_granule(granule_of(*a, 0, 16, 0)), a0 + 1);
  EXPECT_EQ(cache.frame_granule(granule_of(*c, 0, 0, 0)), c0) << "stable within the frame";
  // A fresh frame (cache) placing a first gives a the same address c had.
  TextureCache next(TextureCacheConfig{});
  EXPECT_EQ(next.frame_granule(granule_of(*a, 0, 0, 0)), c0);
  EXPECT_EQ(next.frame_granule(1000), 1000u) << "raw granules (no texture) pass through";
}

TEST(TextureTrace, NearestSampleAtATexelCentreRecordsOneGranule) {
  const auto t = rgba8_texture(64, 64);
  std::vector<uint64_t> granules;
  {
    const TexelTraceScope scope(&granules);
    t->sample_lod(sampler_of(FilterMode::Nearest, MipmapMode::None),
                  glm::vec2((37 + 0.5f) / 64, (9 + 0.5f) / 64), 0.0f);
  }
  const uint64_t expected = (t->base_address() + (9 * 64 + 37) * 4) / 64;
  EXPECT_EQ(granules, std::vector<uint64_t>{expected});
}

TEST(TextureTrace, NoScopeRecordsNothing) {
  const auto t = rgba8_texture(8, 8);
  std::vector<uint64_t> granules;
  { const TexelTraceScope scope(&granules); }
  t->fetch(0, 1, 1);  // outside the scope
  EXPECT_TRUE(granules.empty());
}

TEST(TextureTrace, BilinearReadsFourTexelsInLoadOrder) {
  const auto t = rgba8_texture(64, 64);
  const SamplerDesc bilinear = sampler_of(FilterMode::Linear, MipmapMode::None);
  // Between texels 15 and 16 (different granules: 16 RGBA8 texels per 64 bytes), rows 20-21.
  std::vector<uint64_t> across;
  {
    const TexelTraceScope scope(&across);
    t->sample_lod(bilinear, glm::vec2(16.0f / 64, 21.0f / 64), 0.0f);
  }
  EXPECT_EQ(across, (std::vector<uint64_t>{granule_of(*t, 0, 15, 20), granule_of(*t, 0, 16, 20),
                                           granule_of(*t, 0, 15, 21), granule_of(*t, 0, 16, 21)}));
  EXPECT_EQ(granule_of(*t, 0, 16, 20), granule_of(*t, 0, 15, 20) + 1);
  EXPECT_EQ(granule_of(*t, 0, 15, 21), granule_of(*t, 0, 15, 20) + 4);  // 256-byte rows
  // Between texels 5 and 6 (same granule): the repeat in each row is merged.
  std::vector<uint64_t> within;
  {
    const TexelTraceScope scope(&within);
    t->sample_lod(bilinear, glm::vec2(6.0f / 64, 21.0f / 64), 0.0f);
  }
  EXPECT_EQ(within, (std::vector<uint64_t>{granule_of(*t, 0, 5, 20), granule_of(*t, 0, 5, 21)}));
}

TEST(TextureTrace, TrilinearReadsTwoLevels) {
  const auto t = rgba8_texture(64, 64);
  std::vector<uint64_t> granules;
  {
    const TexelTraceScope scope(&granules);
    // lod 0.5 blends levels 0 and 1. uv = (0.5, 0.5) sits between texels 31|32 of level 0
    // and 15|16 of level 1: both pairs straddle a granule boundary, so all 8 reads are distinct.
    t->sample_lod(sampler_of(FilterMode::Linear, MipmapMode::Linear), glm::vec2(0.5f, 0.5f),
                  0.5f);
  }
  EXPECT_EQ(granules, (std::vector<uint64_t>{
                          granule_of(*t, 0, 31, 31), granule_of(*t, 0, 32, 31),
                          granule_of(*t, 0, 31, 32), granule_of(*t, 0, 32, 32),
                          granule_of(*t, 1, 15, 15), granule_of(*t, 1, 16, 15),
                          granule_of(*t, 1, 15, 16), granule_of(*t, 1, 16, 16)}));
  EXPECT_GE(granule_of(*t, 1, 15, 15) * 64, t->base_address() + t->level_offset_bytes(1));
}

TEST(TextureTrace, SurfaceSnapshotUsesTheTargetsBytesPerTexelAndOneLevel) {
  const auto t = Texture2D::from_surface_texels(32, 4, std::vector<float>(32 * 4 * 4, 0.5f), 4,
                                                "gbuffer.albedo");
  EXPECT_EQ(t->level_count(), 1);
  EXPECT_EQ(t->bytes_per_texel(), 16);         // stored as float here
  EXPECT_EQ(t->memory_bytes_per_texel(), 4);   // counted as RGBA8 in memory
  EXPECT_EQ(t->base_address() % 4096, 0u);
  EXPECT_EQ(granule_of(*t, 0, 16, 0), granule_of(*t, 0, 0, 0) + 1);
  EXPECT_EQ(granule_of(*t, 0, 15, 0), granule_of(*t, 0, 0, 0));
  std::vector<uint64_t> granules;
  {
    const TexelTraceScope scope(&granules);
    t->fetch(0, 0, 0);
    t->fetch(0, 16, 0);
    // A mip mode with a large LOD still reads level 0, the only level.
    t->sample_lod(sampler_of(FilterMode::Nearest, MipmapMode::Linear),
                  glm::vec2(0.5f / 32, 2.5f / 4), 3.0f);
  }
  EXPECT_EQ(granules, (std::vector<uint64_t>{t->base_address() / 64, t->base_address() / 64 + 1,
                                             t->base_address() / 64 + 4}));
  EXPECT_THROW(Texture2D::from_surface_texels(2, 2, std::vector<float>(16), 0, "bad"), Error);
}

// ---- End to end: a textured full-screen quad ----

TEST(TextureTrafficEndToEnd, OneTexelPerPixelFetchesEveryLineExactlyOnce) {
  // A 16x16 tile reads 16 rows x 16 texels = 16 lines (16 RGBA8 texels per 64-byte line, rows
  // 1 KiB apart, texture 4 KiB aligned); no two tiles share a line, and a tile's 16 lines fall
  // in 16 distinct sets (line stride 16, 256 sets), so nothing is evicted before its last use:
  // every line of level 0 misses exactly once, and every other access hits.
  constexpr int kSize = 256;
  const auto texture = rgba8_texture(kSize, kSize);
  const test::TexturedQuadResult one = test::draw_textured_quad(texture, kSize, 1);
  for (int y = 0; y < kSize; y += 17) {
    for (int x = 0; x < kSize; x += 13) {
      const glm::vec4 expected = texture->fetch(0, x, y);  // outside any trace scope
      EXPECT_EQ(one.pixels[static_cast<size_t>(y) * kSize + x], expected) << x << "," << y;
    }
  }
  EXPECT_EQ(one.texture.bytes_read, uint64_t{kSize} * kSize * 4);
  EXPECT_EQ(one.texture.misses * 64, one.texture.bytes_read);
  // Accesses: a quad's lanes (even x) share a granule per row and sample_quad reads all 4
  // lanes, so each shaded quad records row y then row y + 1: 2 accesses. Quads with i + j = 127
  // straddle the diagonal x + y = 256 and are shaded once per triangle: 128 extra quads.
  EXPECT_EQ(one.texture.accesses, 2u * (kSize * kSize / 4 + kSize / 2));
  EXPECT_EQ(one.texture.hits, one.texture.accesses - kSize * kSize * 4 / 64);
  for (int threads : {2, 7}) {
    const test::TexturedQuadResult other = test::draw_textured_quad(texture, kSize, threads);
    EXPECT_EQ(other.texture.accesses, one.texture.accesses) << threads << " threads";
    EXPECT_EQ(other.texture.hits, one.texture.hits) << threads << " threads";
    EXPECT_EQ(other.texture.misses, one.texture.misses) << threads << " threads";
    EXPECT_EQ(other.texture.bytes_read, one.texture.bytes_read) << threads << " threads";
    EXPECT_EQ(other.pixels, one.pixels) << threads << " threads";
  }
}

}  // namespace
}  // namespace ontile
