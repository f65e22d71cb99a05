// The G-buffer functor of the deferred pipelines: evaluates the PBR material and writes the
// layout's targets; with a light-accumulation layout (Unity's) it also writes ambient (GI) and
// emission into the light target, output 0. Template flags: texture keywords and alpha test.
#pragma once
#include <algorithm>

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
    // encode_gbuffer channel by channel (the same float operations per fragment).
    const float* const base[3] = {s.base_color[0], s.base_color[1], s.base_color[2]};
    BrdfBatch brdf;
    if (layout_.has_specular || layout_.light_in_gbuffer) metallic_roughness_brdf(base, s.metallic, s.roughness, count, brdf);
    const auto write = [count](float* target, const float* values) { std::copy_n(values, count, target); };
    const auto fill_one = [count](float* target) { std::fill_n(target, count, 1.0f); };
    float(*normal_target)[kBatchFragments];
    if (layout_.has_specular) {
      float(*diffuse)[kBatchFragments] = out.color[first_target];
      float(*specular)[kBatchFragments] = out.color[first_target + 1];
      for (int c = 0; c < 3; ++c) {
        write(diffuse[c], brdf.diffuse_color[c]);
        write(specular[c], brdf.f0[c]);
      }
      fill_one(diffuse[3]);
      for (int f = 0; f < count; ++f) specular[3][f] = 1.0f - s.roughness[f];
      normal_target = out.color[first_target + 2];
      fill_one(normal_target[3]);
    } else {
      // Metallic rides in the normal target's alpha (see encode_gbuffer).
      float(*albedo)[kBatchFragments] = out.color[first_target];
      for (int c = 0; c < 3; ++c) write(albedo[c], s.base_color[c]);
      write(albedo[3], s.roughness);
      normal_target = out.color[first_target + 1];
      write(normal_target[3], s.metallic);
    }
    const bool signed_normals = gbuffer_detail::is_float_format(layout_.normal_format);
    for (int c = 0; c < 3; ++c) {
      if (signed_normals) {
        write(normal_target[c], normal[c]);
      } else {
        for (int f = 0; f < count; ++f) normal_target[c][f] = normal[c][f] * 0.5f + 0.5f;
      }
    }
    if (layout_.light_in_gbuffer) {
      for (int c = 0; c < 3; ++c) {
        for (int f = 0; f < count; ++f) out.color[0][c][f] = ambient_[c] * brdf.diffuse_color[c][f] + s.emission[c][f];
      }
      fill_one(out.color[0][3]);
    }
  }

 private:
  PbrMaterialParams material_;
  GBufferLayout layout_;
  glm::vec3 ambient_;
};

}  // namespace ontile
