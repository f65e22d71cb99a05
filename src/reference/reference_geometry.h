// The reference renderer's ray-traced view of a scene (Embree 3): every renderer's triangles in
// world space, in the rasterizer's order, so a hit names the same primitive id the tiler uses.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "context/culling.h"

namespace ontile {

// One triangle a ray crosses, with the exact (double) distance along the ray.
struct RayCandidate {
  double t = 0.0;              // origin + t * direction lies on the triangle's plane
  uint32_t renderer = 0;       // index into the renderers the geometry was built from
  uint32_t triangle = 0;       // triangle index inside the renderer's mesh
  uint32_t primitive_id = 0;   // renderer's primitive_id_base + triangle
  bool front_facing = true;    // counter-clockwise as seen along the ray (glTF front face)
};

class ReferenceGeometry {
 public:
  // cull_modes[i] is the face culling renderer i is drawn with (the same the rasterizer uses):
  // hits on culled faces are never reported. Throws Error when Embree fails or when the scene
  // has 2^24 or more triangles (primitive ids must be exact as float AOVs).
  ReferenceGeometry(const std::vector<Renderer>& renderers, const std::vector<CullMode>& cull_modes);
  ~ReferenceGeometry();
  ReferenceGeometry(const ReferenceGeometry&) = delete;
  ReferenceGeometry& operator=(const ReferenceGeometry&) = delete;

  // Every non-culled triangle the ray origin + t * direction crosses with t in [0, t_max],
  // sorted by t, ties by primitive id (so the answer never depends on the BVH's traversal
  // order). Thread-safe.
  void intersect_all(const glm::dvec3& origin, const glm::dvec3& direction, double t_max,
                     std::vector<RayCandidate>& out) const;

  // World-space corners of a triangle (the renderer's double world matrix applied to its
  // object-space positions), in index order.
  std::array<glm::dvec3, 3> triangle_world(uint32_t renderer, uint32_t triangle) const;
  // The vertex indices of a triangle.
  std::array<uint32_t, 3> triangle_indices(uint32_t renderer, uint32_t triangle) const;
  // Finds the renderer and triangle of a primitive id; false when no triangle has that id.
  bool locate(uint32_t primitive_id, uint32_t& renderer, uint32_t& triangle) const;
  uint64_t triangle_count() const { return triangle_count_; }
  CullMode cull_mode(uint32_t renderer) const { return renderers_[renderer].cull; }
  uint32_t primitive_id_base(uint32_t renderer) const { return renderers_[renderer].primitive_id_base; }

 private:
  struct RendererGeometry {
    const MeshPrimitive* mesh = nullptr;
    uint32_t primitive_id_base = 0;
    CullMode cull = CullMode::Back;
    std::vector<glm::dvec3> world_positions;
  };
  struct EmbreeHandles;

  std::vector<RendererGeometry> renderers_;
  // Embree's float vertices and ray origins are relative to this point (double), near the
  // centre of the scene's bounds and 0 for a scene around the origin (see the constructor).
  // Far from the origin, float world coordinates would move the triangles Embree tests by up
  // to 1/32 unit at 1e6.
  glm::dvec3 embree_origin_{0.0};
  uint64_t triangle_count_ = 0;
  EmbreeHandles* embree_ = nullptr;
};

// Largest primitive id + 1 that a float AOV channel stores exactly (2^24).
constexpr uint64_t kMaxExactFloatPrimitiveIds = uint64_t{1} << 24;

}  // namespace ontile
