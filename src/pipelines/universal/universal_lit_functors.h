// Fragment functors of the universal Lit shader: the forward pass (Lambert diffuse + Blinn-Phong
// specular over a per-object list of at most 8 lights, main-light shadows), the alpha-clip
// functor the depth and shadow passes use for alpha-tested materials, and the DepthNormals
// functor. Template flags are the keyword variants (_BASEMAP, _ALPHATEST_ON, _EMISSION) and
// whether a main-light shadow map is bound (URP's _MAIN_LIGHT_SHADOWS).
#pragma once
#include <array>
#include <cmath>

#include <glm/glm.hpp>

#include "pipelines/universal/main_light_shadows.h"
#include "pipelines/universal/universal_lights.h"
#include "raster/shader_interface.h"
#include "shaders_cpp/mesh_vertex_shader.h"
#include "shaders_cpp/toon/toon_outputs.h"

namespace ontile {

struct UniversalSurfaceParams {
  glm::vec4 base_color{1.0f};
  const Texture2D* base_map = nullptr;  // required by the _BASEMAP variants
  SamplerDesc base_sampler;
  float alpha_cutoff = 0.5f;
};

struct UniversalLitParams {
  UniversalSurfaceParams surface;
  float metallic = 0.0f;
  float smoothness = 0.5f;
  glm::vec3 emission{0.0f};                 // _EMISSION variants
  const Texture2D* emission_map = nullptr;  // optional in them
  SamplerDesc emission_sampler;
  glm::vec3 camera_position{0.0f};
  glm::vec3 ambient{0.2f};
  MainLight main_light;
  std::array<AdditionalLight, kMaxAdditionalLightsPerObject> additional_lights{};
  int additional_light_count = 0;
  ShadowLookup shadow;  // the shadow variants need shadow.map
};

// Blinn-Phong as URP's SimpleLit has it: specular power exp2(10 * smoothness + 1); the
// specular colour is 0.04 for dielectrics and the albedo for metals (glTF metallic-roughness,
// smoothness = 1 - roughness), the diffuse colour albedo x (1 - metallic). The highlight is
// scaled by N.L so it fades at the terminator instead of lighting back faces.
inline glm::vec3 blinn_phong(glm::vec3 diffuse_color, glm::vec3 specular_color, float shininess,
                             glm::vec3 n, glm::vec3 to_view, glm::vec3 to_light, glm::vec3 radiance) {
  const float n_dot_l = glm::dot(n, to_light);
  if (!(n_dot_l > 0.0f)) return glm::vec3(0.0f);
  const glm::vec3 half_vector = to_light + to_view;
  const float half_length = glm::length(half_vector);
  const float n_dot_h = half_length > 0.0f ? glm::max(glm::dot(n, half_vector / half_length), 0.0f) : 0.0f;
  return radiance * n_dot_l * (diffuse_color + specular_color * std::pow(n_dot_h, shininess));
}

// The non-template part: the lights this draw shades, inspectable by tests.
class UniversalLitFragment : public FragmentShader {
 public:
  explicit UniversalLitFragment(const UniversalLitParams& params) : p_(params) {}
  // Main light + the additional lights chosen for this object (at most kMaxLightsPerObject).
  int light_count() const { return 1 + p_.additional_light_count; }
  const UniversalLitParams& params() const { return p_; }

 protected:
  UniversalLitParams p_;
};

template <bool kBaseMap, bool kAlphaTest, bool kEmission, bool kShadows>
class UniversalLitShader final : public UniversalLitFragment {
 public:
  using UniversalLitFragment::UniversalLitFragment;
  bool may_discard() const override { return kAlphaTest; }

