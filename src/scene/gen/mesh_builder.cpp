// Parametric-surface mesh assembly for the procedural scene generators (see mesh_builder.h).
#include "scene/gen/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "util/error.h"

namespace ontile::gen {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Radii this close to zero are snapped to exactly zero so that a ring on the axis collapses
// to one point and its zero-area triangles are dropped by add_surface_grid.
constexpr float kAxisSnapRadius = 1e-6f;

glm::vec3 any_perpendicular(const glm::vec3& n) {
  const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(axis, n));
}

}  // namespace

int scaled_segments(double base, double scale, int minimum) {
  return std::max(minimum, static_cast<int>(std::lround(base * scale)));
}

void add_surface_grid(MeshData& mesh, int cols, int rows,
                      const std::function<SurfacePoint(int col, int row)>& eval,
                      const glm::mat4& transform) {
  if (cols < 1 || rows < 1) {
    throw Error("scene generator: surface grid needs at least 1x1 cells, got " +
                std::to_string(cols) + "x" + std::to_string(rows));
  }
  const size_t base = mesh.positions.size();
  const size_t grid_vertices = static_cast<size_t>(cols + 1) * static_cast<size_t>(rows + 1);
  if (base + grid_vertices > std::numeric_limits<uint32_t>::max()) {
    throw Error("scene generator: mesh exceeds 2^32 vertices");
  }
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  for (int row = 0; row <= rows; ++row) {
    for (int col = 0; col <= cols; ++col) {
      const SurfacePoint p = eval(col, row);
      mesh.positions.push_back(glm::vec3(transform * glm::vec4(p.position, 1.0f)));
      const glm::vec3 n = normal_matrix * p.normal;
      const float length = glm::length(n);
      // Callers give non-zero normals; the fallback only keeps a degenerate input finite.
      mesh.normals.push_back(length > 0.0f ? n / length : glm::vec3(0.0f, 1.0f, 0.0f));
      mesh.uvs.push_back(p.uv);
    }
  }
  const auto vertex = [&](int col, int row) {
    return static_cast<uint32_t>(base + static_cast<size_t>(row) * (cols + 1) + col);
  };
  // Pick the winding once per grid: the one whose geometric normals agree with the vertex
  // normals summed over all cells (glTF: counter-clockwise is the front face).
  double agreement = 0.0;
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col < cols; ++col) {
      const uint32_t a = vertex(col, row), b = vertex(col + 1, row), c = vertex(col + 1, row + 1);
      const glm::vec3 g = glm::cross(mesh.positions[b] - mesh.positions[a],
                                     mesh.positions[c] - mesh.positions[a]);
      agreement += glm::dot(g, mesh.normals[a] + mesh.normals[b] + mesh.normals[c]);
    }
  }
  const bool flip = agreement < 0.0;
  const auto emit = [&](uint32_t a, uint32_t b, uint32_t c) {
    const glm::vec3 g = glm::cross(mesh.positions[b] - mesh.positions[a],
                                   mesh.positions[c] - mesh.positions[a]);
    if (g == glm::vec3(0.0f)) return;
    mesh.indices.push_back(a);
    mesh.indices.push_back(flip ? c : b);
    mesh.indices.push_back(flip ? b : c);
  };
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col < cols; ++col) {
      const uint32_t a = vertex(col, row), b = vertex(col + 1, row);
      const uint32_t c = vertex(col + 1, row + 1), d = vertex(col, row + 1);
      emit(a, b, c);
      emit(a, c, d);
    }
  }
}

void add_quad(MeshData& mesh, const glm::vec3& corner, const glm::vec3& edge_u,
              const glm::vec3& edge_v, int cols, int rows, float uv_metres_per_repeat,
              const glm::mat4& transform) {
  const glm::vec3 normal = glm::normalize(glm::cross(edge_u, edge_v));
  const float length_u = glm::length(edge_u), length_v = glm::length(edge_v);
  add_surface_grid(
      mesh, cols, rows,
      [&](int col, int row) {
        const float fu = static_cast<float>(col) / static_cast<float>(cols);
        const float fv = static_cast<float>(row) / static_cast<float>(rows);
        return SurfacePoint{corner + edge_u * fu + edge_v * fv, normal,
                            glm::vec2(fu * length_u, fv * length_v) / uv_metres_per_repeat};
      },
      transform);
}

