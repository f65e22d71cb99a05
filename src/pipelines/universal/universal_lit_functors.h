// Fragment functors of the universal Lit shader: the forward pass (Lambert diffuse + Blinn-Phong
// specular over a per-object list of at most 8 lights, main-light shadows), the alpha-clip
// functor the depth and shadow passes use for alpha-tested materials, and the DepthNormals
// functor. Template flags are the keyword variants (_BASEMAP, _ALPHATEST_ON, _EMISSION) and
// whether a main-light shadow map is bound (URP's _MAIN_LIGHT_SHADOWS).
#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include <glm/glm.hpp>

#include "pipelines/universal/main_light_shadows.h"
#include "pipelines/universal/main_light_shadows_batch.h"
#include "pipelines/universal/universal_lit_lighting.h"
#include "pipelines/universal/universal_normals.h"
#include "pipelines/universal/universal_lights.h"
#include "raster/shader_interface.h"
#include "raster/texel_trace.h"
#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/mesh_vertex_shader.h"
#include "shaders_cpp/toon/toon_outputs.h"

namespace ontile {

struct UniversalSurfaceParams {
  glm::vec4 base_color{1.0f};
  const Texture2D* base_map = nullptr;  // required by the _BASEMAP variants
  SamplerDesc base_sampler;
  float alpha_cutoff = 0.5f;
};

struct UniversalLitParams {
  UniversalSurfaceParams surface;
  float metallic = 0.0f;
  float smoothness = 0.5f;
  glm::vec3 emission{0.0f};                 // _EMISSION variants
  const Texture2D* emission_map = nullptr;  // optional in them
  SamplerDesc emission_sampler;
  glm::vec3 camera_position{0.0f};
  glm::vec3 ambient{0.2f};
  MainLight main_light;
  std::array<AdditionalLight, kMaxAdditionalLightsPerObject> additional_lights{};
  int additional_light_count = 0;
  ShadowLookup shadow;  // the shadow variants need shadow.map
};

// Blinn-Phong as URP's SimpleLit has it: specular power exp2(10 * smoothness + 1); the
// specular colour is 0.04 for dielectrics and the albedo for metals (glTF metallic-roughness,
// smoothness = 1 - roughness), the diffuse colour albedo x (1 - metallic). The highlight is
// scaled by N.L so it fades at the terminator instead of lighting back faces.
inline glm::vec3 blinn_phong(glm::vec3 diffuse_color, glm::vec3 specular_color, float shininess,
                             glm::vec3 n, glm::vec3 to_view, glm::vec3 to_light, glm::vec3 radiance) {
  const float n_dot_l = glm::dot(n, to_light);
  if (!(n_dot_l > 0.0f)) return glm::vec3(0.0f);
  const glm::vec3 half_vector = to_light + to_view;
  const float half_length = glm::length(half_vector);
  const float n_dot_h = half_length > 0.0f ? glm::max(glm::dot(n, half_vector / half_length), 0.0f) : 0.0f;
  return radiance * n_dot_l * (diffuse_color + specular_color * std::pow(n_dot_h, shininess));
}

// The non-template part: the lights this draw shades, inspectable by tests.
class UniversalLitFragment : public FragmentShader {
 public:
  explicit UniversalLitFragment(const UniversalLitParams& params) : p_(params) {}
  // Main light + the additional lights chosen for this object (at most kMaxLightsPerObject).
  int light_count() const { return 1 + p_.additional_light_count; }
  const UniversalLitParams& params() const { return p_; }

 protected:
  UniversalLitParams p_;
};

template <bool kBaseMap, bool kAlphaTest, bool kEmission, bool kShadows>
class UniversalLitShader final : public UniversalLitFragment {
 public:
  using UniversalLitFragment::UniversalLitFragment;
  bool may_discard() const override { return kAlphaTest; }
  // Outputs per quad; texels read quad by quad (base map, emission map, shadow taps).
  bool batches_across_triangles() const override { return true; }

