// MatCap coordinate mapping and normal-map helpers (see matcap_shader.h).
#include "shaders_cpp/toon/matcap_shader.h"

namespace ontile {

SamplerDesc matcap_sampler() {
  SamplerDesc s;
  s.mag_filter = FilterMode::Linear;
  s.min_filter = FilterMode::Linear;
  s.mipmap_mode = MipmapMode::None;
  s.wrap_u = WrapMode::ClampToEdge;
  s.wrap_v = WrapMode::ClampToEdge;
  return s;
}

glm::vec3 decode_tangent_space_normal(glm::vec4 texel, float normal_scale) {
  const glm::vec3 n = (glm::vec3(texel) * 2.0f - 1.0f) * glm::vec3(normal_scale, normal_scale, 1.0f);
  const float len = glm::length(n);
  return len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
}

glm::vec3 perturb_normal(glm::vec3 unit_world_normal, glm::vec4 world_tangent,
                         glm::vec3 tangent_space_normal) {
  const glm::vec3 n = unit_world_normal;
  const glm::vec3 t_raw = glm::vec3(world_tangent) - n * glm::dot(n, glm::vec3(world_tangent));
  const float t_len = glm::length(t_raw);
  // No tangent (or one parallel to the normal): nothing defines the texture's orientation.
  if (!(t_len > 1e-8f) || world_tangent.w == 0.0f) return n;
  const glm::vec3 t = t_raw / t_len;
  const glm::vec3 b = glm::cross(n, t) * (world_tangent.w < 0.0f ? -1.0f : 1.0f);
  const glm::vec3 mapped =
      t * tangent_space_normal.x + b * tangent_space_normal.y + n * tangent_space_normal.z;
  const float len = glm::length(mapped);
  return len > 0.0f ? mapped / len : n;
}

}  // namespace ontile
