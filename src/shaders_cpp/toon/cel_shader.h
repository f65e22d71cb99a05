// Cel (toon) shading with one directional light: fully lit where the surface faces the light,
// and `steps` flat shadow bands beyond the terminator, mixing a lit and a shadow colour (or
// textures: the kTextures variant).
#pragma once
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
#include "shaders_cpp/toon/toon_outputs.h"
#include "shaders_cpp/toon/toon_vertex_shader.h"
#include "util/error.h"

namespace ontile {

// Shadow amount for d = dot(N, L): 0 when d >= 0 (fully lit), else
// min(1, ceil(-d / step_size) / steps). With steps = 1 any d < 0 is full shadow (classic cel
// shading); with steps = n and step_size = 1/n, d in [-k/n, -(k-1)/n) gives k/n. NaN -> 1.
float cel_shadow_factor(float n_dot_l, int steps, float step_size);

struct CelParams {
  glm::vec3 to_light{0.0f, 1.0f, 0.0f};  // unit vector towards the light, world space
  int steps = 1;                         // >= 1
  float step_size = 0.0f;                // > 0; <= 0 means the default 1 / steps
  glm::vec4 lit_color{1.0f};
  glm::vec4 shadow_color{0.45f, 0.45f, 0.55f, 1.0f};
  // kTextures: each colour is multiplied by its texture at TEXCOORD_0; a null map is skipped
  // (that colour stays a constant).
  const Texture2D* lit_map = nullptr;
  SamplerDesc lit_sampler;
  const Texture2D* shadow_map = nullptr;
  SamplerDesc shadow_sampler;
  ToonOutputParams outputs;
};

// Colour = mix(lit, shadow, cel_shadow_factor(dot(N, L), steps, step_size)), RGBA, with N the
// unit interpolated world normal (flipped on back faces).
template <uint32_t kOutputs, bool kTextures>
class CelShader final : public FragmentShader {
  static_assert(is_valid_toon_output_mask(kOutputs), "kOutputs must be a ToonOutput mask");

 public:
  explicit CelShader(const CelParams& params) : p_(params) {
    if (p_.steps < 1) {
      throw Error("CelShader: steps must be at least 1 (got " + std::to_string(p_.steps) + ")");
    }
    if (!(p_.step_size > 0.0f)) p_.step_size = 1.0f / static_cast<float>(p_.steps);
  }

  void shade(const QuadFragment& quad, QuadOutput& out) const override {
    glm::vec3 view_normal[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      view_normal[lane] =
          toon_unit_normal(quad.var3(ToonVertexShader::kViewNormal, lane), quad.front_facing);
    }
    if constexpr ((kOutputs & ToonOutput::kColor) != 0u) shade_color(quad, out);
    write_toon_normal_and_border<kOutputs>(quad, out, view_normal, p_.outputs);
  }

 private:
  void shade_color(const QuadFragment& quad, QuadOutput& out) const {
    glm::vec4 lit[kQuadLanes], shadow[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      lit[lane] = p_.lit_color;
      shadow[lane] = p_.shadow_color;
    }
    if constexpr (kTextures) {
      glm::vec2 uv[kQuadLanes];
      for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = quad.var2(ToonVertexShader::kUv, lane);
      glm::vec4 texel[kQuadLanes];
      if (p_.lit_map) {
        p_.lit_map->sample_quad(p_.lit_sampler, uv, texel);
        for (int lane = 0; lane < kQuadLanes; ++lane) lit[lane] *= texel[lane];
      }
      if (p_.shadow_map) {
        p_.shadow_map->sample_quad(p_.shadow_sampler, uv, texel);
        for (int lane = 0; lane < kQuadLanes; ++lane) shadow[lane] *= texel[lane];
      }
    }
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (!quad.lane_active(lane)) continue;
      const glm::vec3 n =
          toon_unit_normal(quad.var3(ToonVertexShader::kNormal, lane), quad.front_facing);
      const float shadow_amount = cel_shadow_factor(glm::dot(n, p_.to_light), p_.steps, p_.step_size);
      out.color[0][lane] = glm::mix(lit[lane], shadow[lane], shadow_amount);
    }
  }

  CelParams p_;
};

}  // namespace ontile