  // Texture reads per quad in the per-quad functor's order: base map, emission map, then the
  // shadow-map lookups of the quad's kept fragments; then the lights fragment by fragment. The
  // shadow lookups of the whole batch run on SIMD lanes first when the map allows it (same
  // visibility bits), their texel trace is still emitted quad by quad.
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    const int n = batch.padded_fragment_count();
    const int count = batch.fragment_count();
    alignas(64) BatchVec4 albedo;
    alignas(64) BatchVec3 emissive, normal;
    alignas(64) float visibility[kBatchFragments];
    for (int c = 0; c < 4; ++c) {
      const float value = p_.surface.base_color[c];  // glm's operator[] is a switch: read it once
      for (int f = 0; f < n; ++f) albedo[c][f] = value;
    }
    for (int c = 0; c < 3; ++c) {
      const float value = p_.emission[c];  // glm's operator[] is a switch: read it once
      for (int f = 0; f < n; ++f) emissive[c][f] = value;
    }
    batch_unit_normals(batch, MeshVertexShader::kNormal, n, normal);
    [[maybe_unused]] ShadowBatch shadow_batch;
    [[maybe_unused]] bool batched_shadows = false;
    if constexpr (kShadows) {
      batched_shadows = shadow_batch_supported(p_.shadow);
      if (!batched_shadows) std::fill(visibility, visibility + n, 1.0f);  // read only where lit
      if (batched_shadows) {
        main_light_visibility_batch(p_.shadow, batch.varyings[MeshVertexShader::kWorldPos],
                                    batch.varyings[MeshVertexShader::kWorldPos + 1],
                                    batch.varyings[MeshVertexShader::kWorldPos + 2], normal,
                                    p_.main_light.to_light, n, shadow_batch);
      }
    }
    const uint64_t lit = !kShadows || batched_shadows
                             ? surface_batch(batch, shadow_batch, albedo, emissive, out)
                             : surface_per_quad(batch, normal, albedo, emissive, visibility, out);
    alignas(64) BatchVec3 rgb;
    const float* main_visibility = nullptr;
    if constexpr (kShadows) main_visibility = batched_shadows ? shadow_batch.visibility : visibility;
    universal_lit_lighting(p_, batch, normal, albedo, main_visibility, lit, count, rgb);
    // Every fragment's output is written, lit or not: the core stores only the kept fragments'.
    for (int c = 0; c < 3; ++c) {
      for (int f = 0; f < count; ++f) out.color[0][c][f] = kEmission ? rgb[c][f] + emissive[c][f] : rgb[c][f];
    }
    for (int f = 0; f < count; ++f) out.color[0][3][f] = albedo[3][f];
  }

 private:
  // What the shadow trace of a quad needs: its kept fragments are the active ones whose albedo
  // alpha (base_alpha x the base map's, as albedo has it) passes the alpha test.
  struct ShadowTraceOfQuads {
    const UniversalLitParams* params;
    const FragmentBatch* batch;
    const ShadowBatch* shadows;
    const float* base_map_alpha;  // texel alpha per fragment (_BASEMAP), else null
  };
  static int append_shadow_trace(const void* context, int q, uint64_t* out, uint64_t& last) {
    const ShadowTraceOfQuads& trace = *static_cast<const ShadowTraceOfQuads*>(context);
    const UniversalLitParams& p = *trace.params;
    unsigned lanes = trace.batch->lane_mask[q] & 0xFu;
    if constexpr (kAlphaTest) {
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        const float base_alpha = p.surface.base_color.w;
        const float alpha = kBaseMap ? base_alpha * trace.base_map_alpha[q * kQuadLanes + lane] : base_alpha;
        if (alpha < p.surface.alpha_cutoff) lanes &= ~(1u << lane);
      }
    }
    return shadow_quad_granules(p.shadow, *trace.shadows, q, lanes, out, last);
  }

  // The surface reads of the batch in one Texture2D::sample_quads call, the shadow taps (when
  // batched) traced after each quad's reads by its hook: the per-quad trace order of
  // surface_per_quad. Discards alpha-tested fragments; returns the kept (lit) ones.
  uint64_t surface_batch(const FragmentBatch& batch, const ShadowBatch& shadow_batch, BatchVec4& albedo,
                         BatchVec3& emissive, BatchOutput& out) const {
    alignas(64) BatchVec4 base_texel, emission_texel;
    Texture2D::QuadRead reads[2];
    int read_count = 0;
    if constexpr (kBaseMap) reads[read_count++] = batch_texture_read(p_.surface.base_map, p_.surface.base_sampler, base_texel);
    const bool emission_read = kEmission && p_.emission_map;  // glTF 2.0 3.9.3: factor x texture
    if (emission_read) reads[read_count++] = batch_texture_read(p_.emission_map, p_.emission_sampler, emission_texel);
    const ShadowTraceOfQuads shadow_trace{&p_, &batch, &shadow_batch, kBaseMap ? base_texel[3] : nullptr};
    const Texture2D::QuadTraceHook hook{&append_shadow_trace, &shadow_trace, kMaxShadowQuadGranules};
    if (read_count > 0) {
      Texture2D::sample_quads(reads, read_count, batch.varyings[MeshVertexShader::kUv],
                              batch.varyings[MeshVertexShader::kUv + 1], batch.quad_count,
                              kShadows ? &hook : nullptr);
    } else if (kShadows && texel_trace_detail::sink) {
      for (int q = 0; q < batch.quad_count; ++q) {
        uint64_t granules[kMaxShadowQuadGranules];
        const int kept = append_shadow_trace(&shadow_trace, q, granules, texel_trace_detail::last_granule);
        texel_trace_detail::sink->insert(texel_trace_detail::sink->end(), granules, granules + kept);
      }
    }
    if constexpr (kBaseMap) batch_multiply_quads(albedo, 4, batch.quad_count, base_texel);
    if (emission_read) batch_multiply_quads(emissive, 3, batch.quad_count, emission_texel);
    uint64_t lit = batch.active_mask();
    if constexpr (kAlphaTest) {
      for (uint64_t rest = lit; rest != 0; rest &= rest - 1) {
        const int f = std::countr_zero(rest);
        if (albedo[3][f] < p_.surface.alpha_cutoff) {
          out.discard(f);
          lit &= ~(uint64_t{1} << f);
        }
      }
    }
    return lit;
  }

  // The surface reads quad by quad, each quad's shadow lookups (fragment by fragment, for maps
  // the batched lookups cannot read) after them.
  uint64_t surface_per_quad(const FragmentBatch& batch, const BatchVec3& normal, BatchVec4& albedo,
                            BatchVec3& emissive, float* visibility, BatchOutput& out) const {
    uint64_t lit = 0;
    for (int q = 0; q < batch.quad_count; ++q) {
      glm::vec2 uv[kQuadLanes];
      batch_quad_uv(batch, MeshVertexShader::kUv, q, uv);
      glm::vec4 texel[kQuadLanes];
      if constexpr (kBaseMap) {
        p_.surface.base_map->sample_quad(p_.surface.base_sampler, uv, texel);
        batch_multiply_quad(albedo, 4, q, texel);
      }
      if constexpr (kEmission) {
        if (p_.emission_map) {  // glTF 2.0 3.9.3: emissiveFactor x emissiveTexture
          p_.emission_map->sample_quad(p_.emission_sampler, uv, texel);
          batch_multiply_quad(emissive, 3, q, texel);
        }
      }
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        const int f = q * kQuadLanes + lane;
        if (!batch.active(f)) continue;
        if constexpr (kAlphaTest) {
          if (albedo[3][f] < p_.surface.alpha_cutoff) {
            out.discard(f);
            continue;
          }
        }
        lit |= uint64_t{1} << f;
        visibility[f] = main_light_visibility(p_.shadow, batch_var3(batch, MeshVertexShader::kWorldPos, f),
                                              batch_get3(normal, f), p_.main_light.to_light);
      }
    }
    return lit;
  }
};

