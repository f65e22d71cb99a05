// Cartoon vertex functor (see toon_vertex_shader.h).
#include "shaders_cpp/toon/toon_vertex_shader.h"

namespace ontile {

ToonVertexShader::ToonVertexShader(const MeshPrimitive& primitive, const glm::dmat4& world,
                                   const glm::dmat4& view, const glm::dmat4& view_projection)
    : primitive_(primitive), world_(world), model_view_projection_(view_projection * world),
      // The inverse transpose keeps normals perpendicular under non-uniform scale.
      normal_matrix_(glm::transpose(glm::inverse(glm::dmat3(world)))),
      view_normal_matrix_(glm::transpose(glm::inverse(glm::dmat3(view * world)))),
      tangent_matrix_(glm::dmat3(world)),
      // glTF 2.0 3.7.2.1: bitangent = cross(normal, tangent.xyz) * w. A mirroring transform flips
      // the cross product, so w flips with it (Unity's unity_WorldTransformParams.w does the same).
      handedness_sign_(glm::determinant(glm::dmat3(world)) < 0.0 ? -1.0f : 1.0f) {}

void ToonVertexShader::shade(uint32_t first, uint32_t count, glm::vec4* clip, float* var) const {
  const bool has_normals = !primitive_.normals.empty();
  const bool has_uv = !primitive_.uv0.empty();
  const bool has_tangents = !primitive_.tangents.empty();
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t v = first + i;
    const glm::vec4 p(primitive_.positions[v], 1.0f);
    clip[i] = model_view_projection_ * p;
    const glm::vec3 object_normal = has_normals ? primitive_.normals[v] : glm::vec3(0, 0, 1);
    const glm::vec3 n = normal_matrix_ * object_normal;
    const glm::vec3 vn = view_normal_matrix_ * object_normal;
    const glm::vec2 uv = has_uv ? primitive_.uv0[v] : glm::vec2(0.0f);
    const glm::vec3 wp(world_ * p);
    glm::vec4 t(0.0f);
    if (has_tangents) {
      const glm::vec4& object_tangent = primitive_.tangents[v];
      t = glm::vec4(tangent_matrix_ * glm::vec3(object_tangent), object_tangent.w * handedness_sign_);
    }
    float* out = var + static_cast<size_t>(i) * kVaryingCount;
    out[kNormal] = n.x; out[kNormal + 1] = n.y; out[kNormal + 2] = n.z;
    out[kUv] = uv.x; out[kUv + 1] = uv.y;
    out[kWorldPos] = wp.x; out[kWorldPos + 1] = wp.y; out[kWorldPos + 2] = wp.z;
    out[kViewNormal] = vn.x; out[kViewNormal + 1] = vn.y; out[kViewNormal + 2] = vn.z;
    out[kTangent] = t.x; out[kTangent + 1] = t.y; out[kTangent + 2] = t.z; out[kTangent + 3] = t.w;
  }
}

uint32_t ToonVertexShader::input_vertex_bytes() const {
  uint32_t bytes = 12;  // position
  if (!primitive_.normals.empty()) bytes += 12;
  if (!primitive_.uv0.empty()) bytes += 8;
  if (!primitive_.tangents.empty()) bytes += 16;
  return bytes;
}

}  // namespace ontile
