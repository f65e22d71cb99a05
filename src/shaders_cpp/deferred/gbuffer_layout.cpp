// G-buffer presets and encoding (see gbuffer_layout.h).
#include "shaders_cpp/deferred/gbuffer_layout.h"

#include "util/error.h"

namespace ontile {
namespace {

bool is_float_format(PixelFormat f) {
  return f == PixelFormat::RGBA16_FLOAT || f == PixelFormat::RGBA32_FLOAT || f == PixelFormat::RG16_FLOAT;
}

// Unsigned-normalised targets hold n * 0.5 + 0.5 (Vulkan-Samples geometry.frag); float
// targets hold the signed normal.
glm::vec3 encode_normal(PixelFormat f, glm::vec3 n) { return is_float_format(f) ? n : n * 0.5f + 0.5f; }

glm::vec3 decode_normal(PixelFormat f, glm::vec3 stored) {
  const glm::vec3 n = is_float_format(f) ? stored : stored * 2.0f - 1.0f;
  const float length = glm::length(n);
  return length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

}  // namespace

std::vector<PixelFormat> GBufferLayout::target_formats() const {
  if (has_specular) return {albedo_format, specular_format, normal_format};
  return {albedo_format, normal_format};
}

std::vector<std::string> GBufferLayout::target_names() const {
  if (has_specular) return {"diffuse", "specular", "normal"};
  return {"albedo", "normal"};
}

int GBufferLayout::color_bits_per_px() const {
  int bits = bits_per_pixel(light_format);
  for (PixelFormat f : target_formats()) bits += bits_per_pixel(f);
  return bits;
}

std::vector<std::string> gbuffer_layout_names() { return {"unity", "vulkan-samples", "vulkan-samples-large"}; }

GBufferLayout gbuffer_layout(const std::string& name) {
  GBufferLayout l;
  l.name = name;
  if (name == "unity") {
    l.light_format = PixelFormat::RGBA16_FLOAT;
    l.light_in_gbuffer = true;
    l.has_specular = true;
    return l;
  }
  if (name == "vulkan-samples") return l;
  if (name == "vulkan-samples-large") {
    l.albedo_format = PixelFormat::RGBA16_FLOAT;
    l.normal_format = PixelFormat::RGBA16_FLOAT;
    return l;
  }
  throw Error("unknown G-buffer layout '" + name + "' (valid: unity, vulkan-samples, vulkan-samples-large)");
}

void encode_gbuffer(const GBufferLayout& l, const GBufferSurface& s, glm::vec4* targets) {
  const glm::vec3 n = encode_normal(l.normal_format, s.normal);
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

DecodedGBuffer decode_gbuffer(const GBufferLayout& l, const glm::vec4* targets) {
  DecodedGBuffer d;
  if (l.has_specular) {
    d.brdf.diffuse_color = glm::vec3(targets[0]);
    d.brdf.f0 = glm::vec3(targets[1]);
    d.brdf.roughness = 1.0f - targets[1].w;
    d.normal = decode_normal(l.normal_format, glm::vec3(targets[2]));
    return d;
  }
  d.brdf = metallic_roughness_brdf(glm::vec3(targets[0]), targets[1].w, targets[0].w);
  d.normal = decode_normal(l.normal_format, glm::vec3(targets[1]));
  return d;
}

}  // namespace ontile
