// PNG encoding into memory for data: URIs (see image_io.h): OpenImageIO's PNG writer on an
// IOVecOutput proxy, then OpenImageIO's base64 encoder.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <memory>

#include "io/image_io.h"
#include "util/error.h"

namespace ontile {

std::string png_data_uri(int width, int height, const std::vector<uint8_t>& rgba) {
  if (width <= 0 || height <= 0 || rgba.size() != static_cast<size_t>(width) * height * 4) {
    throw Error("PNG data URI: " + std::to_string(rgba.size()) + " bytes for a " + std::to_string(width) + "x" +
                std::to_string(height) + " RGBA image");
  }
  OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // as write_png_rgba8: the bytes are unassociated
  OIIO::Filesystem::IOVecOutput memory;
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create("png");
  if (!out || !out->set_ioproxy(&memory) || !out->open("memory.png", spec) ||
      !out->write_image(OIIO::TypeDesc::UINT8, rgba.data()) || !out->close()) {
    throw Error("PNG data URI: cannot encode the image" + (out ? ": " + out->geterror() : std::string()));
  }
  const std::vector<unsigned char>& png = memory.buffer();
  return "data:image/png;base64," +
         OIIO::Strutil::base64_encode(OIIO::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

}  // namespace ontile
