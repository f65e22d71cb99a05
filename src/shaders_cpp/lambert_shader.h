// A Lambert fragment functor: base colour (factor x sRGB texture) lit by one directional light
// plus a constant ambient term, with emissive added. Template flags are the keyword variants:
// a material without a base map, alpha test or emission map runs code without those branches.
#pragma once
#include <cmath>

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
  // Per-fragment arithmetic and per-quad texture reads (base, then emission, quad by quad).
  bool batches_across_triangles() const override { return true; }
  // Colour, every channel of every padded fragment (the lighting loop below runs over all).
  int outputs_always_written() const override { return 1; }

  // Structure-of-arrays over the batch: texture reads per quad (the LOD needs the quad's
  // derivatives), the lighting arithmetic as plain loops over fragment lanes.
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    const int n = batch.padded_fragment_count();
    // Textured factors per fragment (factor x texel, the product glTF defines); an untextured
    // factor stays a constant of the loop below, so nothing is filled per fragment for it.
    alignas(64) float albedo[4][kBatchFragments];
    alignas(64) float emissive[3][kBatchFragments];
    if constexpr (kBaseMap || kEmissionMap) {
      const float* u = batch.varyings[MeshVertexShader::kUv];
      const float* v = batch.varyings[MeshVertexShader::kUv + 1];
      // Texels land in albedo and emissive (emission's alpha in a scratch row), then the factors
      // multiply them in place. Per quad, base then emission: the texel trace's order.
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
      // Quad by quad, 4 lanes at a time (one SIMD multiply per channel at -O2).
      for (int f0 = 0; f0 < batch.quad_count * kQuadLanes; f0 += kQuadLanes) {
        if constexpr (kBaseMap) {
          for (int c = 0; c < 4; ++c) {
            const float factor = p_.base_color[c];
            for (int lane = 0; lane < kQuadLanes; ++lane) albedo[c][f0 + lane] = factor * albedo[c][f0 + lane];
          }
        }
        // glTF 2.0 3.9.3: emissive = emissiveFactor x emissiveTexture (sRGB).
        if constexpr (kEmissionMap) {
          for (int c = 0; c < 3; ++c) {
            const float factor = p_.emission[c];
            for (int lane = 0; lane < kQuadLanes; ++lane) emissive[c][f0 + lane] = factor * emissive[c][f0 + lane];
          }
        }
      }
      // Padding lanes repeat the last fragment, as the batch's own padding does.
      const int last = batch.fragment_count() - 1;
      for (int f = last + 1; f < n; ++f) {
        for (int c = 0; c < 4; ++c) albedo[c][f] = albedo[c][last];
        for (int c = 0; c < 3; ++c) emissive[c][f] = emissive[c][last];
      }
    }
    const auto albedo_at = [&](int c, int f) { return kBaseMap ? albedo[c][f] : p_.base_color[c]; };
    const auto emissive_at = [&](int c, int f) { return kEmissionMap ? emissive[c][f] : p_.emission[c]; };
    if constexpr (kAlphaTest) {
      for (int f = 0; f < batch.fragment_count(); ++f) {
        if (batch.active(f) && albedo_at(3, f) < p_.alpha_cutoff) out.discard(f);
      }
    }
    const float* nx = batch.varyings[MeshVertexShader::kNormal];
    const float* ny = batch.varyings[MeshVertexShader::kNormal + 1];
    const float* nz = batch.varyings[MeshVertexShader::kNormal + 2];
    // Back faces are seen only on double-sided materials: their normal is flipped.
    const float facing = batch.front_facing ? 1.0f : -1.0f;
    const glm::vec3 l = p_.lighting.to_light, ambient = p_.lighting.ambient, radiance = p_.lighting.radiance;
    float* r = out.color[0][0];
    float* g = out.color[0][1];
    float* b = out.color[0][2];
    float* a = out.color[0][3];
    for (int f = 0; f < n; ++f) {
      const float len = std::sqrt(nx[f] * nx[f] + ny[f] * ny[f] + nz[f] * nz[f]);
      const bool has_length = len > 0.0f;
      // Divide unconditionally (by 1 where the length is 0), then select: no branches, so the
      // loop runs on SIMD lanes.
      const float divisor = has_length ? len : 1.0f;
      const float qx = nx[f] / divisor, qy = ny[f] / divisor, qz = nz[f] / divisor;
      const float x = (has_length ? qx : 0.0f) * facing;
      const float y = (has_length ? qy : 0.0f) * facing;
      const float z = (has_length ? qz : 1.0f) * facing;
      const float dot = x * l.x + y * l.y + z * l.z;
      const float n_dot_l = dot > 0.0f ? dot : 0.0f;
      r[f] = albedo_at(0, f) * (ambient.x + radiance.x * n_dot_l) + emissive_at(0, f);
      g[f] = albedo_at(1, f) * (ambient.y + radiance.y * n_dot_l) + emissive_at(1, f);
      b[f] = albedo_at(2, f) * (ambient.z + radiance.z * n_dot_l) + emissive_at(2, f);
      a[f] = albedo_at(3, f);
    }
  }

 private:
  LambertParams p_;
};

}  // namespace ontile
