// Cube-map environments for the toon environment shader: six square Texture2D faces, face
// selection per the Vulkan specification, and factories from six images, an equirectangular
// image or a procedural gradient sky.
#pragma once
#include <array>
#include <filesystem>
#include <memory>

#include <glm/glm.hpp>

#include "raster/texture.h"

namespace ontile {

// Face order = Vulkan array layers of a cube image: +X, -X, +Y, -Y, +Z, -Z.
enum class CubeFace { PositiveX = 0, NegativeX, PositiveY, NegativeY, PositiveZ, NegativeZ };
constexpr int kCubeFaceCount = 6;

struct CubeFaceCoord {
  CubeFace face = CubeFace::PositiveZ;
  glm::vec2 uv{0.5f};  // (s, t) in [0, 1]; t = 0 is the face's top row
};

// Vulkan 1.3 "Cube Map Face Selection and Transformations": the major axis is the component of
// largest magnitude; ties go to z over y over x, as the specification recommends. Then
// s = (sc / |rc| + 1) / 2, t = (tc / |rc| + 1) / 2 with (sc, tc) from its table:
// +X: (-rz, -ry)  -X: (+rz, -ry)  +Y: (+rx, +rz)  -Y: (+rx, -rz)  +Z: (+rx, -ry)  -Z: (-rx, -ry).
// A zero direction gives +Z's centre.
CubeFaceCoord cube_face_coord(glm::vec3 direction);
// The inverse: the (unnormalised) direction through (s, t) of `face`.
glm::vec3 cube_face_direction(CubeFace face, glm::vec2 uv);

class CubeMap {
 public:
  // Throws Error unless the six faces exist, are square and all the same size.
  explicit CubeMap(std::array<std::shared_ptr<const Texture2D>, kCubeFaceCount> faces);

  // Bilinear sample of the base level inside the selected face (clamped at the face edge: no
  // filtering across faces, i.e. not seamless cube filtering). Linear RGBA.
  glm::vec4 sample(glm::vec3 direction) const;

  const Texture2D& face(CubeFace f) const { return *faces_[static_cast<int>(f)]; }
  int face_size_px() const { return faces_[0]->width(); }

 private:
  std::array<std::shared_ptr<const Texture2D>, kCubeFaceCount> faces_;
  SamplerDesc sampler_;
};

// Six image files in face order (+X, -X, +Y, -Y, +Z, -Z), decoded as image_texture.h says.
// Errors name the offending file.
std::shared_ptr<const CubeMap> load_cube_map(
    const std::array<std::filesystem::path, kCubeFaceCount>& face_paths);

// Resamples an equirectangular (latitude-longitude) image into face_size_px faces, bilinear.
// Mapping: direction d -> u = 0.5 + atan2(d.x, -d.z) / (2 pi), v = acos(d.y) / pi, so the image
// centre is the -Z direction (where an unrotated camera looks) and the top row is straight up.
// LDR files give sRGB RGBA8 faces, HDR files (.exr, .hdr) float faces.
std::shared_ptr<const CubeMap> load_equirect_cube_map(const std::filesystem::path& path,
                                                      int face_size_px);
std::shared_ptr<const CubeMap> cube_map_from_equirect(const Texture2D& equirect, int face_size_px,
                                                      bool float_faces);

// A toon sky: blue zenith, pale horizon, warm brown ground (linear RGB as in GradientSkyShader),
// one sample per texel centre, sRGB RGBA8 faces. Throws Error when face_size_px is outside
// [1, 4096].
std::shared_ptr<const CubeMap> generate_gradient_sky(int face_size_px);

}  // namespace ontile
