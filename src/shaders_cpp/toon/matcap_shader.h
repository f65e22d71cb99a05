// MatCap ("material capture", lit sphere) fragment functor: the view-space normal picks a texel
// of a painted sphere, so a whole lighting model comes from one bilinear lookup. Variants: base
// colour map (kBaseMap) and tangent-space normal map (kNormalMap, the NORMAL_MAP keyword).
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/toon/toon_outputs.h"
#include "shaders_cpp/toon/toon_vertex_shader.h"
#include "util/error.h"

namespace ontile {

// MatCap texture coordinates of a unit view-space normal (+X right, +Y up, +Z towards the
// camera): u = 0.5 + 0.5 * n.x, v = 0.5 - 0.5 * n.y. v is flipped because texture v = 0 is the
// top row: a normal pointing up (+Y view) reads the top of the image, (0,0,1) its centre, and
// (1,0,0) the middle of the right edge.
inline glm::vec2 matcap_uv(glm::vec3 view_normal) {
  return {0.5f + 0.5f * view_normal.x, 0.5f - 0.5f * view_normal.y};
}

// The MatCap sampler: bilinear, clamp to edge, base level only (MipmapMode::None). The uv of
// neighbouring pixels can jump across the sphere on creases, which would select blurry mips.
SamplerDesc matcap_sampler();

// glTF 2.0 3.9.3 normalTexture: n = normalize((texel * 2 - 1) * (scale, scale, 1)).
glm::vec3 decode_tangent_space_normal(glm::vec4 texel, float normal_scale);

// Tangent space -> world with the TBN frame of glTF 2.0 3.7.2.1: N = unit world normal,
// T = tangent.xyz made perpendicular to N (Gram-Schmidt), B = cross(N, T) * tangent.w. A zero or
// degenerate tangent (a mesh without TANGENT) returns N unperturbed. Result is unit length.
glm::vec3 perturb_normal(glm::vec3 unit_world_normal, glm::vec4 world_tangent,
                         glm::vec3 tangent_space_normal);

struct MatCapParams {
  const Texture2D* matcap = nullptr;  // required; sampled with matcap_sampler()
  glm::vec4 base_color{1.0f};         // multiplies the MatCap colour; alpha is the output alpha
  const Texture2D* base_map = nullptr;  // kBaseMap: required (sRGB base colour texture)
  SamplerDesc base_sampler;
  const Texture2D* normal_map = nullptr;  // kNormalMap: required (linear tangent-space normals)
  SamplerDesc normal_sampler;
  float normal_scale = 1.0f;
  glm::mat3 world_to_view{1.0f};  // rotation part of the view matrix (kNormalMap only)
  ToonOutputParams outputs;
};

// Colour = MatCap(matcap_uv(n)).rgb x base colour factor [x base map], alpha = base alpha.
// n is the interpolated view-space normal, or with kNormalMap the normal-mapped world normal
// rotated to view space. The normal output is always the geometric (interpolated) view normal:
// normal-map detail would otherwise light up the screen-space normal edges everywhere.
template <uint32_t kOutputs, bool kBaseMap, bool kNormalMap>
class MatCapShader final : public FragmentShader {
  static_assert(is_valid_toon_output_mask(kOutputs), "kOutputs must be a ToonOutput mask");

 public:
  explicit MatCapShader(const MatCapParams& params) : p_(params), matcap_sampler_(matcap_sampler()) {
    if ((kOutputs & ToonOutput::kColor) == 0u) return;
    if (!p_.matcap) throw Error("MatCapShader: no MatCap texture");
    if (kBaseMap && !p_.base_map) throw Error("MatCapShader: base-map variant without a base map");
    if (kNormalMap && !p_.normal_map) {
      throw Error("MatCapShader: NORMAL_MAP variant without a normal map");
    }
  }

