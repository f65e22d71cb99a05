// Test helper: a triangle given in view space under a perspective projection, with an exact
// (double precision) per-pixel expectation from a ray cast through each pixel centre.
#pragma once
#include <cmath>
#include <optional>

#include <glm/glm.hpp>

namespace ontile::test {

struct PerspectiveSetup {
  int width = 128, height = 96;
  double yfov = 1.0, znear = 0.5, zfar = 100.0;
  glm::dmat4 projection() const {
    const double f = 1.0 / std::tan(yfov / 2), aspect = double(width) / height;
    glm::dmat4 m(0.0);
    m[0][0] = f / aspect; m[1][1] = f; m[2][3] = -1.0;
    m[2][2] = zfar / (znear - zfar); m[3][2] = znear * zfar / (znear - zfar);
    return m;
  }
  // Ray direction (view space, not normalised) through the centre of pixel (x, y).
  glm::dvec3 ray(int x, int y) const {
    const double f = 1.0 / std::tan(yfov / 2), aspect = double(width) / height;
    const double ndc_x = (x + 0.5) / width * 2.0 - 1.0;
    const double ndc_y = 1.0 - (y + 0.5) / height * 2.0;
    return {ndc_x * aspect / f, ndc_y / f, -1.0};
  }
};

struct RayHit {
  double b0, b1, b2;  // barycentrics of the hit
  double view_depth;  // distance along -z
};

// Möller-Trumbore in double; nullopt when the ray is parallel to the plane.
inline std::optional<RayHit> intersect(const glm::dvec3& dir, const glm::dvec3 v[3]) {
  const glm::dvec3 e1 = v[1] - v[0], e2 = v[2] - v[0];
  const glm::dvec3 p = glm::cross(dir, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-300) return std::nullopt;
  const glm::dvec3 t0 = -v[0];
  const double u = glm::dot(t0, p) / det;
  const glm::dvec3 q = glm::cross(t0, e1);
  const double w = glm::dot(dir, q) / det;
  const double t = glm::dot(e2, q) / det;
  return RayHit{1.0 - u - w, u, w, t};
}

}  // namespace ontile::test
