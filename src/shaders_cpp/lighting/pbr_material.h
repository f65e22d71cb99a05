// A glTF metallic-roughness material evaluated over a batch of quads: base colour, metallic,
// roughness, emission and the shading normal, with each texture a compile-time variant. The
// forward and G-buffer functors share it, so both see the same surface.
#pragma once
#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/mesh_vertex_shader.h"

namespace ontile {

struct PbrMaterialParams {
  glm::vec4 base_color{1.0f};
  const Texture2D* base_map = nullptr;
  SamplerDesc base_sampler;
  float metallic = 1.0f;
  float roughness = 1.0f;
  const Texture2D* metallic_roughness_map = nullptr;  // glTF: roughness in G, metallic in B
  SamplerDesc metallic_roughness_sampler;
  glm::vec3 emission{0.0f};
  const Texture2D* emission_map = nullptr;
  SamplerDesc emission_sampler;
  float alpha_cutoff = 0.5f;
};

// The material at each fragment of a batch, structure-of-arrays.
struct SurfaceBatch {
  alignas(64) float base_color[4][kBatchFragments];  // alpha = coverage
  alignas(64) float metallic[kBatchFragments];
  alignas(64) float roughness[kBatchFragments];
  alignas(64) float emission[3][kBatchFragments];
};

// glTF 2.0 3.9.2-3.9.3: factors times textures (base colour and emission sRGB-decoded by the
// texture, metallic-roughness linear), plus the MASK alpha test (3.9.4): active fragments below
// the cutoff are discarded in `out`. Textures are sampled per quad, for all four lanes so helper
// lanes give the derivatives, in the order base, metallic-roughness, emission.
template <bool kBaseMap, bool kAlphaTest, bool kMetallicRoughnessMap, bool kEmissionMap>
void evaluate_pbr_batch(const PbrMaterialParams& p, const FragmentBatch& batch, BatchOutput& out,
                        SurfaceBatch& s) {
  const int n = batch.padded_fragment_count();
  // glm's operator[] is a switch: each factor is read once so the fills vectorise.
  for (int c = 0; c < 4; ++c) {
    const float value = p.base_color[c];
    for (int f = 0; f < n; ++f) s.base_color[c][f] = value;
  }
  for (int f = 0; f < n; ++f) {
    s.metallic[f] = p.metallic;
    s.roughness[f] = p.roughness;
  }
  for (int c = 0; c < 3; ++c) {
    const float value = p.emission[c];
    for (int f = 0; f < n; ++f) s.emission[c][f] = value;
  }
  if constexpr (kBaseMap || kMetallicRoughnessMap || kEmissionMap) {
    for (int q = 0; q < batch.quad_count; ++q) {
      glm::vec2 uv[kQuadLanes];
      batch_quad_uv(batch, MeshVertexShader::kUv, q, uv);
      glm::vec4 texel[kQuadLanes];
      if constexpr (kBaseMap) {
        p.base_map->sample_quad(p.base_sampler, uv, texel);
        batch_multiply_quad(s.base_color, 4, q, texel);
      }
      if constexpr (kMetallicRoughnessMap) {
        p.metallic_roughness_map->sample_quad(p.metallic_roughness_sampler, uv, texel);
        for (int lane = 0; lane < kQuadLanes; ++lane) {
          s.roughness[q * kQuadLanes + lane] *= texel[lane].y;
          s.metallic[q * kQuadLanes + lane] *= texel[lane].z;
        }
      }
      if constexpr (kEmissionMap) {
        p.emission_map->sample_quad(p.emission_sampler, uv, texel);
        batch_multiply_quad(s.emission, 3, q, texel);
      }
    }
  }
  if constexpr (kAlphaTest) {
    for (int f = 0; f < batch.fragment_count(); ++f) {
      if (batch.active(f) && s.base_color[3][f] < p.alpha_cutoff) out.discard(f);
    }
  }
}

// The interpolated vertex normals, normalised and flipped for back faces (seen only on
// double-sided materials), for fragments [0, n).
inline void shading_normals(const FragmentBatch& batch, int n, BatchVec3& normal) {
  batch_unit_normals(batch, MeshVertexShader::kNormal, n, normal);
}

}  // namespace ontile
