// Analytic MatCap spheres and MatCap file loading (see matcap_generator.h). Shading happens in
// view space (+Z towards the viewer, +Y up) with the key light above left, in front.
#include "shaders_cpp/toon/matcap_generator.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "raster/pixel_format.h"
#include "shaders_cpp/toon/image_texture.h"
#include "util/error.h"

namespace ontile {
namespace {

const glm::vec3 kKeyLight = glm::normalize(glm::vec3(-0.45f, 0.65f, 0.6f));
const glm::vec3 kKickerLight = glm::normalize(glm::vec3(0.75f, 0.15f, 0.45f));

float smoothstep01(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Mirror reflection of the view ray (0, 0, -1) about n.
glm::vec3 reflected_view(glm::vec3 n) { return 2.0f * n.z * n - glm::vec3(0.0f, 0.0f, 1.0f); }

glm::vec3 shade_clay(glm::vec3 n) {
  const glm::vec3 albedo(0.58f, 0.53f, 0.48f);
  // Wrapped diffuse (light reaches 0.35 past the terminator) for a soft, chalky falloff.
  const float wrapped = std::clamp((glm::dot(n, kKeyLight) + 0.35f) / 1.35f, 0.0f, 1.0f);
  const float diffuse = 0.16f + 0.84f * smoothstep01(0.0f, 1.0f, wrapped);
  const float rim = 0.09f * std::pow(1.0f - n.z, 3.0f);
  const float sheen = 0.04f * std::pow(std::max(glm::dot(reflected_view(n), kKeyLight), 0.0f), 6.0f);
  return albedo * diffuse + glm::vec3(1.0f, 0.96f, 0.9f) * rim + glm::vec3(sheen);
}

glm::vec3 shade_metal(glm::vec3 n) {
  const glm::vec3 r = reflected_view(n);
  // Environment seen in reflection: sky fading up from a bright horizon, a sharp horizon band,
  // and a dark ground below.
  glm::vec3 env;
  if (r.y >= 0.0f) {
    env = glm::mix(glm::vec3(0.85f, 0.87f, 0.9f), glm::vec3(0.42f, 0.46f, 0.52f),
                   smoothstep01(0.0f, 0.7f, r.y));
  } else {
    env = glm::mix(glm::vec3(0.22f, 0.21f, 0.2f), glm::vec3(0.025f), smoothstep01(0.0f, 0.4f, -r.y));
  }
  env += glm::vec3(0.9f) * std::exp(-(r.y / 0.05f) * (r.y / 0.05f));
  const float key = std::pow(std::max(glm::dot(r, kKeyLight), 0.0f), 160.0f);
  const float kicker = std::pow(std::max(glm::dot(r, kKickerLight), 0.0f), 400.0f);
  const glm::vec3 tint(0.9f, 0.91f, 0.93f);
  return tint * env + glm::vec3(2.0f * key + 0.9f * kicker);
}

glm::vec3 shade_painted(glm::vec3 n) {
  const glm::vec3 lit(0.9f, 0.85f, 0.78f);
  const glm::vec3 mid(0.62f, 0.56f, 0.54f);
  const glm::vec3 shadow(0.3f, 0.3f, 0.4f);  // cool shadows, as painters use
  const float d = glm::dot(n, kKeyLight);
  glm::vec3 c = d > 0.4f ? lit : (d > -0.15f ? mid : shadow);
  if (glm::dot(reflected_view(n), kKeyLight) > 0.97f) c = glm::vec3(1.0f);
  return c;
}

glm::vec3 shade(MatCapStyle style, glm::vec3 n) {
  switch (style) {
    case MatCapStyle::Metal: return shade_metal(n);
    case MatCapStyle::Clay: return shade_clay(n);
    case MatCapStyle::Painted: return shade_painted(n);
  }
  return shade_clay(n);
}

// The view-space normal whose matcap_uv is (u, v); points outside the disc take the rim normal.
glm::vec3 normal_at(float u, float v) {
  const float x = 2.0f * u - 1.0f;
  const float y = 1.0f - 2.0f * v;
  const float r2 = x * x + y * y;
  if (r2 >= 1.0f) {
    const float r = std::sqrt(r2);
    return {x / r, y / r, 0.0f};
  }
  return {x, y, std::sqrt(1.0f - r2)};
}

}  // namespace

std::shared_ptr<const Texture2D> generate_matcap(MatCapStyle style, int size) {
  if (size < 1 || size > 4096) {
    throw Error("generate_matcap: size " + std::to_string(size) + " outside [1, 4096]");
  }
  constexpr int kSubSamples = 2;
  std::vector<uint8_t> rgba(static_cast<size_t>(size) * size * 4);
  const float inv_size = 1.0f / static_cast<float>(size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      glm::vec3 sum(0.0f);
      for (int sy = 0; sy < kSubSamples; ++sy) {
        for (int sx = 0; sx < kSubSamples; ++sx) {
          const float u = (static_cast<float>(x) + (sx + 0.5f) / kSubSamples) * inv_size;
          const float v = (static_cast<float>(y) + (sy + 0.5f) / kSubSamples) * inv_size;
          sum += shade(style, normal_at(u, v));
        }
      }
      const glm::vec3 c = sum / static_cast<float>(kSubSamples * kSubSamples);
      uint8_t* p = rgba.data() + (static_cast<size_t>(y) * size + x) * 4;
      p[0] = linear_to_srgb8(c.x);
      p[1] = linear_to_srgb8(c.y);
      p[2] = linear_to_srgb8(c.z);
      p[3] = 255;
    }
  }
  return Texture2D::from_rgba8(size, size, std::move(rgba), /*srgb=*/true,
                               std::string("matcap:") + matcap_style_name(style));
}

MatCapStyle parse_matcap_style(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "metal") return MatCapStyle::Metal;
  if (lower == "clay") return MatCapStyle::Clay;
  if (lower == "painted") return MatCapStyle::Painted;
  throw Error("unknown MatCap style '" + std::string(name) + "' (expected metal, clay or painted)");
}

const char* matcap_style_name(MatCapStyle style) {
  switch (style) {
    case MatCapStyle::Metal: return "metal";
    case MatCapStyle::Clay: return "clay";
    case MatCapStyle::Painted: return "painted";
  }
  return "clay";
}

std::shared_ptr<const Texture2D> load_matcap(const std::filesystem::path& path) {
  return load_color_texture(path);
}

}  // namespace ontile