  // Per-fragment arithmetic; texture reads quad by quad (normal map, MatCap, base map).
  bool batches_across_triangles() const override { return true; }
  // The view normal; for the colour the UV, and with kNormalMap the world normal and tangent:
  // the raster core interpolates only these (not the world position).
  uint32_t varyings_read() const override {
    constexpr uint32_t kViewNormalBits = 7u << ToonVertexShader::kViewNormal;
    constexpr uint32_t kUvBits = 3u << ToonVertexShader::kUv;
    constexpr uint32_t kNormalMapBits = (7u << ToonVertexShader::kNormal) | (15u << ToonVertexShader::kTangent);
    if constexpr ((kOutputs & ToonOutput::kColor) == 0u) return kViewNormalBits;
    return kViewNormalBits | kUvBits | (kNormalMap ? kNormalMapBits : 0u);
  }

  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    alignas(64) BatchVec3 view_normal;
    batch_unit_normals(batch, ToonVertexShader::kViewNormal, batch.padded_fragment_count(), view_normal);
    if constexpr ((kOutputs & ToonOutput::kColor) != 0u) shade_color(batch, view_normal, out);
    write_toon_normal_and_border<kOutputs>(batch, out, view_normal, p_.outputs);
  }

 private:
  // Texture reads per quad in the per-quad functor's order (normal map, MatCap, base map), then
  // the colour product over all fragments.
  void shade_color(const FragmentBatch& batch, const BatchVec3& view_normal, BatchOutput& out) const {
    const int n = batch.padded_fragment_count();
    alignas(64) BatchVec3 world_normal;
    if constexpr (kNormalMap) batch_unit_normals(batch, ToonVertexShader::kNormal, n, world_normal);
    alignas(64) BatchVec4 matcap, albedo;
    for (int c = 0; c < 4; ++c) {
      const float value = p_.base_color[c];  // glm's operator[] is a switch: read it once
      for (int f = 0; f < n; ++f) albedo[c][f] = value;
    }
    for (int q = 0; q < batch.quad_count; ++q) {
      const int f0 = q * kQuadLanes;
      glm::vec2 uv[kQuadLanes];
      batch_quad_uv(batch, ToonVertexShader::kUv, q, uv);
      glm::vec2 matcap_coords[kQuadLanes];
      glm::vec4 texel[kQuadLanes];
      if constexpr (kNormalMap) {
        p_.normal_map->sample_quad(p_.normal_sampler, uv, texel);
        for (int lane = 0; lane < kQuadLanes; ++lane) {
          const int f = f0 + lane;
          const glm::vec4 tangent(batch_var3(batch, ToonVertexShader::kTangent, f),
                                  batch.varyings[ToonVertexShader::kTangent + 3][f]);
          const glm::vec3 mapped = perturb_normal(batch_get3(world_normal, f), tangent,
                                                  decode_tangent_space_normal(texel[lane], p_.normal_scale));
          matcap_coords[lane] = matcap_uv(toon_unit_normal(p_.world_to_view * mapped, true));
        }
      } else {
        for (int lane = 0; lane < kQuadLanes; ++lane) {
          matcap_coords[lane] = matcap_uv(batch_get3(view_normal, f0 + lane));
        }
      }
      p_.matcap->sample_quad(matcap_sampler_, matcap_coords, texel);
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        for (int c = 0; c < 4; ++c) matcap[c][f0 + lane] = texel[lane][c];
      }
      if constexpr (kBaseMap) {
        p_.base_map->sample_quad(p_.base_sampler, uv, texel);
        batch_multiply_quad(albedo, 4, q, texel);
      }
    }
    // Only quads < quad_count have MatCap values: the rest is padding whose outputs are ignored.
    const int real = batch.fragment_count();
    for (int c = 0; c < 3; ++c) {
      for (int f = 0; f < real; ++f) out.color[0][c][f] = matcap[c][f] * albedo[c][f];
    }
    for (int f = 0; f < real; ++f) out.color[0][3][f] = albedo[3][f];
  }

  MatCapParams p_;
  SamplerDesc matcap_sampler_;
};

}  // namespace ontile
