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
  // Per-fragment arithmetic; texture reads per quad (evaluate_pbr_batch).
  bool batches_across_triangles() const override { return true; }

  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    SurfaceBatch s;
    evaluate_pbr_batch<kBaseMap, kAlphaTest, kMetallicRoughnessMap, kEmissionMap>(material_, batch, out, s);
    const int count = batch.fragment_count();
    alignas(64) BatchVec3 normal;
    shading_normals(batch, count, normal);
    const int first_target = layout_.light_in_gbuffer ? 1 : 0;
    for (int f = 0; f < count; ++f) {
      const GBufferSurface g{{s.base_color[0][f], s.base_color[1][f], s.base_color[2][f]}, s.metallic[f],
                             s.roughness[f], batch_get3(normal, f)};
      glm::vec4 targets[3];
      encode_gbuffer(layout_, g, targets);
      for (int k = 0; k < layout_.target_count(); ++k) out.set(first_target + k, f, targets[k]);
      if (layout_.light_in_gbuffer) {
        const BrdfInputs brdf = metallic_roughness_brdf(g.base_color, g.metallic, g.roughness);
        const glm::vec3 emission(s.emission[0][f], s.emission[1][f], s.emission[2][f]);
        out.set(0, f, glm::vec4(ambient_ * brdf.diffuse_color + emission, 1.0f));
      }
    }
  }

 private:
  PbrMaterialParams material_;
  GBufferLayout layout_;
  glm::vec3 ambient_;
};

}  // namespace ontile
