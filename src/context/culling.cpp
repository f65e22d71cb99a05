// Frustum and layer culling (see culling.h).
#include "context/culling.h"

#include <array>

namespace ontile {
namespace {

// Plane (a, b, c, d) with a*x + b*y + c*z + d >= 0 inside, from rows of the clip matrix
// (Gribb & Hartmann, "Fast Extraction of Viewing Frustum Planes", for z in [0, w]).
std::array<glm::dvec4, 6> frustum_planes(const glm::dmat4& m) {
  const glm::dvec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]);
  const glm::dvec4 r1(m[0][1], m[1][1], m[2][1], m[3][1]);
  const glm::dvec4 r2(m[0][2], m[1][2], m[2][2], m[3][2]);
  const glm::dvec4 r3(m[0][3], m[1][3], m[2][3], m[3][3]);
  return {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2};
}

// Bounds are float and come from a float transform of the corners (scene_renderers.cpp), so
// each coordinate may be a few float spacings inside the true box (a spacing is 1/16 unit at
// 1e6 from the origin). A box counts as outside only when it is farther out than 8 spacings of
// its largest coordinate (2^-20 relative), so culling stays conservative far from the origin.
constexpr double kBoundsRoundingRelative = 1.0 / (1 << 20);

bool box_outside(const std::array<glm::dvec4, 6>& planes, const Bounds& b) {
  const glm::dvec3 magnitude = glm::max(glm::abs(glm::dvec3(b.min)), glm::abs(glm::dvec3(b.max)));
  for (const glm::dvec4& p : planes) {
    // The box corner furthest along the plane normal (the "p-vertex").
    const glm::dvec3 v(p.x >= 0 ? b.max.x : b.min.x, p.y >= 0 ? b.max.y : b.min.y,
                       p.z >= 0 ? b.max.z : b.min.z);
    const double rounding_allowance =
        kBoundsRoundingRelative * glm::dot(glm::abs(glm::dvec3(p)), magnitude);
    if (p.x * v.x + p.y * v.y + p.z * v.z + p.w < -rounding_allowance) return true;
  }
  return false;
}

}  // namespace

bool box_outside_frustum(const glm::dmat4& view_projection, const Bounds& box) {
  return box_outside(frustum_planes(view_projection), box);
}

CullingResults cull_renderers(const std::vector<Renderer>& renderers, const CameraMatrices& camera,
                              const CullingParameters& params) {
  CullingResults r;
  r.camera = camera;
  r.renderers = &renderers;
  const auto planes = frustum_planes(camera.view_projection);
  for (uint32_t i = 0; i < renderers.size(); ++i) {
    const Renderer& rd = renderers[i];
    if (!((params.layer_mask >> (rd.layer & 31)) & 1u)) continue;
    if (rd.world_bounds.empty() || box_outside(planes, rd.world_bounds)) continue;
    r.visible.push_back(i);
  }
  return r;
}

}  // namespace ontile
