// Image files as cartoon-material textures (see image_texture.h).
#include "shaders_cpp/toon/image_texture.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

namespace ontile {

bool is_hdr_image_path(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".exr" || ext == ".hdr";
}

std::shared_ptr<const Texture2D> texture_from_image(const ImageRGBA32F& image,
                                                    const std::filesystem::path& path) {
  if (is_hdr_image_path(path)) {
    return Texture2D::from_rgba32f(image.width, image.height, image.pixels, path.string());
  }
  std::vector<uint8_t> codes(image.pixels.size());
  for (size_t i = 0; i < codes.size(); ++i) {
    // read_image gives code / 255 for 8-bit files, so this recovers the stored codes exactly;
    // 16-bit files are rounded to the nearest 8-bit code. NaN clamps to 0.
    const float v = image.pixels[i];
    const float clamped = v > 0.0f ? std::min(v, 1.0f) : 0.0f;
    codes[i] = static_cast<uint8_t>(std::lround(clamped * 255.0f));
  }
  return Texture2D::from_rgba8(image.width, image.height, std::move(codes), /*srgb=*/true,
                               path.string());
}

std::shared_ptr<const Texture2D> load_color_texture(const std::filesystem::path& path) {
  return texture_from_image(read_image(path), path);
}

}  // namespace ontile
