// Toon environment lighting: the diffuse colour multiplied by a cube map looked up with the
// surface normal, in world space, or in view space with kCameraBased (the
// CAMERA_BASED_ENVIRONMENT keyword: the lighting turns with the camera, like a MatCap).
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
#include "shaders_cpp/toon/cube_map.h"
#include "shaders_cpp/toon/toon_outputs.h"
#include "shaders_cpp/toon/toon_vertex_shader.h"
#include "util/error.h"

namespace ontile {

struct ToonEnvParams {
  const CubeMap* environment = nullptr;  // required when the colour output is written
  glm::vec4 base_color{1.0f};
  const Texture2D* base_map = nullptr;   // optional (sRGB); null = base colour factor only
  SamplerDesc base_sampler;
  ToonOutputParams outputs;
};

// Colour = (base colour [x base map]).rgb x environment(N).rgb, alpha = base alpha; N = the unit
// interpolated world normal, or view-space normal with kCameraBased (flipped on back faces).
template <uint32_t kOutputs, bool kCameraBased>
class ToonEnvShader final : public FragmentShader {
  static_assert(is_valid_toon_output_mask(kOutputs), "kOutputs must be a ToonOutput mask");

 public:
  explicit ToonEnvShader(const ToonEnvParams& params) : p_(params) {
    if ((kOutputs & ToonOutput::kColor) != 0u && !p_.environment) {
      throw Error("ToonEnvShader: no environment cube map");
    }
  }

  void shade(const QuadFragment& quad, QuadOutput& out) const override {
    glm::vec3 view_normal[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      view_normal[lane] =
          toon_unit_normal(quad.var3(ToonVertexShader::kViewNormal, lane), quad.front_facing);
    }
    if constexpr ((kOutputs & ToonOutput::kColor) != 0u) shade_color(quad, view_normal, out);
    write_toon_normal_and_border<kOutputs>(quad, out, view_normal, p_.outputs);
  }

 private:
  void shade_color(const QuadFragment& quad, const glm::vec3 view_normal[kQuadLanes],
                   QuadOutput& out) const {
    glm::vec4 albedo[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) albedo[lane] = p_.base_color;
    if (p_.base_map) {  // one branch per quad: the base map is not a keyword of this shader
      glm::vec2 uv[kQuadLanes];
      for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = quad.var2(ToonVertexShader::kUv, lane);
      glm::vec4 texel[kQuadLanes];
      p_.base_map->sample_quad(p_.base_sampler, uv, texel);
      for (int lane = 0; lane < kQuadLanes; ++lane) albedo[lane] *= texel[lane];
    }
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (!quad.lane_active(lane)) continue;
      glm::vec3 direction;
      if constexpr (kCameraBased) {
        direction = view_normal[lane];
      } else {
        direction = toon_unit_normal(quad.var3(ToonVertexShader::kNormal, lane), quad.front_facing);
      }
      const glm::vec3 env(p_.environment->sample(direction));
      out.color[0][lane] = glm::vec4(glm::vec3(albedo[lane]) * env, albedo[lane].w);
    }
  }

  ToonEnvParams p_;
};

}  // namespace ontile
