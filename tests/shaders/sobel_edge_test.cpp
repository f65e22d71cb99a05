// Screen-space Sobel edges: the kernel on synthetic 3x3 patches, depth linearization, and whole
// synthetic G-buffers (a depth step along a column, a normal crease along a row, a region
// without border) run through the functor and through the tiler with the full-screen triangle.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "context/camera_matrices.h"
#include "context/render_context.h"
#include "shaders/toon_test_support.h"
#include "shaders_cpp/full_screen.h"
#include "shaders_cpp/toon/sobel_edge_shader.h"
#include "util/error.h"

namespace ontile {
namespace {

TEST(SobelMagnitude, FlatIsZeroAndAStepOfHeightHIsFourH) {
  const float flat[9] = {0.7f, 0.7f, 0.7f, 0.7f, 0.7f, 0.7f, 0.7f, 0.7f, 0.7f};
  EXPECT_EQ(sobel_magnitude(flat), 0.0f);
  const float h = 0.1f;
  const float vertical_step[9] = {0, 0, h, 0, 0, h, 0, 0, h};
  EXPECT_EQ(sobel_magnitude(vertical_step), 4.0f * h);
  const float vertical_step_left[9] = {0, h, h, 0, h, h, 0, h, h};
  EXPECT_EQ(sobel_magnitude(vertical_step_left), 4.0f * h);
  const float on_a_base[9] = {2, 2, 2.5f, 2, 2, 2.5f, 2, 2, 2.5f};  // height 0.5 above 2
  EXPECT_EQ(sobel_magnitude(on_a_base), 2.0f);
  const float horizontal_step[9] = {0, 0, 0, 0, 0, 0, h, h, h};
  EXPECT_EQ(sobel_magnitude(horizontal_step), 4.0f * h);
  const float ramp[9] = {0, 1, 2, 0, 1, 2, 0, 1, 2};  // slope 1 per tap: 8
  EXPECT_EQ(sobel_magnitude(ramp), 8.0f);
}

TEST(SobelVectorMagnitude, IsFourTimesTheNormalDifferenceAcrossACrease) {
  const glm::vec3 a(0, 0, 1), b = glm::normalize(glm::vec3(0, 1, 1));
  const glm::vec3 crease[9] = {a, a, a, a, a, a, b, b, b};
  EXPECT_NEAR(sobel_vector_magnitude(crease), 4.0f * glm::length(b - a), 1e-6f);
  const glm::vec3 flat[9] = {b, b, b, b, b, b, b, b, b};
  EXPECT_EQ(sobel_vector_magnitude(flat), 0.0f);
}

float perspective_depth(double z, double n, double f) { return static_cast<float>(f * (z - n) / (z * (f - n))); }

TEST(LinearizeDepth, InvertsThePerspectiveAndOrthographicProjections) {
  const DepthLinearization persp{false, 0.1f, 100.0f};
  EXPECT_FLOAT_EQ(linearize_depth(0.0f, persp), 0.1f);
  EXPECT_FLOAT_EQ(linearize_depth(1.0f, persp), 100.0f);
  for (double z : {0.5, 2.0, 37.0}) EXPECT_NEAR(linearize_depth(perspective_depth(z, 0.1, 100.0), persp), z, z * 1e-5);
  const DepthLinearization infinite{false, 0.1f, 0.0f};
  EXPECT_FLOAT_EQ(linearize_depth(0.5f, infinite), 0.2f);
  EXPECT_FLOAT_EQ(linearize_depth(1.0f, infinite), 0.1f * 16777216.0f);  // finite background
  const DepthLinearization ortho{true, 1.0f, 11.0f};
  EXPECT_EQ(linearize_depth(0.5f, ortho), 6.0f);
  EXPECT_EQ(linearize_depth(2.0f, ortho), 11.0f);  // clamped to [0, 1]

  Camera camera;
  camera.znear = 0.5f;
  camera.zfar = 50.0f;
  DepthLinearization l = DepthLinearization::from_projection(camera_matrices(camera, 1.5).projection);
  EXPECT_FALSE(l.orthographic);
  EXPECT_FLOAT_EQ(l.near_plane, 0.5f);
  EXPECT_FLOAT_EQ(l.far_plane, 50.0f);
  camera.zfar = 0.0f;
  l = DepthLinearization::from_projection(camera_matrices(camera, 1.5).projection);
  EXPECT_FLOAT_EQ(l.near_plane, 0.5f);
  EXPECT_EQ(l.far_plane, 0.0f);
  camera.type = Camera::Type::Orthographic;
  camera.zfar = 20.0f;
  l = DepthLinearization::from_projection(camera_matrices(camera, 1.5).projection);
  EXPECT_TRUE(l.orthographic);
  EXPECT_FLOAT_EQ(l.near_plane, 0.5f);
  EXPECT_FLOAT_EQ(l.far_plane, 20.0f);
}

// A 16x12 G-buffer: columns 0-7 at distance 2, 8-15 at distance 4 (depth step between columns
// 7 and 8); rows 0-5 face the camera, rows 6-11 are tilted 45 degrees (crease between rows 5
// and 6); border colour: columns 0-3 green with alpha 0 (no border), 4-7 red, 8-15 blue.
constexpr int kW = 16, kH = 12;
const glm::vec4 kRed(1, 0, 0, 1), kBlue(0, 0, 1, 1), kNoBorder(0, 1, 0, 0);
glm::vec4 scene_at(int x, int y) { return {x / 16.0f, y / 12.0f, 0.25f, 0.5f}; }

struct GBuffer {
  std::shared_ptr<const Texture2D> color, depth, normal, border;
  SobelEdgeParams params() const {
    SobelEdgeParams p;
    p.color = color.get();
    p.depth = depth.get();
    p.normal = normal.get();
    p.border = border.get();
    p.depth_linearization = {false, 0.1f, 100.0f};
    p.normal_encoding = NormalEncoding::Unorm;
    return p;
  }
};

GBuffer make_gbuffer() {
  GBuffer g;
  g.color = test::make_float_texture(kW, kH, scene_at);
  g.depth = test::make_float_texture(kW, kH, [](int x, int) {
    return glm::vec4(perspective_depth(x <= 7 ? 2.0 : 4.0, 0.1, 100.0), 0, 0, 1);
  });
  g.normal = test::make_float_texture(kW, kH, [](int, int y) {
    const glm::vec3 n = y <= 5 ? glm::vec3(0, 0, 1) : glm::normalize(glm::vec3(0, 1, 1));
    return encode_view_normal(n, NormalEncoding::Unorm);
  });
  g.border = test::make_float_texture(kW, kH, [](int x, int) {
    return x <= 3 ? kNoBorder : (x <= 7 ? kRed : kBlue);
  });
  return g;
}

// Edges: depth at columns 7 and 8 (both sides of the step), normals at rows 5 and 6. The border
// comes from the nearest tap: column 8's nearest taps are in column 7 (red); elsewhere the
// centre's own. Columns 0-3 have no border, so they keep the scene colour.
glm::vec4 expected_at(int x, int y) {
  const bool edge = x == 7 || x == 8 || y == 5 || y == 6;
  if (!edge || x <= 3) return scene_at(x, y);
  const glm::vec4 border = x <= 8 ? kRed : kBlue;
  return {border.x, border.y, border.z, scene_at(x, y).w};
}

TEST(SobelEdgeShader, DrawsEdgesExactlyWhereExpected) {
  const GBuffer g = make_gbuffer();
  const SobelEdgeShader shader(g.params());
  int edge_pixels = 0;
  for (int y = 0; y < kH; y += 2) {
    for (int x = 0; x < kW; x += 2) {
      QuadFragment q = test::make_quad(x, y, 0xF);
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        q.varyings[FullScreenVertexShader::kUv][lane] = (x + (lane & 1) + 0.5f) / kW;
        q.varyings[FullScreenVertexShader::kUv + 1][lane] = (y + (lane >> 1) + 0.5f) / kH;
      }
      QuadOutput out;
      shader.shade(q, out);
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        const int px = x + (lane & 1), py = y + (lane >> 1);
        EXPECT_EQ(out.color[0][lane], expected_at(px, py)) << px << "," << py;
        edge_pixels += out.color[0][lane] != scene_at(px, py);
      }
    }
  }
  // Columns 7, 8 (12 rows each) + rows 5, 6 over columns 4-15 minus the 2x2 overlap.
  EXPECT_EQ(edge_pixels, 2 * 12 + 2 * 12 - 4);
}

