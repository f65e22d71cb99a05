// The vertex functor of the cartoon materials: MeshVertexShader's varyings (same indices) plus
// the view-space normal that MatCaps and the normal buffer need and the world tangent that
// normal mapping needs.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "scene/scene.h"

namespace ontile {

class ToonVertexShader final : public VertexShader {
 public:
  // Varying layout (the first 8 match MeshVertexShader).
  static constexpr int kNormal = 0;       // world-space normal (not normalised)
  static constexpr int kUv = 3;           // TEXCOORD_0 (0 when absent)
  static constexpr int kWorldPos = 5;     // world-space position
  static constexpr int kViewNormal = 8;   // view-space normal (not normalised)
  static constexpr int kTangent = 11;     // world tangent xyz + handedness w; 0 when absent
  static constexpr int kVaryingCount = 15;

  ToonVertexShader(const MeshPrimitive& primitive, const glm::dmat4& world,
                   const glm::dmat4& view, const glm::dmat4& view_projection);
  int varying_count() const override { return kVaryingCount; }
  void shade(uint32_t first, uint32_t count, glm::vec4* clip_positions,
             float* varyings) const override;
  // Bytes per vertex a GPU would fetch for this layout (position, normal, uv, tangent).
  uint32_t input_vertex_bytes() const;

 private:
  const MeshPrimitive& primitive_;
  glm::mat4 world_;
  glm::mat4 model_view_projection_;
  glm::mat3 normal_matrix_;       // world: inverse transpose of the model matrix
  glm::mat3 view_normal_matrix_;  // view: inverse transpose of the model-view matrix
  glm::mat3 tangent_matrix_;      // tangents are directions on the surface: the model matrix
  float handedness_sign_;         // -1 when the model matrix mirrors (negative determinant)
};

}  // namespace ontile
