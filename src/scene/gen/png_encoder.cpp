// PNG encoding of the generated textures through stb_image_write (Debian's libstb).
#include "scene/gen/png_encoder.h"

#include <stb/stb_image_write.h>

#include <string>

#include "util/error.h"

namespace ontile::gen {
namespace {

constexpr int kBytesPerPixel = 3;

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* bytes = static_cast<const uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<uint8_t> encode_png(const RgbImage& image) {
  if (image.width_px <= 0 || image.height_px <= 0 ||
      image.rgb.size() != static_cast<size_t>(image.width_px) * image.height_px * kBytesPerPixel) {
    throw Error("scene generator: PNG encoder got an image of " + std::to_string(image.width_px) +
                "x" + std::to_string(image.height_px) + " px with " +
                std::to_string(image.rgb.size()) + " bytes");
  }
  std::vector<uint8_t> png;
  const int stride_bytes = image.width_px * kBytesPerPixel;
  if (!stbi_write_png_to_func(append_bytes, &png, image.width_px, image.height_px, kBytesPerPixel,
                              image.rgb.data(), stride_bytes)) {
    throw Error("scene generator: stb_image_write could not encode a " + std::to_string(image.width_px) +
                "x" + std::to_string(image.height_px) + " PNG");
  }
  return png;
}

}  // namespace ontile::gen
