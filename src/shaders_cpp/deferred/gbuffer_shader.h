// The G-buffer functor of the deferred pipelines: evaluates the PBR material and writes the
// layout's targets; with a light-accumulation layout (Unity's) it also writes ambient (GI) and
// emission into the light target, output 0. Template flags: texture keywords and alpha test.
#pragma once
#include "shaders_cpp/deferred/gbuffer_layout.h"
#include "shaders_cpp/lighting/pbr_material.h"

namespace ontile {

template <bool kBaseMap, bool kAlphaTest, bool kMetallicRoughnessMap, bool kEmissionMap>
class GBufferShader final : public FragmentShader {
 public:
  GBufferShader(const PbrMaterialParams& material, const GBufferLayout& layout, glm::vec3 ambient)
      : material_(material), layout_(layout), ambient_(ambient) {}
  bool may_discard() const override { return kAlphaTest; }

  void shade(const QuadFragment& quad, QuadOutput& out) const override {
    SurfacePoint surface[kQuadLanes];
    const uint8_t lanes =
        evaluate_pbr_quad<kBaseMap, kAlphaTest, kMetallicRoughnessMap, kEmissionMap>(material_, quad, out, surface);
    const int first_target = layout_.light_in_gbuffer ? 1 : 0;
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (!((lanes >> lane) & 1u)) continue;
      const SurfacePoint& s = surface[lane];
      const GBufferSurface g{glm::vec3(s.base_color), s.metallic, s.roughness, shading_normal(quad, lane)};
      glm::vec4 targets[3];
      encode_gbuffer(layout_, g, targets);
      for (int k = 0; k < layout_.target_count(); ++k) out.color[first_target + k][lane] = targets[k];
      if (layout_.light_in_gbuffer) {
        const BrdfInputs brdf = metallic_roughness_brdf(g.base_color, g.metallic, g.roughness);
        out.color[0][lane] = glm::vec4(ambient_ * brdf.diffuse_color + s.emission, 1.0f);
      }
    }
  }

 private:
  PbrMaterialParams material_;
  GBufferLayout layout_;
  glm::vec3 ambient_;
};

}  // namespace ontile
