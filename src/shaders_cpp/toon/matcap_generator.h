// MatCap textures: three built-in lit spheres drawn analytically (so scenes need no image
// files) and loading of painted MatCaps from image files.
#pragma once
#include <filesystem>
#include <memory>
#include <string_view>

#include "raster/texture.h"

namespace ontile {

enum class MatCapStyle {
  Metal,    // sharp highlights, a bright horizon band reflected from an environment, dark bottom
  Clay,     // warm grey, soft wrapped diffuse and a faint rim
  Painted,  // three flat bands of stylised shading with a hard highlight
};

// A size x size sRGB RGBA8 MatCap (alpha 255) for matcap_uv's mapping: the sphere fills the
// image, texel centres outside the disc repeat the rim (so bilinear taps at the rim stay on the
// sphere). Each texel averages 2x2 sub-samples in linear space, then is sRGB-encoded:
// deterministic. The name is "matcap:<style>". Throws Error when size is outside [1, 4096].
std::shared_ptr<const Texture2D> generate_matcap(MatCapStyle style, int size = 512);

// "metal", "clay" or "painted" (case-insensitive); anything else throws Error naming the value.
MatCapStyle parse_matcap_style(std::string_view name);
const char* matcap_style_name(MatCapStyle style);

// A MatCap image file (anything read_image reads) as an sRGB texture; .exr/.hdr stay linear float.
// Errors name the file.
std::shared_ptr<const Texture2D> load_matcap(const std::filesystem::path& path);

}  // namespace ontile
