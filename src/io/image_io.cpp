// PNG/EXR writing and image reading through OpenImageIO 2.4 (see image_io.h). Writers go through
// write_file_atomically; OpenImageIO errors become one-line ontile::Error messages.
#include "io/image_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <memory>

#include "raster/pixel_format.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace ontile {
namespace {

namespace fs = std::filesystem;

// OpenImageIO messages may span lines; an Error is one line.
std::string one_line(std::string message) {
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  std::replace(message.begin(), message.end(), '\n', ' ');
  return message.empty() ? std::string("unknown OpenImageIO error") : message;
}

std::string lowercase_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

void require_extension(const fs::path& path, const char* expected) {
  if (lowercase_extension(path) != expected) {
    throw Error(path.string() + ": unsupported extension '" + path.extension().string() +
                "' (expected " + expected + ")");
  }
}

void check_image_size(const fs::path& path, int width, int height, int channels,
                      size_t value_count) {
  if (width <= 0 || height <= 0 || channels <= 0) {
    throw Error(path.string() + ": invalid image size " + std::to_string(width) + "x" +
                std::to_string(height) + " with " + std::to_string(channels) + " channels");
  }
  const size_t expected = static_cast<size_t>(width) * height * channels;
  if (value_count != expected) {
    throw Error(path.string() + ": " + std::to_string(value_count) + " values for a " +
                std::to_string(width) + "x" + std::to_string(height) + " image with " +
                std::to_string(channels) + " channels (expected " + std::to_string(expected) + ")");
  }
}

// An EXR spec without a timestamp: OpenImageIO 2.4's OpenEXR writer adds the current time as
// `capDate` when the spec has no "DateTime", so identical runs wrote different bytes; an empty
// DateTime is written as an empty capDate (no date). PNG gets no time chunk from OpenImageIO.
OIIO::ImageSpec exr_spec(int width, int height, int channels) {
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  spec.attribute("DateTime", "");
  return spec;
}

// Writes spec + pixels (of spec.format) with the named OpenImageIO plugin: staged into `staged`,
// or on its own, atomically.
void write_atomically(const fs::path& path, const char* plugin, const OIIO::ImageSpec& spec,
                      const void* pixels, StagedOutputs* staged) {
  const auto write = [&](const fs::path& tmp_path) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(plugin);
    if (!out) throw Error(path.string() + ": " + one_line(OIIO::geterror()));
    if (!out->open(tmp_path.string(), spec) || !out->write_image(spec.format, pixels) ||
        !out->close()) {
      throw Error(path.string() + ": cannot write image: " + one_line(out->geterror()));
    }
  };
  if (staged) {
    staged->stage(path, write);
  } else {
    write_file_atomically(path, write);
  }
}

std::unique_ptr<OIIO::ImageInput> open_input(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw Error(path.string() +
                (fs::exists(path, ec) ? ": not a regular file" : ": file not found"));
  }
  // Keep colour and alpha as stored: OpenImageIO would otherwise premultiply (associate) the
  // colour of formats with unassociated alpha such as PNG.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) throw Error(path.string() + ": cannot read image: " + one_line(OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.nchannels <= 0) {
    throw Error(path.string() + ": unsupported image layout " + std::to_string(spec.width) + "x" +
                std::to_string(spec.height) + "x" + std::to_string(spec.depth) + " with " +
                std::to_string(spec.nchannels) + " channels");
  }
  return in;
}

// Reads all channels of subimage 0 as `type` (FLOAT or UINT8), interleaved.
template <typename T>
std::vector<T> read_all_channels(const fs::path& path, OIIO::ImageInput& in, OIIO::TypeDesc type) {
  const OIIO::ImageSpec& spec = in.spec();
  std::vector<T> values(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in.read_image(0, 0, 0, spec.nchannels, type, values.data())) {
    throw Error(path.string() + ": cannot read image: " + one_line(in.geterror()));
  }
  return values;
}