void add_box(MeshData& mesh, const glm::vec3& min_corner, const glm::vec3& max_corner,
             float cells_per_metre, float uv_metres_per_repeat, unsigned face_mask,
             const glm::mat4& transform) {
  const glm::vec3 lo = min_corner, hi = max_corner, size = max_corner - min_corner;
  const auto cells = [&](float extent_m) {
    return std::max(1, static_cast<int>(std::ceil(extent_m * cells_per_metre)));
  };
  struct Face {
    unsigned bit;
    glm::vec3 corner, edge_u, edge_v;
  };
  // Each face's cross(edge_u, edge_v) points out of the box.
  const Face faces[] = {
      {kBoxNegX, {lo.x, lo.y, lo.z}, {0, 0, size.z}, {0, size.y, 0}},
      {kBoxPosX, {hi.x, lo.y, hi.z}, {0, 0, -size.z}, {0, size.y, 0}},
      {kBoxNegY, {lo.x, lo.y, lo.z}, {size.x, 0, 0}, {0, 0, size.z}},
      {kBoxPosY, {lo.x, hi.y, hi.z}, {size.x, 0, 0}, {0, 0, -size.z}},
      {kBoxNegZ, {hi.x, lo.y, lo.z}, {-size.x, 0, 0}, {0, size.y, 0}},
      {kBoxPosZ, {lo.x, lo.y, hi.z}, {size.x, 0, 0}, {0, size.y, 0}},
  };
  for (const Face& face : faces) {
    if ((face_mask & face.bit) == 0) continue;
    add_quad(mesh, face.corner, face.edge_u, face.edge_v, cells(glm::length(face.edge_u)),
             cells(glm::length(face.edge_v)), uv_metres_per_repeat, transform);
  }
}

ProfileRun profile_line(const glm::vec2& from, const glm::vec2& to, int segments) {
  const glm::vec2 direction = glm::normalize(to - from);
  const glm::vec2 normal(direction.y, -direction.x);
  ProfileRun run;
  for (int i = 0; i <= segments; ++i) {
    const float t = static_cast<float>(i) / static_cast<float>(segments);
    run.push_back({from + (to - from) * t, normal});
  }
  return run;
}

ProfileRun profile_arc(const glm::vec2& center, float radius, float from_angle_rad,
                       float to_angle_rad, int segments) {
  const double sweep = static_cast<double>(to_angle_rad) - from_angle_rad;
  const float direction = sweep >= 0.0 ? 1.0f : -1.0f;
  ProfileRun run;
  for (int i = 0; i <= segments; ++i) {
    const double angle = from_angle_rad + sweep * i / segments;
    const glm::vec2 radial(static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)));
    glm::vec2 point = center + radial * radius;
    if (std::abs(point.x) < kAxisSnapRadius) point.x = 0.0f;
    // Right-hand perpendicular of the travel direction (-sin, cos) * direction.
    run.push_back({point, radial * direction});
  }
  return run;
}

ProfileRun profile_curve(const std::function<glm::dvec2(double t)>& curve, int segments) {
  constexpr double kStep = 1e-5;
  ProfileRun run;
  for (int i = 0; i <= segments; ++i) {
    const double t = static_cast<double>(i) / segments;
    const glm::dvec2 tangent = curve(t + kStep) - curve(t - kStep);
    glm::vec2 point(curve(t));
    if (std::abs(point.x) < kAxisSnapRadius) point.x = 0.0f;
    run.push_back({point, glm::vec2(glm::normalize(glm::dvec2(tangent.y, -tangent.x)))});
  }
  return run;
}

