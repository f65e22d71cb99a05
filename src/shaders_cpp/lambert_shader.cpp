// Lambert fragment functor (see lambert_shader.h).
#include "shaders_cpp/lambert_shader.h"

#include "shaders_cpp/mesh_vertex_shader.h"

namespace ontile {

DirectionalLighting main_directional_light(const Scene& scene) {
  DirectionalLighting lighting;
  lighting.to_light = glm::normalize(glm::vec3(-0.4f, 0.8f, 0.45f));
  lighting.radiance = glm::vec3(1.0f);
  float best = -1.0f;
  for (const Light& light : scene.lights) {
    if (light.type != Light::Type::Directional) continue;
    const float strength = light.intensity * glm::max(light.color.x, glm::max(light.color.y, light.color.z));
    if (strength > best) {
      best = strength;
      lighting.to_light = -glm::normalize(light.direction);
      // Lux to display-referred radiance: a sun of a few lux should not blow out; glTF
      // sample scenes use intensities from 1 to ~10, so normalise by the intensity and keep
      // the colour.
      lighting.radiance = light.color;
    }
  }
  return lighting;
}

LambertShader::LambertShader(const Material& material, const DirectionalLighting& lighting)
    : material_(material), lighting_(lighting),
      alpha_mask_(material.alpha_mode == AlphaMode::Mask) {}

void LambertShader::shade(const QuadFragment& quad, QuadOutput& out) const {
  glm::vec4 albedo[kQuadLanes];
  for (int lane = 0; lane < kQuadLanes; ++lane) albedo[lane] = material_.base_color_factor;
  if (material_.base_color_texture.texture) {
    glm::vec2 uv[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = quad.var2(MeshVertexShader::kUv, lane);
    glm::vec4 texel[kQuadLanes];
    material_.base_color_texture.texture->sample_quad(material_.base_color_texture.sampler, uv, texel);
    for (int lane = 0; lane < kQuadLanes; ++lane) albedo[lane] *= texel[lane];
  }
  // glTF 2.0 3.9.3: emissive = emissiveFactor x emissiveTexture (sRGB).
  glm::vec3 emissive[kQuadLanes];
  for (int lane = 0; lane < kQuadLanes; ++lane) emissive[lane] = material_.emissive_factor;
  if (material_.emissive_texture.texture && material_.emissive_factor != glm::vec3(0.0f)) {
    glm::vec2 uv[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = quad.var2(MeshVertexShader::kUv, lane);
    glm::vec4 texel[kQuadLanes];
    material_.emissive_texture.texture->sample_quad(material_.emissive_texture.sampler, uv, texel);
    for (int lane = 0; lane < kQuadLanes; ++lane) emissive[lane] *= glm::vec3(texel[lane]);
  }
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    if (!quad.lane_active(lane)) continue;
    if (alpha_mask_ && albedo[lane].w < material_.alpha_cutoff) {
      out.discard(lane);
      continue;
    }
    glm::vec3 n = quad.var3(MeshVertexShader::kNormal, lane);
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
    if (!quad.front_facing) n = -n;  // back faces are seen only on double-sided materials
    const float n_dot_l = glm::max(glm::dot(n, lighting_.to_light), 0.0f);
    const glm::vec3 rgb = glm::vec3(albedo[lane]) * (lighting_.ambient + lighting_.radiance * n_dot_l) +
                          emissive[lane];
    out.color[0][lane] = glm::vec4(rgb, albedo[lane].w);
  }
}

}  // namespace ontile
