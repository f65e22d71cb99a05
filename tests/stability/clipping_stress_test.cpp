// Clipping stress beyond tests/raster/clipping_test.cpp: meshes through near, far and guard-band
// planes, fans around a w = 0 or near-plane vertex, enormous rotated triangles, triangles behind
// the eye; decided pixels match the ray cast exactly and none is covered twice.
#include <gtest/gtest.h>

#include "support/planar_polygon_scene.h"
#include "support/raster_harness.h"

namespace ontile::test {
namespace {

struct Outcome {
  int covered = 0, wrong = 0, undecided = 0, not_zero_or_one = 0;
  GeometryCounters geometry;
};

Outcome render_and_compare(const ViewTriangles& tris, const PlanarPolygon& poly) {
  const PerspectiveSetup cam;
  const glm::dmat4 proj = cam.projection();
  std::vector<glm::vec4> clip;
  for (const glm::dvec3& p : tris.positions) clip.push_back(glm::vec4(proj * glm::dvec4(p, 1.0)));
  const CountResult r = draw_counting(clip, tris.indices, cam.width, cam.height);
  Outcome o;
  o.geometry = r.report.passes[0].geometry;
  for (int y = 0; y < cam.height; ++y) {
    for (int x = 0; x < cam.width; ++x) {
      const float c = r.at(x, y, cam.width);
      o.not_zero_or_one += c != 0.0f && c != 1.0f;
      o.covered += c == 1.0f;
      const std::optional<int> expected = expected_coverage(cam, poly, x, y);
      if (!expected) { ++o.undecided; continue; }
      o.wrong += c != static_cast<float>(*expected);
    }
  }
  return o;
}

void expect_exact(const Outcome& o, const std::string& what, int min_covered) {
  EXPECT_EQ(o.not_zero_or_one, 0) << what << ": a pixel covered twice (crack-free but overlapping)";
  EXPECT_EQ(o.wrong, 0) << what;
  EXPECT_GE(o.covered, min_covered) << what;
  EXPECT_LT(o.undecided, 200) << what;  // of 12288 pixels
  EXPECT_EQ(o.geometry.triangles_non_finite, 0u) << what;
}

// The ground y = -1 as a rectangle in a frame rotated by `yaw` about the vertical.
PlanarPolygon ground(double yaw, double x0, double x1, double z0, double z1) {
  PlanarPolygon p;
  p.origin = {0.0, -1.0, 0.0};
  p.u = {std::cos(yaw), 0.0, -std::sin(yaw)};
  p.v = {-std::sin(yaw), 0.0, -std::cos(yaw)};  // u x v = +y: seen from above, counter-clockwise
  p.corners = {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}};
  return p;
}

TEST(ClippingStress, GroundGridThroughNearAndFarPlanesIsWatertight) {
  // 48 x 48 cells from 6 units behind the eye to 160 ahead (far = 100); cells straddle both
  // planes, and the ones behind the eye have vertices with w < 0.
  for (double yaw : {0.0, 0.37, 1.1}) {
    const PlanarPolygon g = ground(yaw, -40.0, 40.0, -6.0, 160.0);
    const Outcome o = render_and_compare(grid(g, 48), g);
    expect_exact(o, "yaw " + std::to_string(yaw), 3000);
    EXPECT_GT(o.geometry.triangles_clipped, 0u);
    EXPECT_GT(o.geometry.triangles_outside, 0u);
  }
}

TEST(ClippingStress, EnormousGroundTrianglesNeedNearFarAndGuardBandClipping) {
  // Two triangles a million units across: clipped by near, far and guard-band planes at once.
  for (double yaw : {0.0, 0.61}) {
    const PlanarPolygon g = ground(yaw, -1e6, 1e6, -1e6, 1e6);
    const Outcome two = render_and_compare(grid(g, 1), g);
    expect_exact(two, "2 triangles, yaw " + std::to_string(yaw), 5000);
    EXPECT_EQ(two.geometry.triangles_clipped, 2u);
    const Outcome many = render_and_compare(grid(g, 8), g);
    expect_exact(many, "8x8 grid, yaw " + std::to_string(yaw), 5000);
    EXPECT_EQ(many.covered, two.covered) << "the same surface, tessellated differently";
  }
}

// A tilted plane through the eye plane: the fan centre has view z = 0, so clip w = 0 exactly.
TEST(ClippingStress, FanAroundAVertexInTheEyePlane) {
  PlanarPolygon p;
  p.origin = {0.4, -0.6, 0.0};
  p.u = glm::normalize(glm::dvec3(1.0, 0.2, 0.0));
  p.v = glm::normalize(glm::dvec3(0.0, 0.3, -1.0));
  p.v = glm::normalize(p.v - glm::dot(p.v, p.u) * p.u);
  p.corners = {{-3.0, -2.0}, {2.0, -2.5}, {3.5, 4.0}, {0.5, 6.0}, {-2.5, 5.0}};
  const ViewTriangles t = fan(p, {0.0, 0.0});
  ASSERT_EQ((PerspectiveSetup{}.projection() * glm::dvec4(t.positions[0], 1.0)).w, 0.0)
      << "the shared vertex must have w = 0";
  const Outcome o = render_and_compare(t, p);
  expect_exact(o, "eye-plane fan", 500);
}

// The fan centre lies exactly on the near plane (clip z = 0 after rounding).
TEST(ClippingStress, FanAroundAVertexOnTheNearPlane) {
  const PerspectiveSetup cam;
  PlanarPolygon p;
  p.origin = {-0.1, 0.05, -cam.znear};
  p.u = glm::normalize(glm::dvec3(1.0, 0.0, -0.3));
  p.v = glm::normalize(glm::dvec3(0.0, 1.0, -0.5));
  p.v = glm::normalize(p.v - glm::dot(p.v, p.u) * p.u);
  p.corners = {{-2.0, -2.0}, {2.0, -2.5}, {2.5, 2.0}, {-1.5, 2.5}};
  const ViewTriangles t = fan(p, {0.0, 0.0});
  const glm::vec4 centre_clip(cam.projection() * glm::dvec4(t.positions[0], 1.0));
  ASSERT_EQ(centre_clip.z, 0.0f);
  expect_exact(render_and_compare(t, p), "near-plane fan", 2000);
}

// Clip space, w = 1: squares a million target widths across, rotated, split along a diagonal
// that crosses the target at an arbitrary angle. Guard-band clipping must keep the shared edge
// watertight: every pixel exactly once.
TEST(ClippingStress, EnormousRotatedSquaresCoverTheTargetExactlyOnce) {
  constexpr int kW = 64, kH = 48;
  for (double angle : {0.1, 0.785398, 1.3, 2.9}) {
    const glm::dvec2 centre(0.13, -0.27);  // in NDC: the diagonal passes inside the target
    const double r = 2e6;                  // NDC units: a million target widths
    std::vector<glm::vec4> pos;
    for (int k = 0; k < 4; ++k) {
      const double a = angle + k * 1.5707963267948966;
      pos.push_back(glm::vec4(float(centre.x + r * std::cos(a)), float(centre.y + r * std::sin(a)), 0.5f, 1.0f));
    }
    const CountResult res = draw_counting(pos, {0, 1, 2, 0, 2, 3}, kW, kH);
    int not_once = 0;
    for (float c : res.counts) not_once += c != 1.0f;
    EXPECT_EQ(not_once, 0) << "angle " << angle;
    EXPECT_EQ(res.report.passes[0].geometry.triangles_clipped, 2u);
  }
}

// A single enormous triangle whose edge crosses the target: covered pixels are exactly those on
// the inside of that edge's line (in double from the float vertices). Guard-band intersections
// of vertices ~1e6 apart must be computed in double: in float they shift this edge by 0.18 px.
TEST(ClippingStress, EnormousTriangleEdgeThroughTheTargetMatchesItsLine) {
  constexpr int kW = 64, kH = 48;
  const std::vector<glm::vec4> pos = {{-3e6f, -1.1e6f, 0.5f, 1.0f}, {2.7e6f, 0.99e6f, 0.5f, 1.0f}, {-1e6f, 4e6f, 0.5f, 1.0f}};
  const CountResult res = draw_counting(pos, {0, 1, 2}, kW, kH);
  int wrong = 0, undecided = 0, covered = 0;
  // Screen coordinates in double (y down) of the two vertices of the crossing edge.
  auto screen = [&](const glm::vec4& p) { return glm::dvec2((p.x * 0.5 + 0.5) * kW, (0.5 - p.y * 0.5) * kH); };
  const glm::dvec2 a = screen(pos[0]), b = screen(pos[1]);
  const glm::dvec2 inside_point = screen(pos[2]);
  auto side = [&](glm::dvec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
  const double inside_sign = side(inside_point) > 0.0 ? 1.0 : -1.0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const double distance_px = inside_sign * side({x + 0.5, y + 0.5}) / glm::length(b - a);
      const float c = res.at(x, y, kW);
      covered += c == 1.0f;
      if (std::abs(distance_px) < kRobustRadiusPx) { ++undecided; continue; }
      wrong += c != (distance_px > 0.0 ? 1.0f : 0.0f);
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_LT(undecided, 4);
  EXPECT_GT(covered, 200);
  EXPECT_LT(covered, kW * kH - 200);
}

// Every vertex behind the eye (w < 0): x / w and y / w land on screen, z / w in [0, 1], yet the
// triangle is invisible. Nothing may be drawn.
TEST(ClippingStress, TrianglesWhollyBehindTheEyeDrawNothing) {
  const std::vector<glm::vec4> pos = {{0.5f, 0.5f, -0.5f, -1.0f}, {-0.5f, 0.3f, -0.4f, -1.0f}, {0.1f, -0.6f, -1.5f, -2.0f},
                                      {-1e6f, -1e6f, -0.5f, -1.0f}, {1e6f, -1e6f, -0.5f, -1.0f}, {0.0f, 1e6f, -0.5f, -1.0f}};
  const CountResult res = draw_counting(pos, {0, 1, 2, 3, 4, 5}, 64, 48);
  for (float c : res.counts) ASSERT_EQ(c, 0.0f);
  EXPECT_EQ(res.report.passes[0].geometry.triangles_outside, 2u);
}

}  // namespace
}  // namespace ontile::test
