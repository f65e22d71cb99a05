// The forward lit functor of the `forward` pipeline: the PBR material lit by ambient, the sun
// and the pixel's light-grid lights (Forward+), with the same BRDF and light order as the
// deferred lighting functor. Template flags are the material's texture keywords and alpha test.
#pragma once
#include "shaders_cpp/lighting/pbr_material.h"
#include "shaders_cpp/lighting/scene_lighting.h"

namespace ontile {

template <bool kBaseMap, bool kAlphaTest, bool kMetallicRoughnessMap, bool kEmissionMap>
class ForwardLitShader final : public FragmentShader {
 public:
  ForwardLitShader(const PbrMaterialParams& material, const SceneLighting& lighting, glm::vec3 camera_position)
      : material_(material), lighting_(lighting), camera_position_(camera_position) {}
  bool may_discard() const override { return kAlphaTest; }

  void shade(const QuadFragment& quad, QuadOutput& out) const override {
    SurfacePoint surface[kQuadLanes];
    const uint8_t lanes =
        evaluate_pbr_quad<kBaseMap, kAlphaTest, kMetallicRoughnessMap, kEmissionMap>(material_, quad, out, surface);
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (!((lanes >> lane) & 1u)) continue;
      const SurfacePoint& s = surface[lane];
      const BrdfInputs brdf = metallic_roughness_brdf(glm::vec3(s.base_color), s.metallic, s.roughness);
      const glm::vec3 position = quad.var3(MeshVertexShader::kWorldPos, lane);
      const glm::vec3 to_view = glm::normalize(camera_position_ - position);
      const glm::vec3 rgb = lighting_.ambient * brdf.diffuse_color + s.emission +
                            direct_lighting(lighting_, brdf, shading_normal(quad, lane), position, to_view,
                                            quad.x_px + (lane & 1), quad.y_px + (lane >> 1));
      out.color[0][lane] = glm::vec4(rgb, s.base_color.w);
    }
  }

 private:
  PbrMaterialParams material_;
  const SceneLighting& lighting_;
  glm::vec3 camera_position_;
};

}  // namespace ontile
