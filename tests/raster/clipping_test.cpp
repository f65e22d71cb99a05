// Homogeneous clipping: triangles crossing the near plane, with a vertex behind the eye, with
// w = 0, or on the near plane draw exactly their visible part (checked against ray casts).
#include <gtest/gtest.h>

#include "support/raster_harness.h"
#include "support/view_space_triangle.h"

namespace ontile::test {
namespace {

// Renders a view-space triangle and compares each pixel with the ray-cast expectation; pixels
// within `margin` (barycentric / relative depth) of a boundary may go either way.
void check_view_space_triangle(const glm::dvec3 v[3], const std::string& what,
                               int* covered_out = nullptr) {
  const PerspectiveSetup cam;
  const glm::dmat4 proj = cam.projection();
  std::vector<glm::vec4> pos;
  for (int i = 0; i < 3; ++i) pos.push_back(glm::vec4(proj * glm::dvec4(v[i], 1.0)));
  const CountResult r = draw_counting(pos, {0, 1, 2}, cam.width, cam.height);
  const double margin = 2e-3;
  int covered = 0, wrong = 0;
  for (int y = 0; y < cam.height; ++y) {
    for (int x = 0; x < cam.width; ++x) {
      const float c = r.at(x, y, cam.width);
      ASSERT_TRUE(c == 0.0f || c == 1.0f) << what << ": pixel " << x << "," << y << " count " << c;
      covered += c == 1.0f;
      const auto hit = intersect(cam.ray(x, y), v);
      if (!hit) continue;
      const double min_b = std::min({hit->b0, hit->b1, hit->b2});
      const double depth_margin = (hit->view_depth - cam.znear) / cam.znear;
      const double far_margin = (cam.zfar - hit->view_depth) / cam.zfar;
      const bool inside = min_b > margin && depth_margin > margin && far_margin > margin;
      const bool outside = min_b < -margin || depth_margin < -margin || far_margin < -margin;
      if ((inside && c != 1.0f) || (outside && c != 0.0f)) ++wrong;
    }
  }
  EXPECT_EQ(wrong, 0) << what;
  EXPECT_EQ(r.report.passes[0].geometry.triangles_non_finite, 0u);
  if (covered_out) *covered_out = covered;
}

TEST(Clipping, TriangleCrossingTheNearPlane) {
  const glm::dvec3 v[3] = {{-2.0, -1.0, -4.0}, {2.0, -1.0, -4.0}, {0.0, -0.2, -0.1}};
  int covered = 0;
  check_view_space_triangle(v, "near crossing", &covered);
  EXPECT_GT(covered, 500);
}

TEST(Clipping, VertexBehindTheEye) {
  const glm::dvec3 v[3] = {{-1.0, -1.0, -2.0}, {1.0, -1.0, -2.0}, {0.0, 1.0, 1.5}};
  int covered = 0;
  check_view_space_triangle(v, "behind the eye", &covered);
  EXPECT_GT(covered, 500);
}

TEST(Clipping, VertexWithWZero) {
  // A view-space vertex in the eye plane has clip w = 0.
  const glm::dvec3 v[3] = {{-1.0, -1.0, -3.0}, {1.5, -0.5, -3.0}, {0.3, 0.8, 0.0}};
  int covered = 0;
  check_view_space_triangle(v, "w = 0", &covered);
  EXPECT_GT(covered, 100);
}

TEST(Clipping, ClipSpaceVertexWithWAndZExactlyZero) {
  // Degenerate homogeneous input straight in clip space: must not crash or produce NaN, and
  // whatever it covers is covered at most once.
  const std::vector<glm::vec4> pos = {{-0.5f, -0.5f, 0.5f, 1.0f}, {0.5f, -0.5f, 0.5f, 1.0f},
                                      {0.3f, 0.2f, 0.0f, 0.0f}};
  const CountResult r = draw_counting(pos, {0, 1, 2}, 64, 64);
  for (float c : r.counts) EXPECT_TRUE(c == 0.0f || c == 1.0f);
}

TEST(Clipping, VertexExactlyOnTheNearPlane) {
  const PerspectiveSetup cam;
  const glm::dvec3 v[3] = {{-1.0, -1.0, -3.0}, {1.0, -1.0, -3.0}, {0.0, -0.1, -cam.znear}};
  check_view_space_triangle(v, "on the near plane");
}

TEST(Clipping, EntirelyBehindTheNearPlaneDrawsNothing) {
  const glm::dvec3 v[3] = {{-1.0, -1.0, -0.2}, {1.0, -1.0, -0.2}, {0.0, 1.0, 0.5}};
  int covered = -1;
  check_view_space_triangle(v, "behind near", &covered);
  EXPECT_EQ(covered, 0);
}

TEST(Clipping, BeyondTheFarPlaneIsClipped) {
  const glm::dvec3 v[3] = {{-5.0, -1.0, -50.0}, {5.0, -1.0, -50.0}, {0.0, -1.0, -400.0}};
  int covered = 0;
  check_view_space_triangle(v, "far crossing", &covered);
  EXPECT_GT(covered, 10);
}

TEST(Clipping, HugeTriangleBeyondTheGuardBandStillCoversTheScreenOnce) {
  // Two triangles spanning a million screen widths need guard-band clipping.
  const float r = 1e6f;
  const std::vector<glm::vec4> pos = {{-r, -r, 0.5f, 1.0f}, {r, -r, 0.5f, 1.0f},
                                      {r, r, 0.5f, 1.0f}, {-r, r, 0.5f, 1.0f}};
  const CountResult res = draw_counting(pos, {0, 1, 2, 0, 2, 3}, 64, 48);
  for (float c : res.counts) ASSERT_EQ(c, 1.0f);
  EXPECT_EQ(res.report.passes[0].geometry.triangles_clipped, 2u);
}

}  // namespace
}  // namespace ontile::test
