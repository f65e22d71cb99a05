// The Sobel edge functor against its specification executed literally (every tap a separate
// nearest, clamp-to-edge sample_lod): bit-identical colours and an identical texel trace on
// random G-buffers, parameters, uvs (including off-centre, out-of-range and non-finite), quads and
// whole batches.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "memory/trace_repeats.h"
#include "raster/cell_raster.h"
#include "raster/texel_trace.h"
#include "shaders/toon_test_support.h"
#include "shaders_cpp/full_screen.h"
#include "shaders_cpp/toon/sobel_edge_shader.h"

namespace ontile {
namespace {

// The functor's specification executed literally: every tap a separate sample_lod (nearest,
// clamp-to-edge, lod 0) at uv + offset * thickness / size, in the order the class comment
// gives. The functor reads each texel of a quad once but must match this bit for bit, in its
// output and in the texel trace it reports. `paths` counts the branches taken.
struct ReferencePaths {
  int depth_edges = 0, normal_sobels = 0, normal_edges = 0;
};
glm::vec4 reference_shade_pixel(const SobelEdgeParams& p, glm::vec2 uv, ReferencePaths& paths) {
  SamplerDesc s;
  s.mag_filter = s.min_filter = FilterMode::Nearest;
  s.mipmap_mode = MipmapMode::None;
  s.wrap_u = s.wrap_v = WrapMode::ClampToEdge;
  const glm::vec2 step(p.thickness_px / static_cast<float>(p.depth->width()),
                       p.thickness_px / static_cast<float>(p.depth->height()));
  glm::vec2 tap_uv[9];
  float linear_z[9], depth[9];
  for (int k = 0; k < 9; ++k) {
    tap_uv[k] = uv + glm::vec2(static_cast<float>(k % 3 - 1), static_cast<float>(k / 3 - 1)) * step;
    depth[k] = p.depth->sample_lod(s, tap_uv[k], 0.0f).x;
    linear_z[k] = linearize_depth(depth[k], p.depth_linearization);
  }
  int nearest = 4;
  for (int k = 0; k < 9; ++k)
    if (depth[k] < depth[nearest]) nearest = k;
  float depth_limit = p.depth_threshold * p.depth_sensitivity * linear_z[4];
  const auto normal_at = [&](int k) {
    return decode_view_normal(p.normal->sample_lod(s, tap_uv[k], 0.0f), p.normal_encoding);
  };
  glm::vec3 normals[9];
  if (p.normal) {
    normals[4] = normal_at(4);
    const glm::vec3 ray(p.view_ray_scale.x * (2.0f * uv.x - 1.0f),
                        p.view_ray_scale.y * (1.0f - 2.0f * uv.y), -1.0f);
    const float len = glm::length(normals[4]);
    float cosine = p.min_grazing_cosine;
    if (len > 0.0f) cosine = std::fabs(glm::dot(normals[4], ray)) / (len * glm::length(ray));
    depth_limit /= cosine > p.min_grazing_cosine ? cosine : p.min_grazing_cosine;
  }
  bool edge = sobel_magnitude(linear_z) > depth_limit;
  paths.depth_edges += edge;
  if (!edge && p.normal) {
    for (int k = 0; k < 9; ++k)
      if (k != 4) normals[k] = normal_at(k);
    edge = sobel_vector_magnitude(normals) > p.normal_threshold;
    ++paths.normal_sobels;
    paths.normal_edges += edge;
  }
  const glm::vec4 scene = p.color->sample_lod(s, uv, 0.0f);
  if (!edge) return scene;
  const glm::vec4 border =
      p.border ? p.border->sample_lod(s, tap_uv[nearest], 0.0f) : p.default_border_color;
  return glm::vec4(glm::mix(glm::vec3(scene), glm::vec3(border), border.w), scene.w);
}

// Restores automatic SIMD target selection however a test exits.
struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

bool same_bits(glm::vec4 a, glm::vec4 b) {
  for (int c = 0; c < 4; ++c)
    if (std::bit_cast<uint32_t>(a[c]) != std::bit_cast<uint32_t>(b[c])) return false;
  return true;
}

// A G-buffer (13x9 unless asked otherwise): depth in 4x3 blocks of a few values (ties,
// background at 1), normals in 3x4 blocks with some zero (background) and noisy texels, borders
// with alpha 0, 0.5 and 1, random colours; a 7x5 sRGB RGBA8 colour texture (another size,
// encoding and a mip chain); and 8-bit unorm normals and borders (byte texels, table decode).
struct RandomGBuffer {
  static constexpr int kW = 13, kH = 9;
  int width, height;
  std::shared_ptr<const Texture2D> color, small_srgb_color, depth, unorm_normal, float_normal,
      border, unorm8_normal, unorm8_border;
  explicit RandomGBuffer(std::mt19937& rng, int width_px = kW, int height_px = kH)
      : width(width_px), height(height_px) {
    const auto uniform = [&](float lo, float hi) {
      return std::uniform_real_distribution<float>(lo, hi)(rng);
    };
    const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    const auto random_normal = [&] {
      return glm::normalize(glm::vec3(uniform(-1, 1), uniform(-1, 1), 1.0f));
    };
    const float kDepths[] = {0.3f, 0.3f, 0.95f, 0.97f, 0.999f, 1.0f};
    float block_depth[16];
    for (float& d : block_depth) d = kDepths[pick(6)];
    depth = test::make_float_texture(width, height, [&](int x, int y) {
      const float d = pick(8) == 0 ? kDepths[pick(6)] : block_depth[(x / 4 + 4 * (y / 3)) % 16];
      return glm::vec4(d, 0, 0, 1);
    });
    glm::vec3 block_normal[25];
    for (glm::vec3& n : block_normal) n = random_normal();
    std::vector<glm::vec3> normals;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const int roll = pick(10);
        const glm::vec3 block = block_normal[(x / 3 + 5 * (y / 4)) % 25];
        normals.push_back(roll == 0 ? glm::vec3(0.0f) : (roll == 1 ? random_normal() : block));
      }
    }
    const auto encoded_normal = [&](int x, int y) {
      const glm::vec3 n = normals[y * width + x];
      return n == glm::vec3(0.0f) ? glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)
                                  : encode_view_normal(n, NormalEncoding::Unorm);
    };
    unorm_normal = test::make_float_texture(width, height, encoded_normal);
    float_normal = test::make_float_texture(
        width, height, [&](int x, int y) { return glm::vec4(normals[y * width + x], 1.0f); });
    border = test::make_float_texture(width, height, [&](int, int) {
      const float alpha = 0.5f * static_cast<float>(pick(3));
      return glm::vec4(uniform(0, 1), uniform(0, 1), uniform(0, 1), alpha);
    });
    color = test::make_float_texture(width, height, [&](int, int) {
      return glm::vec4(uniform(0, 1), uniform(0, 1), uniform(0, 1), uniform(0, 1));
    });
    std::vector<uint8_t> rgba8(7 * 5 * 4);
    for (uint8_t& v : rgba8) v = static_cast<uint8_t>(pick(256));
    small_srgb_color = Texture2D::from_rgba8(7, 5, rgba8, true, "small");
    std::vector<uint8_t> normal8, border8;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const glm::vec4 n = encoded_normal(x, y);
        for (int c = 0; c < 4; ++c) normal8.push_back(static_cast<uint8_t>(n[c] * 255.0f + 0.5f));
        for (int c = 0; c < 3; ++c) border8.push_back(static_cast<uint8_t>(pick(256)));
        border8.push_back(static_cast<uint8_t>(127 * pick(3)));
      }
    }
    unorm8_normal = Texture2D::from_rgba8(width, height, normal8, false, "normal8");
    unorm8_border = Texture2D::from_rgba8(width, height, border8, false, "border8");
  }
};

