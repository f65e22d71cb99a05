// The physically based BRDF of the forward and deferred lit functors: Lambert diffuse plus a
// GGX (Trowbridge-Reitz) specular lobe with the height-correlated Smith visibility and Schlick
// Fresnel, as glTF 2.0 Appendix B specifies for metallic-roughness materials.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"

namespace ontile {

// What the BRDF needs of a surface point, in the form a G-buffer can hold.
struct BrdfInputs {
  glm::vec3 diffuse_color{0.0f};  // albedo x (1 - metallic)
  glm::vec3 f0{0.04f};            // specular reflectance at normal incidence
  float roughness = 1.0f;         // perceptual roughness (glTF), alpha = roughness^2
};

// glTF metallic-roughness to BRDF inputs: dielectrics reflect 4% at normal incidence, metals
// reflect their albedo and have no diffuse term (glTF 2.0 Appendix B.3.5).
inline BrdfInputs metallic_roughness_brdf(glm::vec3 base_color, float metallic, float roughness) {
  BrdfInputs b;
  b.diffuse_color = base_color * (1.0f - metallic);
  b.f0 = glm::mix(glm::vec3(0.04f), base_color, metallic);
  b.roughness = roughness;
  return b;
}

// BRDF inputs of a batch's fragments, structure-of-arrays.
struct BrdfBatch {
  alignas(64) float diffuse_color[3][kBatchFragments];
  alignas(64) float f0[3][kBatchFragments];
  alignas(64) float roughness[kBatchFragments];

  BrdfInputs at(int f) const {
    BrdfInputs b;
    b.diffuse_color = {diffuse_color[0][f], diffuse_color[1][f], diffuse_color[2][f]};
    b.f0 = {f0[0][f], f0[1][f], f0[2][f]};
    b.roughness = roughness[f];
    return b;
  }
};

// metallic_roughness_brdf for fragments [0, n), channel by channel with glm's operations:
// base * (1 - metallic) and mix(0.04, base, metallic) = 0.04 * (1 - metallic) + base * metallic.
inline void metallic_roughness_brdf(const float* const base_color[3], const float* metallic,
                                    const float* roughness, int n, BrdfBatch& out) {
  for (int c = 0; c < 3; ++c) {
    const float* base = base_color[c];
    for (int f = 0; f < n; ++f) {
      const float one_minus_metallic = 1.0f - metallic[f];
      out.diffuse_color[c][f] = base[f] * one_minus_metallic;
      out.f0[c][f] = 0.04f * one_minus_metallic + base[f] * metallic[f];
    }
  }
  for (int f = 0; f < n; ++f) out.roughness[f] = roughness[f];
}

// Perceptual roughness is clamped to 0.045 (Filament's minimum) so an 8-bit G-buffer value of
// 0 still gives a finite highlight in fp32.
constexpr float kMinPerceptualRoughness = 0.045f;

// Reflected radiance from one light: radiance x N.L x (diffuse + pi x specular BRDF). The light
// units follow the rest of ontile: a white light of radiance 1 lights a white Lambert surface
// facing it to 1 (the 1/pi of the Lambert BRDF is folded into the light, so the GGX term is
// scaled by pi to keep the two lobes in proportion).
inline glm::vec3 shade_ggx(const BrdfInputs& b, glm::vec3 n, glm::vec3 to_view, glm::vec3 to_light,
                           glm::vec3 radiance) {
  const float n_dot_l = glm::dot(n, to_light);
  if (!(n_dot_l > 0.0f)) return glm::vec3(0.0f);
  const float n_dot_v = std::max(glm::dot(n, to_view), 1e-4f);
  const glm::vec3 half_sum = to_light + to_view;
  const float half_length = glm::length(half_sum);
  const glm::vec3 h = half_length > 0.0f ? half_sum / half_length : n;
  const float n_dot_h = std::max(glm::dot(n, h), 0.0f);
  const float v_dot_h = std::max(glm::dot(to_view, h), 0.0f);
  const float r = std::max(b.roughness, kMinPerceptualRoughness);
  const float alpha2 = (r * r) * (r * r);
  // Trowbridge-Reitz distribution D.
  const float d_denominator = n_dot_h * n_dot_h * (alpha2 - 1.0f) + 1.0f;
  const float distribution = alpha2 / (3.14159265f * d_denominator * d_denominator);
  // Height-correlated Smith visibility V = G / (4 N.L N.V) (Heitz 2014, eq. 99).
  const float smith_l = n_dot_v * std::sqrt(n_dot_l * n_dot_l * (1.0f - alpha2) + alpha2);
  const float smith_v = n_dot_l * std::sqrt(n_dot_v * n_dot_v * (1.0f - alpha2) + alpha2);
  const float visibility = 0.5f / (smith_l + smith_v);
  // Schlick Fresnel.
  const float schlick = std::pow(1.0f - v_dot_h, 5.0f);
  const glm::vec3 fresnel = b.f0 + (glm::vec3(1.0f) - b.f0) * schlick;
  const glm::vec3 specular = fresnel * (distribution * visibility * 3.14159265f);
  return radiance * n_dot_l * (b.diffuse_color + specular);
}

}  // namespace ontile
