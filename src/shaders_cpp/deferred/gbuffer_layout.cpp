// G-buffer presets and encoding (see gbuffer_layout.h).
#include "shaders_cpp/deferred/gbuffer_layout.h"

#include "util/error.h"

namespace ontile {

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

std::vector<std::string> gbuffer_layout_names() {
  return {"unity", "vulkan-samples", "vulkan-samples-large", "bjorge"};
}

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
  if (name == "bjorge") {
    l.light_in_gbuffer = true;
    l.albedo_format = PixelFormat::RGB10A2_UNORM;
    l.depth_format = PixelFormat::D24S8;
    return l;
  }
  throw Error("unknown G-buffer layout '" + name +
              "' (valid: unity, vulkan-samples, vulkan-samples-large, bjorge)");
}

}  // namespace ontile
