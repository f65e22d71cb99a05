// Triangle-mesh assembly for the procedural scene generators: vertex streams, parametric grids,
// boxes, quads and surfaces of revolution (spheres, tori, capsules, columns, vases).
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

namespace ontile::gen {

// Indexed triangle list with the glTF vertex streams the generators emit (POSITION, NORMAL,
// TANGENT, TEXCOORD_0). Normals are unit length; tangents are filled by compute_tangents().
struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  std::vector<glm::vec4> tangents;
  std::vector<uint32_t> indices;
  size_t vertex_count() const { return positions.size(); }
  size_t triangle_count() const { return indices.size() / 3; }
};

struct SurfacePoint {
  glm::vec3 position;
  glm::vec3 normal;  // need not be normalised; transformed and normalised on append
  glm::vec2 uv;
};

// Appends a (cols+1) x (rows+1) vertex grid whose vertex (col, row) is eval(col, row), two
// triangles per cell. Triangles are wound counter-clockwise seen from the side the normals
// point to (glTF front faces); triangles of exactly zero area (poles, collapsed rows) are skipped.
void add_surface_grid(MeshData& mesh, int cols, int rows,
                      const std::function<SurfacePoint(int col, int row)>& eval,
                      const glm::mat4& transform = glm::mat4(1.0f));

// A flat quad corner, corner+edge_u, corner+edge_u+edge_v, corner+edge_v split into cols x rows
// cells; normal = normalize(cross(edge_u, edge_v)); uv = distance along the edges in metres
// divided by uv_metres_per_repeat.
void add_quad(MeshData& mesh, const glm::vec3& corner, const glm::vec3& edge_u,
              const glm::vec3& edge_v, int cols, int rows, float uv_metres_per_repeat,
              const glm::mat4& transform = glm::mat4(1.0f));

// Axis-aligned box with flat faces, each face split into ceil(extent * cells_per_metre) cells
// per side (at least one). Faces whose bit is clear in face_mask are left out.
enum BoxFace : unsigned {
  kBoxNegX = 1u, kBoxPosX = 2u, kBoxNegY = 4u, kBoxPosY = 8u, kBoxNegZ = 16u, kBoxPosZ = 32u,
  kBoxAllFaces = 63u
};
void add_box(MeshData& mesh, const glm::vec3& min_corner, const glm::vec3& max_corner,
             float cells_per_metre, float uv_metres_per_repeat, unsigned face_mask = kBoxAllFaces,
             const glm::mat4& transform = glm::mat4(1.0f));

// A profile point of a surface of revolution about +Y: (radius, height) and the outward unit
// normal in that half plane.
struct ProfilePoint {
  glm::vec2 radius_height;
  glm::vec2 normal;
};
// One smooth piece of a profile; consecutive runs meet at a crease.
using ProfileRun = std::vector<ProfilePoint>;

// Profile pieces run from the axis at the bottom, outwards, up, and back to the axis at the top,
// so the solid is on the left of the direction of travel; the normals are then the right-hand
// perpendiculars of that direction (outward for convex and concave pieces alike).
ProfileRun profile_line(const glm::vec2& from, const glm::vec2& to, int segments);
ProfileRun profile_arc(const glm::vec2& center, float radius, float from_angle_rad,
                       float to_angle_rad, int segments);

// A smooth run along curve(t) = (radius, height) for t in [0, 1], normals from the curve's
// derivative (central differences in double precision).
ProfileRun profile_curve(const std::function<glm::dvec2(double t)>& curve, int segments);

// Revolves the runs about +Y with radial_segments around. u = angle / 2pi * u_repeats,
// v = profile arc length / v_metres_per_repeat.
void add_lathe(MeshData& mesh, const std::vector<ProfileRun>& runs, int radial_segments,
               float u_repeats, float v_metres_per_repeat,
               const glm::mat4& transform = glm::mat4(1.0f));

void add_sphere(MeshData& mesh, const glm::vec3& center, float radius, int radial_segments,
                int rings);
void add_torus(MeshData& mesh, const glm::mat4& transform, float major_radius,
               float minor_radius, int major_segments, int minor_segments);
// Capped cylinder or capsule standing on its base at the origin of transform.
void add_cylinder(MeshData& mesh, const glm::mat4& transform, float radius, float height,
                  int radial_segments, int height_segments);
void add_capsule(MeshData& mesh, const glm::mat4& transform, float radius, float height,
                 int radial_segments, int cap_rings);

// Per-vertex tangents from the UV layout (glTF TANGENT: xyz along +u, w = +-1 so that
// cross(normal, tangent.xyz) * w points along +v), Gram-Schmidt orthogonalised to the normal.
void compute_tangents(MeshData& mesh);

// max(minimum, round(base * scale)): tessellation counts that grow with the triangle budget.
int scaled_segments(double base, double scale, int minimum);

}  // namespace ontile::gen