TEST(SobelEdgeShader, WithoutNormalsOnlyDepthEdgesRemain) {
  const GBuffer g = make_gbuffer();
  SobelEdgeParams p = g.params();
  p.normal = nullptr;
  p.border = nullptr;  // the default border colour: opaque black
  const SobelEdgeShader shader(p);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const glm::vec4 c = shader.shade_pixel({(x + 0.5f) / kW, (y + 0.5f) / kH});
      const glm::vec4 expected = (x == 7 || x == 8) ? glm::vec4(0, 0, 0, 0.5f) : scene_at(x, y);
      EXPECT_EQ(c, expected) << x << "," << y;
    }
  }
}

TEST(SobelEdgeShader, RunsAsAFullScreenPassOnTheTiler) {
  const GBuffer g = make_gbuffer();
  const SobelEdgeShader shader(g.params());
  ContextConfig cfg;
  cfg.threads = 2;
  cfg.tiler.tile_size_px = 8;
  RenderContext ctx(cfg);
  Surface* target = ctx.create_surface("edges", PixelFormat::RGBA32_FLOAT, kW, kH);
  ctx.begin_render_pass("edges", kW, kH, 1,
                        {{"edges", PixelFormat::RGBA32_FLOAT, LoadAction::DontCare, StoreAction::Store,
                          glm::vec4(0.0f), target, nullptr}},
                        -1);
  ctx.begin_subpass({0});
  const FullScreenVertexShader vs;
  DrawCall d;
  d.vertex_shader = &vs;
  d.fragment_shader = &shader;
  d.vertex_count = 3;
  d.indices = full_screen_indices();
  d.index_count = 3;
  d.raster.cull = CullMode::None;
  d.raster.depth_test = false;
  d.raster.depth_write = false;
  ctx.draw(d);
  ctx.end_subpass();
  ctx.end_render_pass();
  ctx.submit();
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) EXPECT_EQ(target->read(x, y), expected_at(x, y)) << x << "," << y;
}

