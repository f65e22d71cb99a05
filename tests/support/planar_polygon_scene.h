// Test helper: a convex planar polygon in view space (fan or grid triangulation) with a ray-cast
// expectation per pixel centre between near and far; pixels whose answer changes within
// kRobustRadiusPx are undecided (snapping moves edges by a few thousandths of a pixel).
#pragma once
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "support/view_space_triangle.h"

namespace ontile::test {

constexpr double kRobustRadiusPx = 0.02;

struct PlanarPolygon {
  glm::dvec3 origin, u, v;             // plane frame (u, v orthonormal)
  std::vector<glm::dvec2> corners;     // convex, counter-clockwise in (u, v)
  glm::dvec3 at(glm::dvec2 p) const { return origin + p.x * u + p.y * v; }

  bool contains(glm::dvec2 p) const {
    for (size_t i = 0; i < corners.size(); ++i) {
      const glm::dvec2 a = corners[i], b = corners[(i + 1) % corners.size()];
      if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < 0.0) return false;
    }
    return true;
  }
};

struct ViewTriangles {
  std::vector<glm::dvec3> positions;
  std::vector<uint32_t> indices;
};

// Fan around `centre` (plane coordinates, inside or on the polygon): one triangle per side.
inline ViewTriangles fan(const PlanarPolygon& poly, glm::dvec2 centre) {
  ViewTriangles t;
  t.positions.push_back(poly.at(centre));
  for (const glm::dvec2& c : poly.corners) t.positions.push_back(poly.at(c));
  const uint32_t n = static_cast<uint32_t>(poly.corners.size());
  for (uint32_t i = 0; i < n; ++i) t.indices.insert(t.indices.end(), {0u, 1 + i, 1 + (i + 1) % n});
  return t;
}

// cells x cells grid over a parallelogram polygon (corners 0, 1, 3 span it).
inline ViewTriangles grid(const PlanarPolygon& poly, int cells) {
  ViewTriangles t;
  const glm::dvec2 o = poly.corners[0], e1 = poly.corners[1] - o, e2 = poly.corners[3] - o;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) t.positions.push_back(poly.at(o + e1 * (double(i) / cells) + e2 * (double(j) / cells)));
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const uint32_t a = j * (cells + 1) + i, b = a + 1, c = a + cells + 1, d = c + 1;
      t.indices.insert(t.indices.end(), {a, b, d, a, d, c});
    }
  }
  return t;
}

// Ray through screen point (x, y) in pixels (y down), view space, not normalised.
inline glm::dvec3 ray_through(const PerspectiveSetup& cam, double x, double y) {
  const double f = 1.0 / std::tan(cam.yfov / 2), aspect = double(cam.width) / cam.height;
  return {(x / cam.width * 2.0 - 1.0) * aspect / f, (1.0 - y / cam.height * 2.0) / f, -1.0};
}

// True when the ray hits the polygon at a view depth within [near, far].
inline bool ray_hits(const PerspectiveSetup& cam, const PlanarPolygon& poly, double x, double y) {
  const glm::dvec3 d = ray_through(cam, x, y);
  const glm::dvec3 n = glm::cross(poly.u, poly.v);
  const double denom = glm::dot(n, d);
  if (denom == 0.0) return false;
  const double t = glm::dot(n, poly.origin) / denom;  // eye at the origin
  if (!(t > 0.0)) return false;
  const glm::dvec3 hit = t * d;
  const double depth = -hit.z;
  if (depth < cam.znear || depth > cam.zfar) return false;
  const glm::dvec3 rel = hit - poly.origin;
  return poly.contains({glm::dot(rel, poly.u), glm::dot(rel, poly.v)});
}

// 1 covered, 0 empty, nullopt undecided (the answer changes within the robust radius).
inline std::optional<int> expected_coverage(const PerspectiveSetup& cam, const PlanarPolygon& poly, int px, int py) {
  const double cx = px + 0.5, cy = py + 0.5;
  const bool centre = ray_hits(cam, poly, cx, cy);
  for (int k = 0; k < 8; ++k) {
    const double a = k * 0.7853981633974483;
    if (ray_hits(cam, poly, cx + kRobustRadiusPx * std::cos(a), cy + kRobustRadiusPx * std::sin(a)) != centre) {
      return std::nullopt;
    }
  }
  return centre ? 1 : 0;
}

}  // namespace ontile::test
