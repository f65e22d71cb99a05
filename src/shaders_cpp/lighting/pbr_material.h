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
// lanes give the derivatives, in the order base, metallic-roughness, emission (one sample_quads
// call for the batch).
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
    // All quads' texels in one call, per quad in the order base, metallic-roughness, emission
    // (the texel trace's order), then the factors multiplied by them.
    alignas(64) BatchVec4 base_texel, metallic_roughness_texel, emission_texel;
    Texture2D::QuadRead reads[3];
    int read_count = 0;
    if constexpr (kBaseMap) reads[read_count++] = batch_texture_read(p.base_map, p.base_sampler, base_texel);
    if constexpr (kMetallicRoughnessMap) {
      reads[read_count++] = batch_texture_read(p.metallic_roughness_map, p.metallic_roughness_sampler,
                                               metallic_roughness_texel);
    }
    if constexpr (kEmissionMap) {
      reads[read_count++] = batch_texture_read(p.emission_map, p.emission_sampler, emission_texel);
    }
    Texture2D::sample_quads(reads, read_count, batch.varyings[MeshVertexShader::kUv],
                            batch.varyings[MeshVertexShader::kUv + 1], batch.quad_count);
    if constexpr (kBaseMap) batch_multiply_quads(s.base_color, 4, batch.quad_count, base_texel);
    if constexpr (kMetallicRoughnessMap) {
      for (int f = 0; f < batch.quad_count * kQuadLanes; ++f) {
        s.roughness[f] *= metallic_roughness_texel[1][f];
        s.metallic[f] *= metallic_roughness_texel[2][f];
      }
    }
    if constexpr (kEmissionMap) batch_multiply_quads(s.emission, 3, batch.quad_count, emission_texel);
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