TEST(SobelEdgeShader, GrazingSurfacesRaiseTheDepthLimit) {
  // A plane receding to the right: z = 2 + 0.1 x per pixel, so the Sobel strength is 8 * 0.1 =
  // 0.8 against a limit of 0.2 z <= 0.7: every interior pixel is a depth edge when nothing says
  // the plane is grazing. Its normal at |cos| = 0.2 to the view divides the limit by 0.2 (to
  // z >= 2): no edges.
  const auto color = test::make_float_texture(kW, kH, scene_at);
  const auto depth = test::make_float_texture(kW, kH, [](int x, int) {
    return glm::vec4(perspective_depth(2.0 + 0.1 * x, 0.1, 100.0), 0, 0, 1);
  });
  const glm::vec3 grazing = glm::normalize(glm::vec3(0.0f, std::sqrt(0.96f), 0.2f));
  const auto normal = test::make_float_texture(kW, kH, [&](int, int) {
    return encode_view_normal(grazing, NormalEncoding::Float);
  });
  SobelEdgeParams p;
  p.color = color.get();
  p.depth = depth.get();
  p.depth_linearization = {false, 0.1f, 100.0f};
  p.default_border_color = kRed;
  const SobelEdgeShader depth_only(p);
  p.normal = normal.get();
  p.normal_encoding = NormalEncoding::Float;
  const SobelEdgeShader compensated(p);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const glm::vec2 uv((x + 0.5f) / kW, (y + 0.5f) / kH);
      if (x >= 1 && x <= kW - 2) {
        EXPECT_EQ(depth_only.shade_pixel(uv), glm::vec4(1, 0, 0, 0.5f)) << x << "," << y;
      }
      EXPECT_EQ(compensated.shade_pixel(uv), scene_at(x, y)) << x << "," << y;
    }
  }
}

TEST(ViewRayScale, IsTheInverseProjectionScale) {
  Camera camera;
  camera.yfov_rad = 0.8f;
  const CameraMatrices m = camera_matrices(camera, 2.0);
  const glm::vec2 s = view_ray_scale(m.projection);
  EXPECT_FLOAT_EQ(s.y, std::tan(0.4f));
  EXPECT_FLOAT_EQ(s.x, 2.0f * std::tan(0.4f));
  camera.type = Camera::Type::Orthographic;
  EXPECT_EQ(view_ray_scale(camera_matrices(camera, 2.0).projection), glm::vec2(0.0f));
}

TEST(SobelEdgeShader, RejectsMismatchedBuffers) {
  const GBuffer g = make_gbuffer();
  SobelEdgeParams p = g.params();
  const auto small = test::make_float_texture(4, 4, [](int, int) { return glm::vec4(0.0f); });
  p.normal = small.get();
  EXPECT_THROW(SobelEdgeShader{p}, Error);
  p = g.params();
  p.depth = nullptr;
  EXPECT_THROW(SobelEdgeShader{p}, Error);
  p = g.params();
  p.depth_linearization = {false, 0.0f, 10.0f};
  EXPECT_THROW(SobelEdgeShader{p}, Error);
}

}  // namespace
}  // namespace ontile