// Alpha-tested depth-only and shadow-caster draws: writes no colour, discards where the base
// colour's alpha is below the cutoff (so holes cast no shadow and leave no depth).
template <bool kBaseMap>
class UniversalAlphaClipShader final : public FragmentShader {
 public:
  explicit UniversalAlphaClipShader(const UniversalSurfaceParams& params) : p_(params) {}
  bool may_discard() const override { return true; }
  bool batches_across_triangles() const override { return true; }  // outputs and texels per quad
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    alignas(64) float alpha[kBatchFragments];
    surface_alpha(p_, batch, alpha);
    discard_below_cutoff(p_, batch, alpha, out);
  }
  // The base colour's alpha of quads < quad_count, the batch's texels read in one call.
  static void surface_alpha(const UniversalSurfaceParams& p, const FragmentBatch& batch,
                            float alpha[kBatchFragments]) {
    for (int f = 0; f < batch.fragment_count(); ++f) alpha[f] = p.base_color.w;
    if constexpr (kBaseMap) {
      alignas(64) BatchVec4 texel;
      const Texture2D::QuadRead read = batch_texture_read(p.base_map, p.base_sampler, texel);
      Texture2D::sample_quads(&read, 1, batch.varyings[MeshVertexShader::kUv],
                              batch.varyings[MeshVertexShader::kUv + 1], batch.quad_count);
      for (int f = 0; f < batch.quad_count * kQuadLanes; ++f) alpha[f] *= texel[3][f];
    }
  }
  static void discard_below_cutoff(const UniversalSurfaceParams& p, const FragmentBatch& batch,
                                   const float alpha[kBatchFragments], BatchOutput& out) {
    for (int f = 0; f < batch.fragment_count(); ++f) {
      if (batch.active(f) && alpha[f] < p.alpha_cutoff) out.discard(f);
    }
  }

 private:
  UniversalSurfaceParams p_;
};

// URP's DepthNormals pass: the unit view-space normal, encoded n * 0.5 + 0.5 for the RGB10A2
// normals target (toon_outputs.h's Unorm encoding, which the Sobel edge functor decodes).
template <bool kAlphaTest, bool kBaseMap>
class UniversalDepthNormalsShader final : public FragmentShader {
 public:
  UniversalDepthNormalsShader(const UniversalSurfaceParams& params, const glm::mat3& world_to_view)
      : p_(params), world_to_view_(world_to_view) {}
  bool may_discard() const override { return kAlphaTest; }
  bool batches_across_triangles() const override { return true; }  // outputs and texels per quad
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    if constexpr (kAlphaTest) {
      alignas(64) float alpha[kBatchFragments];
      UniversalAlphaClipShader<kBaseMap>::surface_alpha(p_, batch, alpha);
      UniversalAlphaClipShader<kBaseMap>::discard_below_cutoff(p_, batch, alpha, out);
    }
    // Padding lanes too (the core stores only the batch's fragments).
    universal_encoded_view_normals(batch, MeshVertexShader::kNormal, world_to_view_,
                                   batch.padded_fragment_count(), out.color[0]);
  }

 private:
  UniversalSurfaceParams p_;
  glm::mat3 world_to_view_;
};

}  // namespace ontile
