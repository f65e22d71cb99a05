// Test helper: closed, consistently oriented (outward, counter-clockwise seen from outside)
// triangle meshes in double precision for watertightness tests: a UV sphere, a torus and a
// capped cylinder (a column), each with shared vertices so every edge has exactly one twin.
#pragma once
#include <cstdint>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace ontile::test {

struct ClosedMesh {
  std::vector<glm::dvec3> positions;
  std::vector<uint32_t> indices;
  bool convex = false;  // a ray then enters the solid at most once

  // Adds (a, b, c), flipped if needed so that its normal points away from `inside_point`.
  void add_outward(uint32_t a, uint32_t b, uint32_t c, const glm::dvec3& inside_point) {
    const glm::dvec3 &pa = positions[a], &pb = positions[b], &pc = positions[c];
    const glm::dvec3 normal = glm::cross(pb - pa, pc - pa);
    if (glm::dot(normal, (pa + pb + pc) / 3.0 - inside_point) < 0.0) std::swap(b, c);
    indices.insert(indices.end(), {a, b, c});
  }
  size_t triangle_count() const { return indices.size() / 3; }
};

// True when every directed edge (a, b) appears once and its twin (b, a) appears once: the mesh
// is a closed, consistently oriented 2-manifold, so the signed projected coverage (front minus
// back) is zero everywhere (the projection has degree 0).
inline bool is_closed_and_oriented(const ClosedMesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    for (int k = 0; k < 3; ++k) ++directed[{m.indices[t + k], m.indices[t + (k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    if (count != 1) return false;
    const auto twin = directed.find({edge.second, edge.first});
    if (twin == directed.end() || twin->second != 1) return false;
  }
  return true;
}

// Unit sphere: `stacks` latitude bands, `slices` longitudes, one vertex at each pole.
inline ClosedMesh uv_sphere(int stacks, int slices) {
  ClosedMesh m;
  m.convex = true;
  const double pi = std::numbers::pi;
  m.positions.push_back({0.0, 1.0, 0.0});
  for (int i = 1; i < stacks; ++i) {
    const double theta = pi * i / stacks;
    for (int j = 0; j < slices; ++j) {
      const double phi = 2.0 * pi * j / slices;
      m.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
    }
  }
  m.positions.push_back({0.0, -1.0, 0.0});
  const uint32_t south = static_cast<uint32_t>(m.positions.size() - 1);
  auto ring = [&](int i, int j) { return static_cast<uint32_t>(1 + (i - 1) * slices + (j % slices)); };
  const glm::dvec3 centre(0.0);
  for (int j = 0; j < slices; ++j) {
    m.add_outward(0, ring(1, j), ring(1, j + 1), centre);
    m.add_outward(south, ring(stacks - 1, j + 1), ring(stacks - 1, j), centre);
    for (int i = 1; i + 1 < stacks; ++i) {
      m.add_outward(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), centre);
      m.add_outward(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1), centre);
    }
  }
  return m;
}

// Torus around the y axis: main radius `major`, tube radius `minor`.
inline ClosedMesh torus(double major, double minor, int around, int tube) {
  ClosedMesh m;
  const double pi = std::numbers::pi;
  for (int i = 0; i < around; ++i) {
    const double u = 2.0 * pi * i / around;
    for (int j = 0; j < tube; ++j) {
      const double v = 2.0 * pi * j / tube;
      const double r = major + minor * std::cos(v);
      m.positions.push_back({r * std::cos(u), minor * std::sin(v), r * std::sin(u)});
    }
  }
  auto at = [&](int i, int j) { return static_cast<uint32_t>((i % around) * tube + (j % tube)); };
  for (int i = 0; i < around; ++i) {
    // The tube's centre line at the middle of this segment is inside every triangle's tube.
    const double u = 2.0 * pi * (i + 0.5) / around;
    const glm::dvec3 inside(major * std::cos(u), 0.0, major * std::sin(u));
    for (int j = 0; j < tube; ++j) {
      m.add_outward(at(i, j), at(i + 1, j), at(i + 1, j + 1), inside);
      m.add_outward(at(i, j), at(i + 1, j + 1), at(i, j + 1), inside);
    }
  }
  return m;
}

// A column: cylinder of `radius` from y = -half_height to +half_height with `rings` bands and
// flat caps drawn as fans around a centre vertex (long thin triangles meeting at one point).
inline ClosedMesh capped_cylinder(double radius, double half_height, int slices, int rings) {
  ClosedMesh m;
  m.convex = true;
  const double pi = std::numbers::pi;
  for (int k = 0; k <= rings; ++k) {
    const double y = -half_height + 2.0 * half_height * k / rings;
    for (int j = 0; j < slices; ++j) {
      const double phi = 2.0 * pi * j / slices;
      m.positions.push_back({radius * std::cos(phi), y, radius * std::sin(phi)});
    }
  }
  const uint32_t bottom = static_cast<uint32_t>(m.positions.size());
  m.positions.push_back({0.0, -half_height, 0.0});
  m.positions.push_back({0.0, half_height, 0.0});
  const uint32_t top = bottom + 1;
  auto at = [&](int k, int j) { return static_cast<uint32_t>(k * slices + (j % slices)); };
  const glm::dvec3 centre(0.0);
  for (int j = 0; j < slices; ++j) {
    m.add_outward(bottom, at(0, j), at(0, j + 1), centre);
    m.add_outward(top, at(rings, j + 1), at(rings, j), centre);
    for (int k = 0; k < rings; ++k) {
      m.add_outward(at(k, j), at(k + 1, j), at(k + 1, j + 1), centre);
      m.add_outward(at(k, j), at(k + 1, j + 1), at(k, j + 1), centre);
    }
  }
  return m;
}

}  // namespace ontile::test
