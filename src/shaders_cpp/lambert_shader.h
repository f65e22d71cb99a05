// A Lambert fragment functor: base colour (factor x sRGB texture) lit by one directional light
// plus a constant ambient term, with emissive added. Template flags are the keyword variants:
// a material without a base map, alpha test or emission map runs code without those branches.
#pragma once
#include <cmath>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
#include "shaders_cpp/lambert_lanes.h"
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
  // Per-fragment arithmetic and per-quad texture reads (base, then emission, quad by quad).
  bool batches_across_triangles() const override { return true; }
  // The normal, and the UV where a texture is read (not the world position): the raster core
  // interpolates only these.
  uint32_t varyings_read() const override {
    constexpr uint32_t kNormalBits = 7u << MeshVertexShader::kNormal, kUvBits = 3u << MeshVertexShader::kUv;
    return kNormalBits | (kBaseMap || kEmissionMap ? kUvBits : 0u);
  }
  // Colour, every channel of every padded fragment (lambert_light_batch writes them all).
  int outputs_always_written() const override { return 1; }

  // Structure-of-arrays over the batch: texture reads per quad (the LOD needs the quad's
  // derivatives), the lighting on SIMD lanes over every padded fragment (lambert_lanes.h).
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    const int n = batch.padded_fragment_count();
    // Texels per fragment; an untextured factor stays a constant of the lighting lanes, so
    // nothing is filled per fragment for it.
    alignas(64) float albedo[4][kBatchFragments];
    alignas(64) float emissive[3][kBatchFragments];
    if constexpr (kBaseMap || kEmissionMap) {
      const float* u = batch.varyings[MeshVertexShader::kUv];
      const float* v = batch.varyings[MeshVertexShader::kUv + 1];
      // Texels land in albedo and emissive (emission's alpha in a scratch row). Per quad, base
      // then emission: the texel trace's order.
      alignas(64) float emission_alpha[kBatchFragments];
      Texture2D::QuadRead reads[2];
      int read_count = 0;
      if constexpr (kBaseMap) {
        reads[read_count++] = {p_.base_map, &p_.base_sampler, {albedo[0], albedo[1], albedo[2], albedo[3]}};
      }
      if constexpr (kEmissionMap) {
        reads[read_count++] = {p_.emission_map, &p_.emission_sampler,
                               {emissive[0], emissive[1], emissive[2], emission_alpha}};
      }
      Texture2D::sample_quads(reads, read_count, u, v, batch.quad_count);
      // Padding lanes repeat the last fragment, as the batch's own padding does.
      const int last = batch.fragment_count() - 1;
      for (int f = last + 1; f < n; ++f) {
        for (int c = 0; c < 4; ++c) albedo[c][f] = albedo[c][last];
        for (int c = 0; c < 3; ++c) emissive[c][f] = emissive[c][last];
      }
    }
    // The factors multiply the texels (glTF 2.0 3.9.2 and 3.9.3: factor x texture) on the
    // lanes below; the alpha test takes the same product.
    if constexpr (kAlphaTest) {
      for (int f = 0; f < batch.fragment_count(); ++f) {
        const float alpha = kBaseMap ? p_.base_color[3] * albedo[3][f] : p_.base_color[3];
        if (batch.active(f) && alpha < p_.alpha_cutoff) out.discard(f);
      }
    }
    // Back faces are seen only on double-sided materials: their normal is flipped.
    const DirectionalLighting& light = p_.lighting;
    const LambertLaneConstants k{{light.to_light.x, light.to_light.y, light.to_light.z},
                                 {light.ambient.x, light.ambient.y, light.ambient.z},
                                 {light.radiance.x, light.radiance.y, light.radiance.z},
                                 batch.front_facing ? 1.0f : -1.0f,
                                 {p_.base_color.x, p_.base_color.y, p_.base_color.z, p_.base_color.w},
                                 {p_.emission.x, p_.emission.y, p_.emission.z}};
    lambert_light_batch(batch.varyings[MeshVertexShader::kNormal], batch.varyings[MeshVertexShader::kNormal + 1],
                        batch.varyings[MeshVertexShader::kNormal + 2], k, kBaseMap ? albedo : nullptr,
                        kEmissionMap ? emissive : nullptr, out.color[0], n);
  }

 private:
  LambertParams p_;
};

}  // namespace ontile
