// The standard vertex functor for scene meshes: object -> clip space with a double-precision
// model-view-projection, and world-space normal, UV and position as varyings.
#pragma once
#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "scene/scene.h"

namespace ontile {

class MeshVertexShader final : public VertexShader {
 public:
  // Varying layout.
  static constexpr int kNormal = 0;    // world-space normal (not normalised)
  static constexpr int kUv = 3;        // TEXCOORD_0 (0 when absent)
  static constexpr int kWorldPos = 5;  // world-space position
  static constexpr int kVaryingCount = 8;

  MeshVertexShader(const MeshPrimitive& primitive, const glm::dmat4& world,
                   const glm::dmat4& view_projection);
  int varying_count() const override { return kVaryingCount; }
  void shade(uint32_t first, uint32_t count, glm::vec4* clip_positions,
             float* varyings) const override;
  // Bytes per vertex a GPU would fetch for this layout (position, normal, uv).
  uint32_t input_vertex_bytes() const;

 private:
  const MeshPrimitive& primitive_;
  glm::mat4 world_;
  glm::mat4 model_view_projection_;
  glm::mat3 normal_matrix_;
};

}  // namespace ontile