void add_lathe(MeshData& mesh, const std::vector<ProfileRun>& runs, int radial_segments,
               float u_repeats, float v_metres_per_repeat, const glm::mat4& transform) {
  std::vector<double> sines(radial_segments + 1), cosines(radial_segments + 1);
  for (int col = 0; col <= radial_segments; ++col) {
    // The last column repeats the first angle exactly so the seam is watertight.
    const double angle = 2.0 * kPi * (col % radial_segments) / radial_segments;
    sines[col] = std::sin(angle);
    cosines[col] = std::cos(angle);
  }
  float arc_length_m = 0.0f;
  for (const ProfileRun& run : runs) {
    std::vector<float> v_of_point(run.size());
    for (size_t i = 0; i < run.size(); ++i) {
      if (i > 0) arc_length_m += glm::length(run[i].radius_height - run[i - 1].radius_height);
      v_of_point[i] = arc_length_m / v_metres_per_repeat;
    }
    add_surface_grid(
        mesh, radial_segments, static_cast<int>(run.size()) - 1,
        [&](int col, int row) {
          const ProfilePoint& p = run[row];
          const float s = static_cast<float>(sines[col]), c = static_cast<float>(cosines[col]);
          const float r = p.radius_height.x;
          return SurfacePoint{glm::vec3(r * s, p.radius_height.y, r * c),
                              glm::vec3(p.normal.x * s, p.normal.y, p.normal.x * c),
                              glm::vec2(u_repeats * static_cast<float>(col) / radial_segments,
                                        v_of_point[row])};
        },
        transform);
  }
}

void add_sphere(MeshData& mesh, const glm::vec3& center, float radius, int radial_segments,
                int rings) {
  const float half_pi = static_cast<float>(kPi / 2);
  add_lathe(mesh, {profile_arc({0.0f, 0.0f}, radius, -half_pi, half_pi, rings)}, radial_segments,
            1.0f, static_cast<float>(kPi) * radius, glm::translate(glm::mat4(1.0f), center));
}

void add_torus(MeshData& mesh, const glm::mat4& transform, float major_radius,
               float minor_radius, int major_segments, int minor_segments) {
  const float pi = static_cast<float>(kPi);
  add_lathe(mesh, {profile_arc({major_radius, 0.0f}, minor_radius, -pi, pi, minor_segments)},
            major_segments, 2.0f, 2.0f * pi * minor_radius, transform);
}

void add_cylinder(MeshData& mesh, const glm::mat4& transform, float radius, float height,
                  int radial_segments, int height_segments) {
  const std::vector<ProfileRun> runs = {
      profile_line({0.0f, 0.0f}, {radius, 0.0f}, 1),
      profile_line({radius, 0.0f}, {radius, height}, height_segments),
      profile_line({radius, height}, {0.0f, height}, 1)};
  add_lathe(mesh, runs, radial_segments, 1.0f, height + 2.0f * radius, transform);
}

void add_capsule(MeshData& mesh, const glm::mat4& transform, float radius, float height,
                 int radial_segments, int cap_rings) {
  const float half_pi = static_cast<float>(kPi / 2);
  const std::vector<ProfileRun> runs = {
      profile_arc({0.0f, radius}, radius, -half_pi, 0.0f, cap_rings),
      profile_line({radius, radius}, {radius, height - radius}, 2),
      profile_arc({0.0f, height - radius}, radius, 0.0f, half_pi, cap_rings)};
  add_lathe(mesh, runs, radial_segments, 1.0f, height, transform);
}

void compute_tangents(MeshData& mesh) {
  const size_t n = mesh.positions.size();
  std::vector<glm::vec3> along_u(n, glm::vec3(0.0f)), along_v(n, glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    const glm::vec3 e1 = mesh.positions[i1] - mesh.positions[i0];
    const glm::vec3 e2 = mesh.positions[i2] - mesh.positions[i0];
    const glm::vec2 d1 = mesh.uvs[i1] - mesh.uvs[i0];
    const glm::vec2 d2 = mesh.uvs[i2] - mesh.uvs[i0];
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (det == 0.0f) continue;  // no UV area: the triangle says nothing about directions
    const glm::vec3 du = (e1 * d2.y - e2 * d1.y) / det;
    const glm::vec3 dv = (e2 * d1.x - e1 * d2.x) / det;
    for (uint32_t i : {i0, i1, i2}) {
      along_u[i] += du;
      along_v[i] += dv;
    }
  }
  mesh.tangents.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3& normal = mesh.normals[i];
    glm::vec3 t = along_u[i] - normal * glm::dot(normal, along_u[i]);
    const float length = glm::length(t);
    t = length > 1e-12f ? t / length : any_perpendicular(normal);
    const float handedness = glm::dot(glm::cross(normal, t), along_v[i]) < 0.0f ? -1.0f : 1.0f;
    mesh.tangents[i] = glm::vec4(t, handedness);
  }
}

}  // namespace ontile::gen
