// The Sobel edge functor against its specification executed literally (every tap a separate
// nearest, clamp-to-edge sample_lod): bit-identical colours and an identical texel trace on
// random G-buffers, parameters, uvs (including off-centre, out-of-range and non-finite) and quads.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <vector>

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

bool same_bits(glm::vec4 a, glm::vec4 b) {
  for (int c = 0; c < 4; ++c)
    if (std::bit_cast<uint32_t>(a[c]) != std::bit_cast<uint32_t>(b[c])) return false;
  return true;
}

// A 13x9 G-buffer: depth in 4x3 blocks of a few values (ties, background at 1), normals in 3x4
// blocks with some zero (background) and noisy texels, borders with alpha 0, 0.5 and 1, random
// colours; and a 7x5 sRGB RGBA8 colour texture (another size, encoding and a mip chain).
struct RandomGBuffer {
  static constexpr int kW = 13, kH = 9;
  std::shared_ptr<const Texture2D> color, small_srgb_color, depth, unorm_normal, float_normal,
      border;
  explicit RandomGBuffer(std::mt19937& rng) {
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
    depth = test::make_float_texture(kW, kH, [&](int x, int y) {
      const float d = pick(8) == 0 ? kDepths[pick(6)] : block_depth[x / 4 + 4 * (y / 3)];
      return glm::vec4(d, 0, 0, 1);
    });
    glm::vec3 block_normal[25];
    for (glm::vec3& n : block_normal) n = random_normal();
    std::vector<glm::vec3> normals;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        const int roll = pick(10);
        const glm::vec3 block = block_normal[x / 3 + 5 * (y / 4)];
        normals.push_back(roll == 0 ? glm::vec3(0.0f) : (roll == 1 ? random_normal() : block));
      }
    }
    unorm_normal = test::make_float_texture(kW, kH, [&](int x, int y) {
      const glm::vec3 n = normals[y * kW + x];
      return n == glm::vec3(0.0f) ? glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)
                                  : encode_view_normal(n, NormalEncoding::Unorm);
    });
    float_normal = test::make_float_texture(
        kW, kH, [&](int x, int y) { return glm::vec4(normals[y * kW + x], 1.0f); });
    border = test::make_float_texture(kW, kH, [&](int, int) {
      const float alpha = 0.5f * static_cast<float>(pick(3));
      return glm::vec4(uniform(0, 1), uniform(0, 1), uniform(0, 1), alpha);
    });
    color = test::make_float_texture(kW, kH, [&](int, int) {
      return glm::vec4(uniform(0, 1), uniform(0, 1), uniform(0, 1), uniform(0, 1));
    });
    std::vector<uint8_t> rgba8(7 * 5 * 4);
    for (uint8_t& v : rgba8) v = static_cast<uint8_t>(pick(256));
    small_srgb_color = Texture2D::from_rgba8(7, 5, rgba8, true, "small");
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
      ASSERT_EQ(trace, expected_trace) << "config " << config << " quad " << q;
      traced_granules += static_cast<int>(trace.size());
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

}  // namespace
}  // namespace ontile