  void shade(const QuadFragment& quad, QuadOutput& out) const override {
    glm::vec2 uv[kQuadLanes];
    glm::vec4 albedo[kQuadLanes];
    glm::vec3 emissive[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      uv[lane] = quad.var2(MeshVertexShader::kUv, lane);
      albedo[lane] = p_.surface.base_color;
      emissive[lane] = p_.emission;
    }
    if constexpr (kBaseMap) {
      glm::vec4 texel[kQuadLanes];
      p_.surface.base_map->sample_quad(p_.surface.base_sampler, uv, texel);
      for (int lane = 0; lane < kQuadLanes; ++lane) albedo[lane] *= texel[lane];
    }
    if constexpr (kEmission) {
      if (p_.emission_map) {  // glTF 2.0 3.9.3: emissiveFactor x emissiveTexture
        glm::vec4 texel[kQuadLanes];
        p_.emission_map->sample_quad(p_.emission_sampler, uv, texel);
        for (int lane = 0; lane < kQuadLanes; ++lane) emissive[lane] *= glm::vec3(texel[lane]);
      }
    }
    const float shininess = std::exp2(10.0f * p_.smoothness + 1.0f);
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (!quad.lane_active(lane)) continue;
      if constexpr (kAlphaTest) {
        if (albedo[lane].w < p_.surface.alpha_cutoff) {
          out.discard(lane);
          continue;
        }
      }
      const glm::vec3 n = toon_unit_normal(quad.var3(MeshVertexShader::kNormal, lane), quad.front_facing);
      const glm::vec3 position = quad.var3(MeshVertexShader::kWorldPos, lane);
      const glm::vec3 to_camera = p_.camera_position - position;
      const float camera_distance = glm::length(to_camera);
      const glm::vec3 to_view = camera_distance > 0.0f ? to_camera / camera_distance : n;
      const glm::vec3 base(albedo[lane]);
      const glm::vec3 diffuse_color = base * (1.0f - p_.metallic);
      const glm::vec3 specular_color = glm::mix(glm::vec3(0.04f), base, p_.metallic);
      // Ambient stands in for both indirect diffuse and the environment reflection URP would
      // take from a reflection probe, so metals are not black outside their highlights.
      glm::vec3 rgb = p_.ambient * (diffuse_color + specular_color);
      glm::vec3 main_radiance = p_.main_light.radiance;
      if constexpr (kShadows) {
        main_radiance *= main_light_visibility(p_.shadow, position, n, p_.main_light.to_light);
      }
      rgb += blinn_phong(diffuse_color, specular_color, shininess, n, to_view, p_.main_light.to_light,
                         main_radiance);
      for (int i = 0; i < p_.additional_light_count; ++i) {
        const AdditionalLight& light = p_.additional_lights[i];
        glm::vec3 to_light = -light.direction;
        glm::vec3 radiance = light.intensity;
        if (light.type != AdditionalLight::Type::Directional) {
          const glm::vec3 offset = light.position - position;
          const float distance_squared = glm::dot(offset, offset);
          to_light = distance_squared > 0.0f ? offset / std::sqrt(distance_squared) : n;
          radiance *= range_attenuation(distance_squared, light.range) * spot_attenuation(light, -to_light);
        }
        rgb += blinn_phong(diffuse_color, specular_color, shininess, n, to_view, to_light, radiance);
      }
      if constexpr (kEmission) rgb += emissive[lane];
      out.color[0][lane] = glm::vec4(rgb, albedo[lane].w);
    }
  }
};

// Alpha-tested depth-only and shadow-caster draws: writes no colour, discards where the base
// colour's alpha is below the cutoff (so holes cast no shadow and leave no depth).
template <bool kBaseMap>
class UniversalAlphaClipShader final : public FragmentShader {
 public:
  explicit UniversalAlphaClipShader(const UniversalSurfaceParams& params) : p_(params) {}
  bool may_discard() const override { return true; }
  void shade(const QuadFragment& quad, QuadOutput& out) const override {
    float alpha[kQuadLanes];
    surface_alpha(p_, quad, alpha);
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (quad.lane_active(lane) && alpha[lane] < p_.alpha_cutoff) out.discard(lane);
    }
  }
  static void surface_alpha(const UniversalSurfaceParams& p, const QuadFragment& quad,
                            float alpha[kQuadLanes]) {
    for (int lane = 0; lane < kQuadLanes; ++lane) alpha[lane] = p.base_color.w;
    if constexpr (kBaseMap) {
      glm::vec2 uv[kQuadLanes];
      for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = quad.var2(MeshVertexShader::kUv, lane);
      glm::vec4 texel[kQuadLanes];
      p.base_map->sample_quad(p.base_sampler, uv, texel);
      for (int lane = 0; lane < kQuadLanes; ++lane) alpha[lane] *= texel[lane].w;
    }
  }

 private:
  UniversalSurfaceParams p_;
};

// URP's DepthNormals pass: the unit view-space normal, encoded n * 0.5 + 0.5 for the RGB10A2
// normals target (toon_outputs.h's Unorm encoding, which the Sobel edge functor decodes).
template <bool kAlphaTest, bool kBaseMap>
class UniversalDepthNormalsShader final : public FragmentShader {
 public:
  UniversalDepthNormalsShader(const UniversalSurfaceParams& params, const glm::mat3& world_to_view)
      : p_(params), world_to_view_(world_to_view) {}
  bool may_discard() const override { return kAlphaTest; }
  void shade(const QuadFragment& quad, QuadOutput& out) const override {
    float alpha[kQuadLanes] = {};
    if constexpr (kAlphaTest) UniversalAlphaClipShader<kBaseMap>::surface_alpha(p_, quad, alpha);
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (!quad.lane_active(lane)) continue;
      if constexpr (kAlphaTest) {
        if (alpha[lane] < p_.alpha_cutoff) {
          out.discard(lane);
          continue;
        }
      }
      const glm::vec3 world_normal = toon_unit_normal(quad.var3(MeshVertexShader::kNormal, lane), quad.front_facing);
      const glm::vec3 view_normal = toon_unit_normal(world_to_view_ * world_normal, true);
      out.color[0][lane] = encode_view_normal(view_normal, NormalEncoding::Unorm);
    }
  }

 private:
  UniversalSurfaceParams p_;
  glm::mat3 world_to_view_;
};

}  // namespace ontile