// 96 parameter sets (with and without normal and border buffers, both normal encodings,
// perspective, infinite and orthographic depth, thicknesses on and off texel centres) x 40
// quads (full and partial; uvs at pixel centres, jittered, anywhere in and around [0, 1], and
// 0, -0, NaN, +-inf, beyond 2^24). Outputs and texel traces must equal the reference's exactly.
TEST(SobelEdgeShader, MatchesPerTapSamplingBitForBitWithTheSameTexelTrace) {
  std::mt19937 rng(12345);
  const auto uniform = [&](float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(rng);
  };
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  const RandomGBuffer g(rng);
  constexpr int kW = RandomGBuffer::kW, kH = RandomGBuffer::kH;
  const float inf = std::numeric_limits<float>::infinity();
  const float odd_coords[] = {-0.3f, 1.7f, 0.0f, 1.0f, -0.0f, std::nanf(""), inf, -inf, 3e7f,
                              -1e30f};
  const float thicknesses[] = {1.0f, 1.0f, 2.0f, 1.5f, 0.5f, 3.0f};
  int lanes_checked = 0, traced_granules = 0;
  ReferencePaths paths;
  for (int config = 0; config < 96; ++config) {
    SobelEdgeParams p;
    p.color = config % 4 == 3 ? g.small_srgb_color.get() : g.color.get();
    p.depth = g.depth.get();
    const int normals = config % 3;  // none, unorm, float
    p.normal = normals == 0 ? nullptr : (normals == 1 ? g.unorm_normal : g.float_normal).get();
    p.normal_encoding = normals == 2 ? NormalEncoding::Float : NormalEncoding::Unorm;
    p.border = config % 5 == 4 ? nullptr : g.border.get();
    p.depth_linearization = config % 7 == 6
                                ? DepthLinearization{true, 1.0f, 9.0f}
                                : DepthLinearization{false, 0.1f, config % 2 ? 0.0f : 50.0f};
    p.view_ray_scale = config % 2 ? glm::vec2(0.8f, 0.45f) : glm::vec2(0.0f);
    p.thickness_px = thicknesses[config % 6];
    p.depth_threshold = uniform(0.01f, 0.3f);
    p.normal_threshold = uniform(0.5f, 2.5f);
    const SobelEdgeShader shader(p);
    for (int q = 0; q < 40; ++q) {
      const int x = 2 * pick(kW / 2 + 1), y = 2 * pick(kH / 2 + 1);
      QuadFragment quad = test::make_quad(x, y, static_cast<uint8_t>(q % 8 ? 0xF : 1 + pick(15)));
      const int uv_kind = q % 5;  // centres, centres, jittered, anywhere, odd coordinates
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        glm::vec2 uv((x + (lane & 1) + 0.5f) / kW, (y + (lane >> 1) + 0.5f) / kH);
        if (uv_kind == 2) uv += glm::vec2(uniform(-0.5f, 0.5f) / kW, uniform(-0.5f, 0.5f) / kH);
        if (uv_kind == 3) uv = glm::vec2(uniform(-0.2f, 1.2f), uniform(-0.2f, 1.2f));
        if (uv_kind == 4) uv[pick(2)] = odd_coords[pick(10)];
        quad.varyings[FullScreenVertexShader::kUv][lane] = uv.x;
        quad.varyings[FullScreenVertexShader::kUv + 1][lane] = uv.y;
      }
      std::vector<uint64_t> expected_trace, trace;
      glm::vec4 expected[kQuadLanes];
      {
        const TexelTraceScope scope(&expected_trace);
        for (int lane = 0; lane < kQuadLanes; ++lane) {
          const glm::vec2 uv = quad.var2(FullScreenVertexShader::kUv, lane);
          if (quad.lane_active(lane)) expected[lane] = reference_shade_pixel(p, uv, paths);
        }
      }
      QuadOutput out;
      {
        const TexelTraceScope scope(&trace);
        shader.shade(quad, out);
      }
      // The shader may fold repeated reads into repeat entries: its trace stands for the same.
      ASSERT_EQ(expand_trace_repeats(trace), expected_trace) << "config " << config << " quad " << q;
      traced_granules += static_cast<int>(expected_trace.size());
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        if (!quad.lane_active(lane)) continue;
        ++lanes_checked;
        const glm::vec2 uv = quad.var2(FullScreenVertexShader::kUv, lane);
        ASSERT_TRUE(same_bits(out.color[0][lane], expected[lane]))
            << "config " << config << " quad " << q << " lane " << lane;
        ASSERT_TRUE(same_bits(shader.shade_pixel(uv), expected[lane]))
            << "config " << config << " quad " << q << " lane " << lane;
      }
    }
  }
  EXPECT_GT(lanes_checked, 96 * 40 * 3);
  // Every branch ran often: depth edges, normal Sobels with and without an edge.
  EXPECT_GT(paths.depth_edges, lanes_checked / 10);
  EXPECT_GT(paths.normal_edges, lanes_checked / 20);
  EXPECT_GT(paths.normal_sobels - paths.normal_edges, lanes_checked / 20);
  // Each lane reads at least 3 depth rows and its colour: 4 granules unless neighbours repeat.
  EXPECT_GT(traced_granules, lanes_checked);
}

