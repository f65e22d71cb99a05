// Normal storage encodings (see normal_encoding.h).
#include "shaders_cpp/normal_encoding.h"

#include <cmath>

namespace ontile {
namespace {

// sign() that never returns 0, so points on an axis fold consistently (Cigolle et al. 2014).
glm::vec2 sign_not_zero(const glm::vec2& v) {
  return {v.x >= 0.0f ? 1.0f : -1.0f, v.y >= 0.0f ? 1.0f : -1.0f};
}

glm::vec3 normalized_or_zero(const glm::vec3& v) {
  const float len = glm::length(v);
  return len > 0.0f ? v / len : glm::vec3(0.0f);
}

}  // namespace

const char* normal_storage_name(NormalStorage storage) {
  switch (storage) {
    case NormalStorage::Rgb10a2: return "rgb10a2";
    case NormalStorage::Rgba16f: return "rgba16f";
    case NormalStorage::OctRg16: return "oct-rg16";
  }
  return "?";
}

std::vector<NormalStorage> all_normal_storages() {
  return {NormalStorage::Rgb10a2, NormalStorage::Rgba16f, NormalStorage::OctRg16};
}

std::optional<NormalStorage> parse_normal_storage(std::string_view name) {
  for (NormalStorage s : all_normal_storages()) {
    if (name == normal_storage_name(s)) return s;
  }
  return std::nullopt;
}

PixelFormat normal_storage_format(NormalStorage storage) {
  switch (storage) {
    case NormalStorage::Rgb10a2: return PixelFormat::RGB10A2_UNORM;
    case NormalStorage::Rgba16f: return PixelFormat::RGBA16_FLOAT;
    case NormalStorage::OctRg16: return PixelFormat::RG16_UNORM;
  }
  return PixelFormat::RGBA32_FLOAT;
}

glm::vec2 octahedral_encode(const glm::vec3& n) {
  const float l1 = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
  if (!(l1 > 0.0f)) return glm::vec2(0.0f);
  glm::vec2 p = glm::vec2(n.x, n.y) / l1;
  if (n.z < 0.0f) p = (1.0f - glm::abs(glm::vec2(p.y, p.x))) * sign_not_zero(p);
  return p;
}

glm::vec3 octahedral_decode(const glm::vec2& e) {
  glm::vec3 v(e.x, e.y, 1.0f - std::abs(e.x) - std::abs(e.y));
  if (v.z < 0.0f) {
    const glm::vec2 folded = (1.0f - glm::abs(glm::vec2(v.y, v.x))) * sign_not_zero(glm::vec2(v.x, v.y));
    v.x = folded.x;
    v.y = folded.y;
  }
  return glm::normalize(v);  // |v| >= 1/sqrt(3) everywhere on the octahedron
}

glm::vec4 encode_normal(NormalStorage storage, const glm::vec3& n) {
  switch (storage) {
    case NormalStorage::Rgb10a2: return glm::vec4(n * 0.5f + 0.5f, 1.0f);
    case NormalStorage::Rgba16f: return glm::vec4(n, 1.0f);
    case NormalStorage::OctRg16: return glm::vec4(octahedral_encode(n) * 0.5f + 0.5f, 0.0f, 1.0f);
  }
  return glm::vec4(0.0f);
}

glm::vec3 decode_normal(NormalStorage storage, const glm::vec4& stored) {
  switch (storage) {
    case NormalStorage::Rgb10a2:
      if (stored == glm::vec4(0.0f)) return glm::vec3(0.0f);
      return normalized_or_zero(glm::vec3(stored) * 2.0f - 1.0f);
    case NormalStorage::Rgba16f:
      return normalized_or_zero(glm::vec3(stored));
    case NormalStorage::OctRg16:
      return octahedral_decode(glm::vec2(stored) * 2.0f - 1.0f);
  }
  return glm::vec3(0.0f);
}

}  // namespace ontile
