// Texture2D::sample_quads (a batch of quads and reads per call) against Texture2D::sample_quad
// quad by quad and read by read: the same values bit for bit and the same texel trace, for 8-bit
// linear reads (every mip mode, wrap, LOD bias, block-compressed and tiny levels), reads that
// take the general path (huge and non-finite coordinates), other samplers and repeated fetches
// (QuadRead::fetches, traced as often), and a QuadTraceHook's granules between the quads, on
// every SIMD target.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "raster/cell_raster.h"
#include "raster/texel_trace.h"
#include "raster/texture.h"

namespace ontile {
namespace {

constexpr int kQuads = 16;
constexpr int kFragments = kQuads * 4;

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

std::vector<uint8_t> random_bytes(std::mt19937& rng, int w, int h) {
  std::vector<uint8_t> bytes(static_cast<size_t>(w) * h * 4);
  for (auto& b : bytes) b = static_cast<uint8_t>(rng());
  return bytes;
}

SamplerDesc random_sampler(std::mt19937& rng, bool linear) {
  const WrapMode wraps[] = {WrapMode::Repeat, WrapMode::ClampToEdge, WrapMode::MirroredRepeat};
  const MipmapMode mips[] = {MipmapMode::Linear, MipmapMode::Linear, MipmapMode::Nearest, MipmapMode::None};
  SamplerDesc s;
  s.mag_filter = s.min_filter = linear ? FilterMode::Linear : FilterMode::Nearest;
  s.mipmap_mode = mips[rng() % 4];
  s.wrap_u = wraps[rng() % 3];
  s.wrap_v = wraps[rng() % 3];
  s.lod_bias = rng() % 3 == 0 ? std::uniform_real_distribution<float>(-1.5f, 1.5f)(rng) : 0.0f;
  return s;
}

// A shader's own per-quad reads: nothing, a repeat of the trace's last granule (dropped) and a
// new one, or a new one twice (the second dropped) and one that may repeat a texel granule.
int append_quad_granules(const void*, int q, uint64_t* out, uint64_t& last) {
  const uint64_t pattern[3][3] = {{}, {last, 5000u + static_cast<uint64_t>(q)},
                                  {6000u + static_cast<uint64_t>(q), 6000u + static_cast<uint64_t>(q), 7}};
  const int lengths[3] = {0, 2, 3};
  int count = 0;
  for (int i = 0; i < lengths[q % 3]; ++i) {
    const uint64_t granule = pattern[q % 3][i];
    if (granule == last) continue;
    out[count++] = granule;
    last = granule;
  }
  return count;
}

TEST(TextureQuads, BatchesMatchSampleQuadBitsAndTrace) {
  std::mt19937 rng(9100);
  std::mt19937 fetch_rng(12);  // apart, so the other draws stay those of rng alone
  const std::shared_ptr<const Texture2D> textures[] = {
      Texture2D::from_rgba8(64, 64, random_bytes(rng, 64, 64), true, "srgb pot"),
      // Wide power-of-two levels: rows of several granules, footprints of every shape.
      Texture2D::from_rgba8(128, 32, random_bytes(rng, 128, 32), false, "unorm pot wide"),
      Texture2D::from_rgba8(45, 29, random_bytes(rng, 45, 29), false, "unorm npot"),
      Texture2D::from_rgba8(3, 2, random_bytes(rng, 3, 2), false, "tiny"),
      Texture2D::from_rgba8(40, 24, random_bytes(rng, 40, 24), true, "astc", TextureCompression::Astc4x4),
      Texture2D::from_rgba8(33, 17, random_bytes(rng, 33, 17), false, "etc2", TextureCompression::Etc2),
      Texture2D::from_rgba32f(8, 8, std::vector<float>(8 * 8 * 4, 0.25f), "float"),
  };
  constexpr int kTextures = static_cast<int>(std::size(textures));
  const float inf = std::numeric_limits<float>::infinity();
  const float odd[] = {-0.0f, std::nanf(""), inf, -inf, 3e7f, -1e30f, 2e9f};
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  int checked = 0;
  for (int round = 0; round < 600; ++round) {
    force_simd_target(targets[round % targets.size()]);
    const int read_count = 1 + static_cast<int>(rng() % 5);  // 5: more than a batch call takes
    SamplerDesc samplers[5];
    const Texture2D* read_textures[5];
    int fetches[5];
    for (int r = 0; r < read_count; ++r) {
      // Mostly 8-bit linear reads (the batched path); now and then a nearest or float read.
      read_textures[r] = textures[rng() % (round % 7 == 0 ? kTextures : kTextures - 1)].get();
      samplers[r] = random_sampler(rng, round % 11 != 0);
      fetches[r] = fetch_rng() % 3 == 0 ? 2 + static_cast<int>(fetch_rng() % 3) : 1;
    }
    const int quads = 1 + static_cast<int>(rng() % kQuads);
    // Quads of a scale from magnified to far minified, with random offsets and a few odd values.
    const float scale = std::exp2(std::uniform_real_distribution<float>(-9.0f, 2.0f)(rng));
    float u[kFragments], v[kFragments];
    for (int q = 0; q < quads; ++q) {
      const float u0 = std::uniform_real_distribution<float>(-1.5f, 2.5f)(rng);
      const float v0 = std::uniform_real_distribution<float>(-1.5f, 2.5f)(rng);
      for (int lane = 0; lane < 4; ++lane) {
        u[q * 4 + lane] = u0 + scale * static_cast<float>(lane & 1) * (0.5f + static_cast<float>(rng() % 4));
        v[q * 4 + lane] = v0 + scale * static_cast<float>(lane >> 1) * (0.5f + static_cast<float>(rng() % 4));
        if (round % 5 == 4 && rng() % 8 == 0) (rng() % 2 ? u : v)[q * 4 + lane] = odd[rng() % std::size(odd)];
      }
    }
    std::vector<uint64_t> expected_trace{7}, trace{7};  // a granule before: merges count too
    const Texture2D::QuadTraceHook hook{&append_quad_granules, nullptr, 3};
    const Texture2D::QuadTraceHook* after_quad = round % 3 == 1 ? &hook : nullptr;
    float expected[5][4][kFragments], out[5][4][kFragments];
    {
      const TexelTraceScope scope(&expected_trace);
      for (int q = 0; q < quads; ++q) {
        const glm::vec2 uv[4] = {{u[q * 4], v[q * 4]}, {u[q * 4 + 1], v[q * 4 + 1]},
                                 {u[q * 4 + 2], v[q * 4 + 2]}, {u[q * 4 + 3], v[q * 4 + 3]}};
        for (int r = 0; r < read_count; ++r) {
          glm::vec4 texel[4];
          read_textures[r]->sample_quad(samplers[r], uv, texel, fetches[r]);
          for (int lane = 0; lane < 4; ++lane) {
            for (int c = 0; c < 4; ++c) expected[r][c][q * 4 + lane] = texel[lane][c];
          }
        }
        if (after_quad) {
          uint64_t granules[3];
          const int count = append_quad_granules(nullptr, q, granules, texel_trace_detail::last_granule);
          expected_trace.insert(expected_trace.end(), granules, granules + count);
        }
      }
    }
    {
      Texture2D::QuadRead reads[5];
      for (int r = 0; r < read_count; ++r) {
        reads[r] = {read_textures[r], &samplers[r], {out[r][0], out[r][1], out[r][2], out[r][3]}, fetches[r]};
      }
      const TexelTraceScope scope(&trace);
      Texture2D::sample_quads(reads, read_count, u, v, quads, after_quad);
    }
    ASSERT_EQ(trace, expected_trace) << "round " << round;
    for (int r = 0; r < read_count; ++r) {
      for (int f = 0; f < quads * 4; ++f) {
        for (int c = 0; c < 4; ++c) {
          ASSERT_EQ(std::bit_cast<uint32_t>(out[r][c][f]), std::bit_cast<uint32_t>(expected[r][c][f]))
              << "round " << round << " read " << r << " fragment " << f << " channel " << c;
        }
      }
    }
    checked += quads * read_count;
  }
  EXPECT_GT(checked, 600 * 8);
}

// The batch driver keeps each thread's prepared levels from one call to the next: a texture
// made where a destroyed one was (its levels likely at the same place, same level count, other
// sizes) must be sampled with its own levels, and so must the same texture with other wraps.
TEST(TextureQuads, BatchesAfterAnotherTextureAtTheSamePlaceUseTheirOwnLevels) {
  std::mt19937 rng(515);
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  for (int round = 0; round < 60; ++round) {
    force_simd_target(targets[(round / 3) % targets.size()]);
    const bool wide = round % 2 == 0;
    const auto texture = Texture2D::from_rgba8(wide ? 64 : 16, wide ? 16 : 64, random_bytes(rng, 64, 16),
                                               round % 3 == 0, "reused");
    SamplerDesc sampler;
    sampler.wrap_v = round % 4 == 3 ? WrapMode::ClampToEdge : WrapMode::Repeat;
    const float scale = std::exp2(std::uniform_real_distribution<float>(-7.0f, -1.0f)(rng));
    float u[kFragments], v[kFragments];
    for (int q = 0; q < kQuads; ++q) {
      const float u0 = std::uniform_real_distribution<float>(-1.0f, 2.0f)(rng);
      const float v0 = std::uniform_real_distribution<float>(-1.0f, 2.0f)(rng);
      for (int lane = 0; lane < 4; ++lane) {
        u[q * 4 + lane] = u0 + scale * static_cast<float>(lane & 1);
        v[q * 4 + lane] = v0 + scale * static_cast<float>(lane >> 1) * 0.75f;
      }
    }
    std::vector<uint64_t> expected_trace, trace;
    float expected[4][kFragments], out[4][kFragments];
    {
      const TexelTraceScope scope(&expected_trace);
      for (int q = 0; q < kQuads; ++q) {
        const glm::vec2 uv[4] = {{u[q * 4], v[q * 4]}, {u[q * 4 + 1], v[q * 4 + 1]},
                                 {u[q * 4 + 2], v[q * 4 + 2]}, {u[q * 4 + 3], v[q * 4 + 3]}};
        glm::vec4 texel[4];
        texture->sample_quad(sampler, uv, texel);
        for (int lane = 0; lane < 4; ++lane) {
          for (int c = 0; c < 4; ++c) expected[c][q * 4 + lane] = texel[lane][c];
        }
      }
    }
    {
      const Texture2D::QuadRead read{texture.get(), &sampler, {out[0], out[1], out[2], out[3]}};
      const TexelTraceScope scope(&trace);
      Texture2D::sample_quads(&read, 1, u, v, kQuads);
    }
    ASSERT_EQ(trace, expected_trace) << "round " << round;
    for (int c = 0; c < 4; ++c) {
      for (int f = 0; f < kFragments; ++f) {
        ASSERT_EQ(std::bit_cast<uint32_t>(out[c][f]), std::bit_cast<uint32_t>(expected[c][f]))
            << "round " << round << " fragment " << f << " channel " << c;
      }
    }
  }
}

// Without a trace scope nothing is recorded and the values are the same.
TEST(TextureQuads, UntracedBatchesGiveTheSameValues) {
  std::mt19937 rng(77);
  const auto texture = Texture2D::from_rgba8(32, 32, random_bytes(rng, 32, 32), true, "t");
  SamplerDesc sampler;
  float u[kFragments], v[kFragments];
  for (int f = 0; f < kFragments; ++f) {
    u[f] = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng) + 0.01f * static_cast<float>(f & 1);
    v[f] = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng) + 0.03f * static_cast<float>(f >> 1 & 1);
  }
  float traced[4][kFragments], untraced[4][kFragments];
  const Texture2D::QuadRead traced_read{texture.get(), &sampler, {traced[0], traced[1], traced[2], traced[3]}};
  const Texture2D::QuadRead untraced_read{texture.get(), &sampler,
                                          {untraced[0], untraced[1], untraced[2], untraced[3]}};
  std::vector<uint64_t> trace;
  {
    const TexelTraceScope scope(&trace);
    Texture2D::sample_quads(&traced_read, 1, u, v, kQuads);
  }
  Texture2D::sample_quads(&untraced_read, 1, u, v, kQuads);
  EXPECT_FALSE(trace.empty());
  for (int c = 0; c < 4; ++c) {
    for (int f = 0; f < kFragments; ++f) {
      ASSERT_EQ(std::bit_cast<uint32_t>(traced[c][f]), std::bit_cast<uint32_t>(untraced[c][f]));
    }
  }
}

}  // namespace
}  // namespace ontile
