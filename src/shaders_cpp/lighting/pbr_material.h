// A glTF metallic-roughness material evaluated over one 2x2 quad: base colour, metallic,
// roughness, emission and the shading normal, with each texture a compile-time variant. The
// forward and G-buffer functors share it, so both see the same surface.
#pragma once
#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
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

struct SurfacePoint {
  glm::vec4 base_color{1.0f};  // alpha = coverage
  float metallic = 0.0f;
  float roughness = 1.0f;
  glm::vec3 emission{0.0f};
};

// glTF 2.0 3.9.2-3.9.3: factors times textures (base colour and emission sRGB-decoded by the
// texture, metallic-roughness linear). Textures are sampled for all four lanes so helper lanes
// give the derivatives.
template <bool kBaseMap, bool kMetallicRoughnessMap, bool kEmissionMap>
void evaluate_pbr_material(const PbrMaterialParams& p, const QuadFragment& quad, SurfacePoint out[kQuadLanes]) {
  glm::vec2 uv[kQuadLanes];
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    uv[lane] = quad.var2(MeshVertexShader::kUv, lane);
    out[lane].base_color = p.base_color;
    out[lane].metallic = p.metallic;
    out[lane].roughness = p.roughness;
    out[lane].emission = p.emission;
  }
  glm::vec4 texel[kQuadLanes];
  if constexpr (kBaseMap) {
    p.base_map->sample_quad(p.base_sampler, uv, texel);
    for (int lane = 0; lane < kQuadLanes; ++lane) out[lane].base_color *= texel[lane];
  }
  if constexpr (kMetallicRoughnessMap) {
    p.metallic_roughness_map->sample_quad(p.metallic_roughness_sampler, uv, texel);
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      out[lane].roughness *= texel[lane].y;
      out[lane].metallic *= texel[lane].z;
    }
  }
  if constexpr (kEmissionMap) {
    p.emission_map->sample_quad(p.emission_sampler, uv, texel);
    for (int lane = 0; lane < kQuadLanes; ++lane) out[lane].emission *= glm::vec3(texel[lane]);
  }
}

// The material over the quad plus the glTF MASK alpha test (3.9.4): returns the lanes left to
// shade; alpha-tested lanes below the cutoff are discarded in `out`.
template <bool kBaseMap, bool kAlphaTest, bool kMetallicRoughnessMap, bool kEmissionMap>
uint8_t evaluate_pbr_quad(const PbrMaterialParams& p, const QuadFragment& quad, QuadOutput& out,
                          SurfacePoint surface[kQuadLanes]) {
  evaluate_pbr_material<kBaseMap, kMetallicRoughnessMap, kEmissionMap>(p, quad, surface);
  uint8_t lanes = 0;
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    if (!quad.lane_active(lane)) continue;
    if (kAlphaTest && surface[lane].base_color.w < p.alpha_cutoff) {
      out.discard(lane);
      continue;
    }
    lanes |= static_cast<uint8_t>(1u << lane);
  }
  return lanes;
}

// The interpolated vertex normal, normalised and flipped for back faces (seen only on
// double-sided materials).
inline glm::vec3 shading_normal(const QuadFragment& quad, int lane) {
  const glm::vec3 n = quad.var3(MeshVertexShader::kNormal, lane);
  const float length = glm::length(n);
  const glm::vec3 unit = length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
  return quad.front_facing ? unit : -unit;
}

}  // namespace ontile
