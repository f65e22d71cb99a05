// Cube maps: face selection, sampling and the factories (see cube_map.h).
#include "shaders_cpp/toon/cube_map.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "raster/pixel_format.h"
#include "shaders_cpp/toon/image_texture.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr float kPi = 3.14159265358979323846f;
const char* const kFaceNames[kCubeFaceCount] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

SamplerDesc face_sampler() {
  SamplerDesc s;
  s.mag_filter = FilterMode::Linear;
  s.min_filter = FilterMode::Linear;
  s.mipmap_mode = MipmapMode::None;
  s.wrap_u = WrapMode::ClampToEdge;
  s.wrap_v = WrapMode::ClampToEdge;
  return s;
}

// Builds one face by evaluating `radiance(direction)` (linear RGBA) at every texel centre.
template <typename Radiance>
std::shared_ptr<const Texture2D> make_face(CubeFace face, int size, bool float_texels,
                                           const std::string& name, Radiance&& radiance) {
  const size_t texel_count = static_cast<size_t>(size) * size;
  std::vector<float> texels32f(float_texels ? texel_count * 4 : 0);
  std::vector<uint8_t> texels8(float_texels ? 0 : texel_count * 4);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(size),
                         (static_cast<float>(y) + 0.5f) / static_cast<float>(size));
      const glm::vec4 c = radiance(glm::normalize(cube_face_direction(face, uv)));
      const size_t i = (static_cast<size_t>(y) * size + x) * 4;
      if (float_texels) {
        for (int k = 0; k < 4; ++k) texels32f[i + k] = c[k];
      } else {
        for (int k = 0; k < 3; ++k) texels8[i + k] = linear_to_srgb8(c[k]);
        texels8[i + 3] = static_cast<uint8_t>(float_to_unorm(c.w, 8));
      }
    }
  }
  const std::string face_name = name + "[" + kFaceNames[static_cast<int>(face)] + "]";
  if (float_texels) return Texture2D::from_rgba32f(size, size, std::move(texels32f), face_name);
  return Texture2D::from_rgba8(size, size, std::move(texels8), /*srgb=*/true, face_name);
}

template <typename Radiance>
std::shared_ptr<const CubeMap> make_cube_map(int size, bool float_texels, const std::string& name,
                                             Radiance&& radiance) {
  std::array<std::shared_ptr<const Texture2D>, kCubeFaceCount> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    faces[f] = make_face(static_cast<CubeFace>(f), size, float_texels, name, radiance);
  }
  return std::make_shared<const CubeMap>(std::move(faces));
}

void check_face_size(const char* what, int face_size_px) {
  if (face_size_px < 1 || face_size_px > 4096) {
    throw Error(std::string(what) + ": face size " + std::to_string(face_size_px) +
                " outside [1, 4096]");
  }
}

}  // namespace

CubeFaceCoord cube_face_coord(glm::vec3 d) {
  const float ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
  CubeFace face;
  float sc, tc, major;
  if (az >= ax && az >= ay) {
    major = az;
    face = d.z >= 0.0f ? CubeFace::PositiveZ : CubeFace::NegativeZ;
    sc = d.z >= 0.0f ? d.x : -d.x;
    tc = -d.y;
  } else if (ay >= ax) {
    major = ay;
    face = d.y >= 0.0f ? CubeFace::PositiveY : CubeFace::NegativeY;
    sc = d.x;
    tc = d.y >= 0.0f ? d.z : -d.z;
  } else {
    major = ax;
    face = d.x >= 0.0f ? CubeFace::PositiveX : CubeFace::NegativeX;
    sc = d.x >= 0.0f ? -d.z : d.z;
    tc = -d.y;
  }
  if (!(major > 0.0f) || !std::isfinite(major)) return {};  // zero, NaN or infinite direction
  return {face, {0.5f * (sc / major + 1.0f), 0.5f * (tc / major + 1.0f)}};
}

