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
  // Texture reads per quad (evaluate_pbr_batch); lighting per fragment (each fragment's own
  // light-grid list in a fixed order, whatever run of fragments it is shaded in).
  bool batches_across_triangles() const override { return true; }

  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    const int n = batch.padded_fragment_count();
    SurfaceBatch s;
    evaluate_pbr_batch<kBaseMap, kAlphaTest, kMetallicRoughnessMap, kEmissionMap>(material_, batch, out, s);
    BrdfBatch brdf;
    const float* const base[3] = {s.base_color[0], s.base_color[1], s.base_color[2]};
    metallic_roughness_brdf(base, s.metallic, s.roughness, n, brdf);
    alignas(64) BatchVec3 normal, position, to_view;
    alignas(64) BatchVec3 direct = {};  // stays 0 for fragments that are not stored
    shading_normals(batch, n, normal);
    for (int f = 0; f < n; ++f) {
      const glm::vec3 p = batch_var3(batch, MeshVertexShader::kWorldPos, f);
      batch_set3(position, f, p);
      batch_set3(to_view, f, glm::normalize(camera_position_ - p));
    }
    // Lighting only for fragments that are stored: active and not discarded.
    uint64_t lit = 0;
    for (int f = 0; f < batch.fragment_count(); ++f) {
      if (batch.active(f)) lit |= uint64_t{1} << f;
    }
    lit &= ~out.discard_mask;
    direct_lighting(lighting_, brdf, normal, position, to_view, batch, lit, direct);
    const int count = batch.fragment_count();
    for (int c = 0; c < 3; ++c) {
      const float ambient = lighting_.ambient[c];
      for (int f = 0; f < count; ++f) {
        out.color[0][c][f] = (ambient * brdf.diffuse_color[c][f] + s.emission[c][f]) + direct[c][f];
      }
    }
    for (int f = 0; f < count; ++f) out.color[0][3][f] = s.base_color[3][f];
  }

 private:
  PbrMaterialParams material_;
  const SceneLighting& lighting_;
  glm::vec3 camera_position_;
};

}  // namespace ontile
