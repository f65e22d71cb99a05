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
// Throws ontile::Error naming the valid presets for anything else.
GBufferLayout gbuffer_layout(const std::string& name);
std::vector<std::string> gbuffer_layout_names();

struct GBufferSurface {
  glm::vec3 base_color{1.0f};
  float metallic = 0.0f;
  float roughness = 1.0f;
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit, world space
};

// Target values (target_count() of them) for one surface point, before quantisation.
void encode_gbuffer(const GBufferLayout& layout, const GBufferSurface& surface, glm::vec4* targets);

struct DecodedGBuffer {
  BrdfInputs brdf;
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit
};
DecodedGBuffer decode_gbuffer(const GBufferLayout& layout, const glm::vec4* targets);

}  // namespace ontile
