// Perspective-correct interpolation: UVs on a slanted quad match the analytic value from a
// ray cast at every pixel centre (max error < 1e-5).
#include <gtest/gtest.h>

#include "support/raster_harness.h"
#include "support/view_space_triangle.h"

namespace ontile::test {
namespace {

TEST(PerspectiveInterpolation, SlantedQuadUvMatchesAnalytic) {
  // Clip-space vertices (x, y, w) of a strongly slanted quad whose screen positions are whole
  // pixels and whose w are powers of two, so snapping is exact and the analytic answer is the
  // ray cast from the eye through (ndc_x, ndc_y, 1) against the triangle in (x, y, w) space.
  const PerspectiveSetup cam;
  const double screen[4][2] = {{10, 90}, {118, 90}, {100, 10}, {28, 10}};
  const double w[4] = {1.0, 1.0, 16.0, 16.0};
  const glm::dvec2 uv[4] = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  glm::dvec3 v[4];
  std::vector<glm::vec4> pos;
  std::vector<float> var;
  for (int i = 0; i < 4; ++i) {
    pos.push_back(pixel_to_clip(screen[i][0], screen[i][1], cam.width, cam.height, w[i]));
    v[i] = glm::dvec3(pos.back().x, pos.back().y, pos.back().w);
    var.insert(var.end(), {float(uv[i].x), float(uv[i].y), 0.0f, 1.0f});
  }
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3};

  RenderContext ctx(ContextConfig{2, {}});
  Surface* target = ctx.create_surface("uv", PixelFormat::RGBA32_FLOAT, cam.width, cam.height);
  ClipSpaceVertexShader vs(pos, var, 4);
  VaryingsShader fs;
  ctx.begin_render_pass("uv", cam.width, cam.height, 1,
                        {{"uv", PixelFormat::RGBA32_FLOAT, LoadAction::Clear, StoreAction::Store,
                          glm::vec4(-1.0f), target, nullptr}}, -1);
  ctx.begin_subpass({0});
  DrawCall d;
  d.vertex_shader = &vs;
  d.fragment_shader = &fs;
  d.vertex_count = 4;
  d.indices = idx.data();
  d.index_count = 6;
  d.raster.cull = CullMode::None;
  d.raster.depth_test = false;
  ctx.draw(d);
  ctx.end_subpass();
  ctx.end_render_pass();
  ctx.submit();

  double max_error = 0.0;
  int checked = 0;
  for (int y = 0; y < cam.height; ++y) {
    for (int x = 0; x < cam.width; ++x) {
      const glm::vec4 got = target->read(x, y);
      for (int t = 0; t < 2; ++t) {
        const glm::dvec3 tri[3] = {v[0], v[t + 1], v[t + 2]};
        const glm::dvec3 ray((x + 0.5) / cam.width * 2.0 - 1.0, 1.0 - (y + 0.5) / cam.height * 2.0, 1.0);
        const auto hit = intersect(ray, tri);
        if (!hit || std::min({hit->b0, hit->b1, hit->b2}) < 1e-3) continue;
        const glm::dvec2 expect = hit->b0 * uv[0] + hit->b1 * uv[t + 1] + hit->b2 * uv[t + 2];
        ASSERT_NE(got.x, -1.0f) << "pixel " << x << "," << y << " not covered";
        max_error = std::max({max_error, std::abs(got.x - expect.x), std::abs(got.y - expect.y)});
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 3000);
  EXPECT_LT(max_error, 1e-5);
  std::printf("perspective-correct UV: %d pixels, max error %.3g\n", checked, max_error);
}

}  // namespace
}  // namespace ontile::test
