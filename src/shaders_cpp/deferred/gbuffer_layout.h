// G-buffer layouts of the deferred pipelines as named presets (formats and what each channel
// holds), and the encoding of a surface point into the targets and back into BRDF inputs.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "raster/pixel_format.h"
#include "shaders_cpp/lighting/brdf.h"

namespace ontile {

struct GBufferLayout {
  std::string name;
  // The lighting result. When light_in_gbuffer, the G-buffer pass already writes ambient (GI)
  // and emission into it and the lighting pass adds the lights by blending (Unity 2018).
  PixelFormat light_format = PixelFormat::RGBA8_SRGB;
  bool light_in_gbuffer = false;
  // G-buffer targets, in subpass output order: albedo, [specular], normal.
  PixelFormat albedo_format = PixelFormat::RGBA8_UNORM;
  bool has_specular = false;
  PixelFormat specular_format = PixelFormat::RGBA8_UNORM;
  PixelFormat normal_format = PixelFormat::RGB10A2_UNORM;
  PixelFormat depth_format = PixelFormat::D32_FLOAT;

  int target_count() const { return has_specular ? 3 : 2; }
  std::vector<PixelFormat> target_formats() const;
  std::vector<std::string> target_names() const;
  // Tile-memory colour bits per pixel of the light target plus the G-buffer targets (depth is
  // held separately, as on Mali).
  int color_bits_per_px() const;
};

// "unity": "Maximizing Rendering Efficiency" (SIGGRAPH 2018): diffuse RGBA8 (diffuse colour,
//   occlusion), specular RGBA8 (F0, smoothness), normal RGB10A2, light accumulation RGBA16F
//   (GI + emissive from the G-buffer pass), depth D32F: 160 colour bits.
// "vulkan-samples": Khronos Vulkan-Samples render_subpasses: light RGBA8 sRGB, albedo RGBA8
//   (base colour, roughness), normal RGB10A2 (normal, 2-bit metallic), depth D32F: 96 bits.
// "vulkan-samples-large": the sample's "G-buffer size > 128 bits" setting: albedo and normal
//   RGBA16F (160 bits).
// "bjorge": Bjorge, "Bandwidth efficient graphics with ARM Mali GPUs" (GPU Pro 5): RGBA8 sRGB
//   light (the 32-bit framebuffer, started by the G-buffer pass with ambient and emission, lights
//   added by blending), albedo RGB10A2 (2-bit roughness in alpha), normal RGB10A2, depth D24S8:
//   96 colour bits, every target 4 bytes per pixel.
// Throws ontile::Error naming the valid presets for anything else.
GBufferLayout gbuffer_layout(const std::string& name);
std::vector<std::string> gbuffer_layout_names();

struct GBufferSurface {
  glm::vec3 base_color{1.0f};
  float metallic = 0.0f;
  float roughness = 1.0f;
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit, world space
};

namespace gbuffer_detail {

inline bool is_float_format(PixelFormat f) {
  return f == PixelFormat::RGBA16_FLOAT || f == PixelFormat::RGBA32_FLOAT || f == PixelFormat::RG16_FLOAT;
}

// Unsigned-normalised targets hold n * 0.5 + 0.5 (Vulkan-Samples geometry.frag); float
// targets hold the signed normal.
inline glm::vec3 encode_normal(PixelFormat f, glm::vec3 n) { return is_float_format(f) ? n : n * 0.5f + 0.5f; }

inline glm::vec3 decode_normal(PixelFormat f, glm::vec3 stored) {
  const glm::vec3 n = is_float_format(f) ? stored : stored * 2.0f - 1.0f;
  const float length = glm::length(n);
  return length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

}  // namespace gbuffer_detail

// Target values (target_count() of them) for one surface point, before quantisation. Inline:
// the batched functors call it once per fragment.
inline void encode_gbuffer(const GBufferLayout& l, const GBufferSurface& s, glm::vec4* targets) {
  const glm::vec3 n = gbuffer_detail::encode_normal(l.normal_format, s.normal);
  if (l.has_specular) {
    // Unity's StandardSpecular layout: diffuse colour + occlusion, F0 + smoothness.
    const BrdfInputs b = metallic_roughness_brdf(s.base_color, s.metallic, s.roughness);
    targets[0] = glm::vec4(b.diffuse_color, 1.0f);
    targets[1] = glm::vec4(b.f0, 1.0f - s.roughness);
    targets[2] = glm::vec4(n, 1.0f);
    return;
  }
  // Metallic goes into the normal target's alpha: 2 bits in RGB10A2 (0, 1/3, 2/3, 1), which
  // keeps the layout within the sample's 128-bit budget.
  targets[0] = glm::vec4(s.base_color, s.roughness);
  targets[1] = glm::vec4(n, s.metallic);
}

struct DecodedGBuffer {
  BrdfInputs brdf;
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit
};

inline DecodedGBuffer decode_gbuffer(const GBufferLayout& l, const glm::vec4* targets) {
  DecodedGBuffer d;
  if (l.has_specular) {
    d.brdf.diffuse_color = glm::vec3(targets[0]);
    d.brdf.f0 = glm::vec3(targets[1]);
    d.brdf.roughness = 1.0f - targets[1].w;
    d.normal = gbuffer_detail::decode_normal(l.normal_format, glm::vec3(targets[2]));
    return d;
  }
  d.brdf = metallic_roughness_brdf(glm::vec3(targets[0]), targets[1].w, targets[0].w);
  d.normal = gbuffer_detail::decode_normal(l.normal_format, glm::vec3(targets[1]));
  return d;
}

}  // namespace ontile
