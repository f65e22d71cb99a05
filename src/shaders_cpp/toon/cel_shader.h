// Cel (toon) shading with one directional light: fully lit where the surface faces the light,
// and `steps` flat shadow bands beyond the terminator, mixing a lit and a shadow colour (or
// textures: the kTextures variant).
#pragma once
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/toon/toon_outputs.h"
#include "shaders_cpp/toon/toon_vertex_shader.h"
#include "util/error.h"

namespace ontile {

// Shadow amount for d = dot(N, L): 0 when d >= 0 (fully lit), else
// min(1, ceil(-d / step_size) / steps). With steps = 1 any d < 0 is full shadow (classic cel
// shading); with steps = n and step_size = 1/n, d in [-k/n, -(k-1)/n) gives k/n. NaN -> 1.
float cel_shadow_factor(float n_dot_l, int steps, float step_size);

// colour[c][f] = mix(lit[c][f], shadow[c][f], cel_shadow_factor(dot(normal_f, to_light), steps,
// step_size)) for fragments [0, n) rounded up to whole vectors (n <= kBatchFragments), on SIMD
// lanes with the same bits.
void cel_mix_batch(const BatchVec3& normal, const glm::vec3& to_light, int steps, float step_size,
                   const BatchVec4& lit, const BatchVec4& shadow, int n, BatchVec4& colour);

struct CelParams {
  glm::vec3 to_light{0.0f, 1.0f, 0.0f};  // unit vector towards the light, world space
  int steps = 1;                         // >= 1
  float step_size = 0.0f;                // > 0; <= 0 means the default 1 / steps
  glm::vec4 lit_color{1.0f};
  glm::vec4 shadow_color{0.45f, 0.45f, 0.55f, 1.0f};
  // kTextures: each colour is multiplied by its texture at TEXCOORD_0; a null map is skipped
  // (that colour stays a constant).
  const Texture2D* lit_map = nullptr;
  SamplerDesc lit_sampler;
  const Texture2D* shadow_map = nullptr;
  SamplerDesc shadow_sampler;
  ToonOutputParams outputs;
};

// Colour = mix(lit, shadow, cel_shadow_factor(dot(N, L), steps, step_size)), RGBA, with N the
// unit interpolated world normal (flipped on back faces).
template <uint32_t kOutputs, bool kTextures>
class CelShader final : public FragmentShader {
  static_assert(is_valid_toon_output_mask(kOutputs), "kOutputs must be a ToonOutput mask");

 public:
  explicit CelShader(const CelParams& params) : p_(params) {
    if (p_.steps < 1) {
      throw Error("CelShader: steps must be at least 1 (got " + std::to_string(p_.steps) + ")");
    }
    if (!(p_.step_size > 0.0f)) p_.step_size = 1.0f / static_cast<float>(p_.steps);
    one_map_ = p_.lit_map && p_.lit_map == p_.shadow_map && p_.lit_sampler == p_.shadow_sampler;
  }

  // Per-fragment arithmetic and per-quad texture reads (lit, then shadow map, quad by quad).
  bool batches_across_triangles() const override { return true; }
  // The view normal (every output mask), the world normal for the colour and the UV for its
  // maps: the raster core interpolates only these (not the world position or the tangent).
  uint32_t varyings_read() const override {
    constexpr uint32_t kViewNormalBits = 7u << ToonVertexShader::kViewNormal;
    constexpr uint32_t kNormalBits = 7u << ToonVertexShader::kNormal, kUvBits = 3u << ToonVertexShader::kUv;
    constexpr bool kColorOutput = (kOutputs & ToonOutput::kColor) != 0u;
    return kViewNormalBits | (kColorOutput ? kNormalBits : 0u) | (kColorOutput && kTextures ? kUvBits : 0u);
  }

  // Colour (shade_color) and write_toon_normal_and_border fill every padded fragment.
  int outputs_always_written() const override { return toon_output_count(kOutputs); }
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    alignas(64) BatchVec3 view_normal;
    batch_unit_normals(batch, ToonVertexShader::kViewNormal, batch.padded_fragment_count(), view_normal);
    if constexpr ((kOutputs & ToonOutput::kColor) != 0u) shade_color(batch, out);
    write_toon_normal_and_border<kOutputs>(batch, out, view_normal, p_.outputs);
  }

 private:
  void shade_color(const FragmentBatch& batch, BatchOutput& out) const {
    const int n = batch.padded_fragment_count();
    alignas(64) BatchVec4 lit, shadow;
    for (int c = 0; c < 4; ++c) {
      // glm's operator[] is a switch: read each factor once so the fills vectorise.
      const float lit_value = p_.lit_color[c], shadow_value = p_.shadow_color[c];
      for (int f = 0; f < n; ++f) {
        lit[c][f] = lit_value;
        shadow[c][f] = shadow_value;
      }
    }
    if constexpr (kTextures) {
      // All quads' texels in one call, per quad lit then shadow map (the texel trace's order).
      // Both colours from one image: the two sample instructions read the same texels (traced
      // twice, fetches = 2) and return the same value, filtered once.
      const float* u = batch.varyings[ToonVertexShader::kUv];
      const float* v = batch.varyings[ToonVertexShader::kUv + 1];
      alignas(64) BatchVec4 lit_texel, shadow_texel;
      Texture2D::QuadRead reads[2];
      int read_count = 0;
      if (one_map_) {
        reads[read_count++] = batch_texture_read(p_.lit_map, p_.lit_sampler, lit_texel, 2);
      } else {
        if (p_.lit_map) reads[read_count++] = batch_texture_read(p_.lit_map, p_.lit_sampler, lit_texel);
        if (p_.shadow_map) reads[read_count++] = batch_texture_read(p_.shadow_map, p_.shadow_sampler, shadow_texel);
      }
      Texture2D::sample_quads(reads, read_count, u, v, batch.quad_count);
      if (p_.lit_map) batch_multiply_quads(lit, 4, batch.quad_count, lit_texel);
      if (one_map_) {
        batch_multiply_quads(shadow, 4, batch.quad_count, lit_texel);
      } else if (p_.shadow_map) {
        batch_multiply_quads(shadow, 4, batch.quad_count, shadow_texel);
      }
    }
    alignas(64) BatchVec3 normal;
    batch_unit_normals(batch, ToonVertexShader::kNormal, n, normal);
    cel_mix_batch(normal, p_.to_light, p_.steps, p_.step_size, lit, shadow, n, out.color[0]);
  }

  CelParams p_;
  bool one_map_ = false;  // lit and shadow maps are one texture with one sampler
};

}  // namespace ontile
