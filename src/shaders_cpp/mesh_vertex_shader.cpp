// Standard mesh vertex functor (see mesh_vertex_shader.h).
#include "shaders_cpp/mesh_vertex_shader.h"

namespace ontile {

MeshVertexShader::MeshVertexShader(const MeshPrimitive& primitive, const glm::dmat4& world,
                                   const glm::dmat4& view_projection)
    : primitive_(primitive), world_(world), model_view_projection_(view_projection * world),
      // The inverse transpose keeps normals perpendicular under non-uniform scale.
      normal_matrix_(glm::transpose(glm::inverse(glm::dmat3(world)))) {}

void MeshVertexShader::shade(uint32_t first, uint32_t count, glm::vec4* clip, float* var) const {
  const bool has_normals = !primitive_.normals.empty();
  const bool has_uv = !primitive_.uv0.empty();
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t v = first + i;
    const glm::vec4 p(primitive_.positions[v], 1.0f);
    clip[i] = model_view_projection_ * p;
    const glm::vec3 n = has_normals ? normal_matrix_ * primitive_.normals[v] : glm::vec3(0, 0, 1);
    const glm::vec2 uv = has_uv ? primitive_.uv0[v] : glm::vec2(0.0f);
    const glm::vec3 wp(world_ * p);
    float* out = var + static_cast<size_t>(i) * kVaryingCount;
    out[kNormal] = n.x; out[kNormal + 1] = n.y; out[kNormal + 2] = n.z;
    out[kUv] = uv.x; out[kUv + 1] = uv.y;
    out[kWorldPos] = wp.x; out[kWorldPos + 1] = wp.y; out[kWorldPos + 2] = wp.z;
  }
}

uint32_t MeshVertexShader::input_vertex_bytes() const {
  uint32_t bytes = 12;  // position
  if (!primitive_.normals.empty()) bytes += 12;
  if (!primitive_.uv0.empty()) bytes += 8;
  return bytes;
}

}  // namespace ontile