// Whole batches as the tile loop hands them over (16 quads of a tile in row-major quad order,
// padded fragments repeating the last quad) on a 70x38 G-buffer: tiles of 8, 16 and 32 pixels
// anywhere, borders included, with pixel-centre uvs (the full-screen pass: one decoded
// neighbourhood per batch), jittered ones, and batches with a few scattered or non-finite uvs
// whose taps span more than the neighbourhood grid (each tap read separately). Thicknesses
// include odd and large ones; normals and borders come as floats and as 8-bit texels. The
// parameter sets take turns on each SIMD target.
TEST(SobelEdgeShader, BatchesMatchPerTapSamplingBitForBitWithTheSameTexelTrace) {
  std::mt19937 rng(777);
  const auto uniform = [&](float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(rng);
  };
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  constexpr int kW = 70, kH = 38;
  const RandomGBuffer g(rng, kW, kH);
  const float inf = std::numeric_limits<float>::infinity();
  const float odd_coords[] = {-0.3f, 1.7f, 0.0f, 1.0f, -0.0f, std::nanf(""), inf, -inf, 3e7f};
  const float thicknesses[] = {1.0f, 1.0f, 2.0f, 3.0f, 1.5f, 0.5f, 7.0f, 40.0f};
  const int tile_widths[] = {8, 16, 32};
  auto batch = std::make_unique<FragmentBatch>();
  auto out = std::make_unique<BatchOutput>();
  int lanes_checked = 0, scattered_batches = 0;
  ReferencePaths paths;
  // Every SIMD target this machine runs (the kernels must give the same bits on each).
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  for (int config = 0; config < 48; ++config) {
    force_simd_target(targets[config % targets.size()]);
    SobelEdgeParams p;
    p.color = config % 4 == 3 ? g.small_srgb_color.get() : g.color.get();
    p.depth = g.depth.get();
    const int normals = config % 4;  // none, unorm floats, floats, unorm bytes
    const Texture2D* normal_textures[] = {nullptr, g.unorm_normal.get(), g.float_normal.get(),
                                          g.unorm8_normal.get()};
    p.normal = normal_textures[normals];
    p.normal_encoding = normals == 2 ? NormalEncoding::Float : NormalEncoding::Unorm;
    p.border = config % 5 == 4 ? nullptr : (config % 3 == 1 ? g.unorm8_border : g.border).get();
    p.depth_linearization = config % 7 == 6
                                ? DepthLinearization{true, 1.0f, 9.0f}
                                : DepthLinearization{false, 0.1f, config % 2 ? 0.0f : 50.0f};
    p.view_ray_scale = config % 2 ? glm::vec2(0.8f, 0.45f) : glm::vec2(0.0f);
    p.thickness_px = thicknesses[config % 8];
    p.depth_threshold = uniform(0.01f, 0.3f);
    p.normal_threshold = uniform(0.5f, 2.5f);
    const SobelEdgeShader shader(p);
    for (int b = 0; b < 12; ++b) {
      const int tile_w = tile_widths[pick(3)];
      const int quads_per_row = tile_w / 2;
      const int tile_x = tile_w * pick(kW / tile_w + 1), tile_y = 2 * pick(kH / 2);
      const int uv_kind = b % 4;  // centres, centres, jittered, a few scattered or odd
      batch->quad_count = 1 + (b % 3 == 2 ? pick(kBatchQuads) : kBatchQuads - 1);
      batch->varying_count = 2;
      for (int q = 0; q < kBatchQuads; ++q) {
        const int qc = std::min(q, batch->quad_count - 1);  // padding repeats the last quad
        const int x = tile_x + 2 * (qc % quads_per_row), y = tile_y + 2 * (qc / quads_per_row);
        batch->quad_x_px[q] = x;
        batch->quad_y_px[q] = y;
        batch->lane_mask[q] = q >= batch->quad_count ? 0 : (pick(6) ? 0xF : 1 + pick(15));
        for (int lane = 0; lane < kQuadLanes; ++lane) {
          glm::vec2 uv((x + (lane & 1) + 0.5f) / kW, (y + (lane >> 1) + 0.5f) / kH);
          if (uv_kind == 2) uv += glm::vec2(uniform(-0.5f, 0.5f) / kW, uniform(-0.5f, 0.5f) / kH);
          if (uv_kind == 3 && pick(16) == 0) {
            uv = glm::vec2(uniform(-0.2f, 1.2f), uniform(-0.2f, 1.2f));
            if (pick(2)) uv[pick(2)] = odd_coords[pick(9)];
          }
          batch->varyings[FullScreenVertexShader::kUv][q * kQuadLanes + lane] = uv.x;
          batch->varyings[FullScreenVertexShader::kUv + 1][q * kQuadLanes + lane] = uv.y;
        }
      }
      std::vector<uint64_t> expected_trace, trace;
      glm::vec4 expected[kBatchFragments];
      {
        const TexelTraceScope scope(&expected_trace);
        for (int f = 0; f < batch->fragment_count(); ++f) {
          const glm::vec2 uv(batch->varyings[FullScreenVertexShader::kUv][f],
                             batch->varyings[FullScreenVertexShader::kUv + 1][f]);
          if (batch->active(f)) expected[f] = reference_shade_pixel(p, uv, paths);
        }
      }
      {
        const TexelTraceScope scope(&trace);
        shader.shade_batch(*batch, *out);
      }
      scattered_batches += uv_kind == 3;
      ASSERT_EQ(expand_trace_repeats(trace), expected_trace) << "config " << config << " batch " << b;
      for (int f = 0; f < batch->fragment_count(); ++f) {
        if (!batch->active(f)) continue;
        ++lanes_checked;
        ASSERT_TRUE(same_bits(out->get(0, f), expected[f]))
            << "config " << config << " batch " << b << " fragment " << f;
      }
    }
  }
  EXPECT_GT(lanes_checked, 48 * 12 * 30);
  EXPECT_GT(scattered_batches, 48 * 2);
  EXPECT_GT(paths.depth_edges, lanes_checked / 20);
  EXPECT_GT(paths.normal_edges, lanes_checked / 40);
  EXPECT_GT(paths.normal_sobels - paths.normal_edges, lanes_checked / 40);
}

}  // namespace
}  // namespace ontile