glm::vec3 cube_face_direction(CubeFace face, glm::vec2 uv) {
  const float sc = 2.0f * uv.x - 1.0f, tc = 2.0f * uv.y - 1.0f;
  switch (face) {
    case CubeFace::PositiveX: return {1.0f, -tc, -sc};
    case CubeFace::NegativeX: return {-1.0f, -tc, sc};
    case CubeFace::PositiveY: return {sc, 1.0f, tc};
    case CubeFace::NegativeY: return {sc, -1.0f, -tc};
    case CubeFace::PositiveZ: return {sc, -tc, 1.0f};
    case CubeFace::NegativeZ: return {-sc, -tc, -1.0f};
  }
  return {0.0f, 0.0f, 1.0f};
}

CubeMap::CubeMap(std::array<std::shared_ptr<const Texture2D>, kCubeFaceCount> faces)
    : faces_(std::move(faces)), sampler_(face_sampler()) {
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const Texture2D* t = faces_[f].get();
    if (!t) throw Error(std::string("cube map: face ") + kFaceNames[f] + " is missing");
    const std::string size = std::to_string(t->width()) + "x" + std::to_string(t->height());
    if (t->width() != t->height()) {
      throw Error(t->name() + ": cube map face " + kFaceNames[f] + " is " + size +
                  ", faces must be square");
    }
    if (t->width() != faces_[0]->width()) {
      throw Error(t->name() + ": cube map face " + kFaceNames[f] + " is " + size + " but face +X (" +
                  faces_[0]->name() + ") is " + std::to_string(faces_[0]->width()) + "x" +
                  std::to_string(faces_[0]->height()));
    }
  }
}

glm::vec4 CubeMap::sample(glm::vec3 direction) const {
  const CubeFaceCoord c = cube_face_coord(direction);
  return faces_[static_cast<int>(c.face)]->sample_lod(sampler_, c.uv, 0.0f);
}

std::shared_ptr<const CubeMap> load_cube_map(
    const std::array<std::filesystem::path, kCubeFaceCount>& face_paths) {
  std::array<std::shared_ptr<const Texture2D>, kCubeFaceCount> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) faces[f] = load_color_texture(face_paths[f]);
  return std::make_shared<const CubeMap>(std::move(faces));
}

std::shared_ptr<const CubeMap> cube_map_from_equirect(const Texture2D& equirect, int face_size_px,
                                                      bool float_faces) {
  check_face_size("cube_map_from_equirect", face_size_px);
  SamplerDesc sampler = face_sampler();
  sampler.wrap_u = WrapMode::Repeat;  // longitude wraps around
  return make_cube_map(face_size_px, float_faces, equirect.name(), [&](glm::vec3 d) {
    const float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * kPi);
    const float v = std::acos(glm::clamp(d.y, -1.0f, 1.0f)) / kPi;
    return equirect.sample_lod(sampler, {u, v}, 0.0f);
  });
}

std::shared_ptr<const CubeMap> load_equirect_cube_map(const std::filesystem::path& path,
                                                      int face_size_px) {
  const std::shared_ptr<const Texture2D> equirect = load_color_texture(path);
  return cube_map_from_equirect(*equirect, face_size_px, is_hdr_image_path(path));
}

std::shared_ptr<const CubeMap> generate_gradient_sky(int face_size_px) {
  check_face_size("generate_gradient_sky", face_size_px);
  const glm::vec3 zenith(0.15f, 0.35f, 0.75f), horizon(0.7f, 0.8f, 0.9f), ground(0.3f, 0.24f, 0.18f);
  return make_cube_map(face_size_px, /*float_texels=*/false, "gradient_sky", [&](glm::vec3 d) {
    // The same gradient as GradientSkyShader: sqrt(up) towards the zenith, a quick fade to ground.
    const glm::vec3 c = d.y >= 0.0f ? glm::mix(horizon, zenith, std::sqrt(d.y))
                                    : glm::mix(horizon, ground, std::min(1.0f, -d.y * 4.0f));
    return glm::vec4(c, 1.0f);
  });
}

}  // namespace ontile
