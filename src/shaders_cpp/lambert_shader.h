// A Lambert fragment functor: base colour (factor x sRGB texture) lit by one directional light
// plus a constant ambient term, with emissive added. Template flags are the keyword variants:
// a material without a base map, alpha test or emission map runs code without those branches.
#pragma once
#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
#include "shaders_cpp/mesh_vertex_shader.h"

namespace ontile {

struct DirectionalLighting {
  glm::vec3 to_light{0.0f, 1.0f, 0.0f};  // unit vector towards the light, world space
  glm::vec3 radiance{1.0f};
  glm::vec3 ambient{0.2f};
};

// The scene's strongest directional light (KHR_lights_punctual), or a default sun from the
// upper left front when it has none.
DirectionalLighting main_directional_light(const Scene& scene);

struct LambertParams {
  glm::vec4 base_color{1.0f};
  const Texture2D* base_map = nullptr;
  SamplerDesc base_sampler;
  glm::vec3 emission{0.0f};
  const Texture2D* emission_map = nullptr;
  SamplerDesc emission_sampler;
  float alpha_cutoff = 0.5f;
  DirectionalLighting lighting;
};

template <bool kBaseMap, bool kAlphaTest, bool kEmissionMap>
class LambertShader final : public FragmentShader {
 public:
  explicit LambertShader(const LambertParams& p) : p_(p) {}
  bool may_discard() const override { return kAlphaTest; }

  void shade(const QuadFragment& quad, QuadOutput& out) const override {
    glm::vec2 uv[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = quad.var2(MeshVertexShader::kUv, lane);
    glm::vec4 albedo[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) albedo[lane] = p_.base_color;
    if constexpr (kBaseMap) {
      glm::vec4 texel[kQuadLanes];
      p_.base_map->sample_quad(p_.base_sampler, uv, texel);
      for (int lane = 0; lane < kQuadLanes; ++lane) albedo[lane] *= texel[lane];
    }
    // glTF 2.0 3.9.3: emissive = emissiveFactor x emissiveTexture (sRGB).
    glm::vec3 emissive[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) emissive[lane] = p_.emission;
    if constexpr (kEmissionMap) {
      glm::vec4 texel[kQuadLanes];
      p_.emission_map->sample_quad(p_.emission_sampler, uv, texel);
      for (int lane = 0; lane < kQuadLanes; ++lane) emissive[lane] *= glm::vec3(texel[lane]);
    }
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (!quad.lane_active(lane)) continue;
      if constexpr (kAlphaTest) {
        if (albedo[lane].w < p_.alpha_cutoff) {
          out.discard(lane);
          continue;
        }
      }
      glm::vec3 n = quad.var3(MeshVertexShader::kNormal, lane);
      const float len = glm::length(n);
      n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
      if (!quad.front_facing) n = -n;  // back faces are seen only on double-sided materials
      const float n_dot_l = glm::max(glm::dot(n, p_.lighting.to_light), 0.0f);
      const glm::vec3 rgb = glm::vec3(albedo[lane]) *
                                (p_.lighting.ambient + p_.lighting.radiance * n_dot_l) +
                            emissive[lane];
      out.color[0][lane] = glm::vec4(rgb, albedo[lane].w);
    }
  }

 private:
  LambertParams p_;
};

}  // namespace ontile