// Channel expansion to RGBA described in image_io.h; `one` is the opaque alpha value.
template <typename T>
std::vector<T> expand_to_rgba(const std::vector<T>& values, const OIIO::ImageSpec& spec, T one) {
  const int n = spec.nchannels;
  const size_t pixel_count = static_cast<size_t>(spec.width) * spec.height;
  const bool gray_alpha = n == 2 && spec.alpha_channel == 1;
  std::vector<T> rgba(pixel_count * 4);
  for (size_t p = 0; p < pixel_count; ++p) {
    const T* src = values.data() + p * n;
    T* dst = rgba.data() + p * 4;
    if (n == 1 || gray_alpha) {
      dst[0] = dst[1] = dst[2] = src[0];
      dst[3] = gray_alpha ? src[1] : one;
    } else {
      dst[0] = src[0];
      dst[1] = src[1];
      dst[2] = n >= 3 ? src[2] : T(0);
      dst[3] = n >= 4 ? src[3] : one;
    }
  }
  return rgba;
}

}  // namespace

void write_image(const fs::path& path, const ImageRGBA32F& image, bool linear_to_srgb_for_8bit,
                 StagedOutputs* staged) {
  const std::string ext = lowercase_extension(path);
  if (ext != ".png" && ext != ".exr") {
    throw Error(path.string() + ": unsupported image extension '" + path.extension().string() +
                "' (expected .png or .exr)");
  }
  check_image_size(path, image.width, image.height, 4, image.pixels.size());
  if (ext == ".exr") {
    write_atomically(path, "openexr", exr_spec(image.width, image.height, 4), image.pixels.data(), staged);
    return;
  }
  std::vector<uint8_t> rgba8(image.pixels.size());
  for (size_t i = 0; i < image.pixels.size(); i += 4) {
    for (size_t c = 0; c < 3; ++c) {
      const float v = image.pixels[i + c];
      rgba8[i + c] =
          linear_to_srgb_for_8bit ? linear_to_srgb8(v) : static_cast<uint8_t>(float_to_unorm(v, 8));
    }
    rgba8[i + 3] = static_cast<uint8_t>(float_to_unorm(image.pixels[i + 3], 8));
  }
  write_png_rgba8(path, image.width, image.height, rgba8, staged);
}

void write_png_rgba8(const fs::path& path, int width, int height,
                     const std::vector<uint8_t>& rgba, StagedOutputs* staged) {
  require_extension(path, ".png");
  check_image_size(path, width, height, 4, rgba.size());
  OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
  // PNG alpha is unassociated; the bytes are already in that form, so OpenImageIO must not
  // un-premultiply them.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  write_atomically(path, "png", spec, rgba.data(), staged);
}

void write_exr_channels(const fs::path& path, int width, int height,
                        const std::vector<std::string>& channel_names,
                        const std::vector<float>& interleaved, StagedOutputs* staged) {
  require_extension(path, ".exr");
  const int channels = static_cast<int>(channel_names.size());
  check_image_size(path, width, height, channels, interleaved.size());
  OIIO::ImageSpec spec = exr_spec(width, height, channels);
  spec.channelnames = channel_names;
  spec.alpha_channel = -1;
  for (int c = 0; c < channels; ++c) {
    if (channel_names[c] == "A") spec.alpha_channel = c;
  }
  write_atomically(path, "openexr", spec, interleaved.data(), staged);
}

ImageRGBA32F read_image(const fs::path& path) {
  std::unique_ptr<OIIO::ImageInput> in = open_input(path);
  const std::vector<float> values = read_all_channels<float>(path, *in, OIIO::TypeDesc::FLOAT);
  ImageRGBA32F image;
  image.width = in->spec().width;
  image.height = in->spec().height;
  image.pixels = expand_to_rgba<float>(values, in->spec(), 1.0f);
  const OIIO::TypeDesc stored = in->spec().format;
  image.integer_bits = stored.is_floating_point() ? 0 : static_cast<int>(stored.size()) * 8;
  in->close();
  return image;
}

std::vector<uint8_t> read_png_rgba8(const fs::path& path, int& width, int& height) {
  std::unique_ptr<OIIO::ImageInput> in = open_input(path);
  if (std::string(in->format_name()) != "png") {
    throw Error(path.string() + ": not a PNG file (format '" + in->format_name() + "')");
  }
  const std::vector<uint8_t> values = read_all_channels<uint8_t>(path, *in, OIIO::TypeDesc::UINT8);
  width = in->spec().width;
  height = in->spec().height;
  std::vector<uint8_t> rgba = expand_to_rgba<uint8_t>(values, in->spec(), 255);
  in->close();
  return rgba;
}

}  // namespace ontile
