// Watertightness of closed meshes (sphere, torus, column) under 360 rotations with random
// subpixel offsets: the snapped, top-left-ruled coverage (D3D11 3.4.2.1) has no cracks and no
// double hits; front and back coverage agree at every pixel, as they must for a closed surface.
#include <gtest/gtest.h>

#include <numbers>

#include "support/closed_meshes.h"
#include "support/face_count_harness.h"
#include "support/projected_coverage.h"

namespace ontile::test {
namespace {

constexpr int kSizePx = 128;
constexpr double kYFov = 0.9, kNear = 0.5, kFar = 100.0, kDistance = 3.2;
// Pixels this close to a silhouette edge may go either way after snapping (see
// projected_coverage.h); the snap distance itself is 0.0028 px.
constexpr double kMarginPx = 0.05;

glm::dmat4 projection() {
  const double f = 1.0 / std::tan(kYFov / 2);
  glm::dmat4 m(0.0);
  m[0][0] = f;  // square target
  m[1][1] = f;
  m[2][3] = -1.0;
  m[2][2] = kFar / (kNear - kFar);
  m[3][2] = kNear * kFar / (kNear - kFar);
  return m;
}

// Rodrigues rotation about a unit axis.
glm::dmat3 rotation(const glm::dvec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const glm::dmat3 k(0.0, axis.z, -axis.y, -axis.z, 0.0, axis.x, axis.y, -axis.x, 0.0);
  return glm::dmat3(1.0) + s * k + (1.0 - c) * (k * k);
}

// Rotates about a tilted axis, pushes the mesh kDistance in front of the eye and shifts it by
// (dx, dy) pixels on screen; the result is rounded to float once, as a vertex shader would.
std::vector<glm::vec4> place(const ClosedMesh& mesh, double angle, double dx_px, double dy_px) {
  const glm::dmat3 r = rotation(glm::normalize(glm::dvec3(0.3, 1.0, 0.2)), angle);
  const glm::dmat4 p = projection();
  std::vector<glm::vec4> clip;
  clip.reserve(mesh.positions.size());
  for (const glm::dvec3& v : mesh.positions) {
    glm::dvec4 c = p * glm::dvec4(r * v + glm::dvec3(0.0, 0.0, -kDistance), 1.0);
    c.x += dx_px * 2.0 / kSizePx * c.w;
    c.y -= dy_px * 2.0 / kSizePx * c.w;
    clip.push_back(glm::vec4(c));
  }
  return clip;
}

// xorshift32: the same offsets on every platform.
struct Offsets {
  uint32_t state = 2463534242u;
  double next() {
    state ^= state << 13; state ^= state >> 17; state ^= state << 5;
    return (state & 0xFFFFFF) / double(0x1000000);
  }
};

struct Tally {
  int front_back_mismatch = 0, wrong_certain = 0, double_front = 0, non_integer = 0, bad_geometry = 0;
  long certain_covered = 0, certain_empty = 0, uncertain = 0;
};

void check_rotation(const ClosedMesh& mesh, double angle, double dx, double dy, Tally& tally) {
  const std::vector<glm::vec4> clip = place(mesh, angle, dx, dy);
  const FaceCounts counts = draw_face_counts(clip, mesh.indices, kSizePx, kSizePx);
  const ProjectedCoverage ref = projected_front_coverage(clip, mesh.indices, kSizePx, kSizePx, kMarginPx);
  const GeometryCounters& g = counts.report.passes[0].geometry;
  // Off-screen triangles are fine; clipping would cut the closed surface open.
  tally.bad_geometry += g.triangles_submitted != mesh.triangle_count() ||
                        g.triangles_clipped + g.triangles_non_finite != 0;
  for (size_t i = 0; i < counts.front.size(); ++i) {
    const float front = counts.front[i], back = counts.back[i];
    tally.non_integer += front != std::floor(front) || back != std::floor(back);
    tally.front_back_mismatch += front != back;
    tally.double_front += mesh.convex && front > 1.0f;
    if (ref.uncertain[i]) {
      ++tally.uncertain;
      continue;
    }
    tally.wrong_certain += front != static_cast<float>(ref.front[i]);
    (ref.front[i] > 0 ? tally.certain_covered : tally.certain_empty) += 1;
  }
}

// Runs the rotations first_degree, first_degree + step, ... below 360.
void check_mesh(const ClosedMesh& mesh, int first_degree, int step, const std::string& what) {
  ASSERT_TRUE(is_closed_and_oriented(mesh)) << what;
  Offsets offsets;
  Tally tally;
  int rotations = 0;
  for (int degree = first_degree; degree < 360; degree += step, ++rotations) {
    const double dx = offsets.next(), dy = offsets.next();
    check_rotation(mesh, degree * std::numbers::pi / 180.0, dx, dy, tally);
  }
  EXPECT_EQ(tally.bad_geometry, 0) << what;
  EXPECT_EQ(tally.non_integer, 0) << what;
  EXPECT_EQ(tally.front_back_mismatch, 0) << what << ": front and back coverage differ (crack or overlap)";
  EXPECT_EQ(tally.wrong_certain, 0) << what << ": coverage differs from the ray-cast expectation";
  EXPECT_EQ(tally.double_front, 0) << what << ": a convex mesh covered a pixel twice with front faces";
  // The expectation decides almost every pixel, and the object fills a good part of the target.
  const long pixels = long{kSizePx} * kSizePx * rotations;
  EXPECT_LT(tally.uncertain, pixels / 100) << what;
  EXPECT_GT(tally.certain_covered, pixels / 8) << what;
  EXPECT_GT(tally.certain_empty, pixels / 8) << what;
}

// Each mesh takes every third degree, so the three tests together cover all 360.
TEST(Watertight, UvSphereAtEveryThirdDegree) {
  check_mesh(uv_sphere(48, 96), 0, 3, "uv sphere");
}

TEST(Watertight, TorusAtEveryThirdDegree) {
  check_mesh(torus(1.0, 0.45, 96, 48), 1, 3, "torus");
}

TEST(Watertight, CappedColumnAtEveryThirdDegree) {
  check_mesh(capped_cylinder(0.6, 1.1, 96, 12), 2, 3, "capped column");
}

}  // namespace
}  // namespace ontile::test
