// Attachment pictures and files (see attachment_images.h).
#include "report/attachment_images.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "io/image_io.h"
#include "raster/pixel_format.h"
#include "util/error.h"

namespace ontile {
namespace {

bool is_rgba8(PixelFormat f) { return f == PixelFormat::RGBA8_UNORM || f == PixelFormat::RGBA8_SRGB; }
bool is_unorm(PixelFormat f) { return f == PixelFormat::RGB10A2_UNORM || f == PixelFormat::RG16_UNORM; }

// The pixel's samples averaged (colour) or its sample 0 (depth), decoded.
glm::vec4 pixel_value(const Surface& s, int x, int y) {
  if (is_depth_format(s.format()) || s.samples() == 1) return s.read(x, y, 0);
  glm::vec4 sum(0.0f);
  for (int i = 0; i < s.samples(); ++i) sum += s.read(x, y, i);
  return sum / static_cast<float>(s.samples());
}

bool on_grid(int x, int y, int tile_width_px, int tile_height_px) {
  return tile_width_px > 0 && (x % tile_width_px == 0 || y % tile_height_px == 0);
}

}  // namespace

std::string view_description(PixelFormat format) {
  if (is_depth_format(format)) return "depth, stretched over the drawn range, near bright, cleared black";
  if (is_rgba8(format)) return "stored 8-bit codes, alpha not shown";
  if (is_unorm(format)) return "UNORM values x 255, alpha not shown";
  return "float values clamped to 0..1, linear to sRGB, alpha not shown";
}

Rgba8Image display_image(const Surface& s) {
  Rgba8Image image{s.width(), s.height(), std::vector<uint8_t>(static_cast<size_t>(s.width()) * s.height() * 4, 255)};
  const PixelFormat f = s.format();
  float near = 0.0f, far = 1.0f;
  if (is_depth_format(f)) {
    float lo = 1.0f, hi = 0.0f;
    for (int y = 0; y < s.height(); ++y) {
      for (int x = 0; x < s.width(); ++x) {
        const float d = s.read(x, y, 0).x;
        if (d > 0.0f && d < 1.0f) lo = std::min(lo, d), hi = std::max(hi, d);
      }
    }
    near = lo, far = hi;
  }
  for (int y = 0; y < s.height(); ++y) {
    for (int x = 0; x < s.width(); ++x) {
      uint8_t* out = &image.rgba[(static_cast<size_t>(y) * s.width() + x) * 4];
      if (is_rgba8(f) && s.samples() == 1) {
        std::copy_n(s.pixel_bytes(x, y), 3, out);
        continue;
      }
      const glm::vec4 v = pixel_value(s, x, y);
      for (int c = 0; c < 3; ++c) {
        if (is_depth_format(f)) {
          const bool drawn = v.x > 0.0f && v.x < 1.0f;
          // Near bright whichever way the depth test runs: a reversed-Z frame draws near large.
          const float t = far > near ? (v.x - near) / (far - near) : 0.5f;
          out[c] = drawn ? static_cast<uint8_t>(float_to_unorm(1.0f - 0.85f * t, 8)) : 0;
        } else if (is_rgba8(f)) {
          out[c] = f == PixelFormat::RGBA8_SRGB ? linear_to_srgb8(v[c]) : static_cast<uint8_t>(float_to_unorm(v[c], 8));
        } else if (is_unorm(f)) {
          out[c] = static_cast<uint8_t>(float_to_unorm(v[c], 8));
        } else {
          out[c] = linear_to_srgb8(std::clamp(std::isfinite(v[c]) ? v[c] : 0.0f, 0.0f, 1.0f));
        }
      }
    }
  }
  return image;
}

Rgba8Image downscale(const Rgba8Image& image, int max_width_px) {
  if (image.width <= max_width_px) return image;
  const int w = max_width_px, h = std::max(1, static_cast<int>(std::lround(static_cast<double>(image.height) * w / image.width)));
  Rgba8Image out{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h * 4)};
  for (int y = 0; y < h; ++y) {
    const int y0 = static_cast<int>(static_cast<int64_t>(y) * image.height / h);
    const int y1 = std::max(y0 + 1, static_cast<int>(static_cast<int64_t>(y + 1) * image.height / h));
    for (int x = 0; x < w; ++x) {
      const int x0 = static_cast<int>(static_cast<int64_t>(x) * image.width / w);
      const int x1 = std::max(x0 + 1, static_cast<int>(static_cast<int64_t>(x + 1) * image.width / w));
      uint32_t sum[4] = {0, 0, 0, 0};
      for (int sy = y0; sy < y1; ++sy) {
        for (int sx = x0; sx < x1; ++sx) {
          for (int c = 0; c < 4; ++c) sum[c] += image.rgba[(static_cast<size_t>(sy) * image.width + sx) * 4 + c];
        }
      }
      const uint32_t n = static_cast<uint32_t>((y1 - y0) * (x1 - x0));
      for (int c = 0; c < 4; ++c) out.rgba[(static_cast<size_t>(y) * w + x) * 4 + c] = static_cast<uint8_t>((sum[c] + n / 2) / n);
    }
  }
  return out;
}

void draw_tile_grid(Rgba8Image& image, int tile_width_px, int tile_height_px) {
  if (tile_width_px <= 0 || tile_height_px <= 0) return;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!on_grid(x, y, tile_width_px, tile_height_px)) continue;
      uint8_t* p = &image.rgba[(static_cast<size_t>(y) * image.width + x) * 4];
      p[0] = 255, p[1] = 0, p[2] = 255, p[3] = 255;
    }
  }
}

std::string attachment_file_name(size_t pass_index, const std::string& pass, const std::string& attachment,
                                 PixelFormat format) {
  auto clean = [](std::string text) {
    for (char& c : text) {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
    }
    return text;
  };
  return std::to_string(pass_index) + "-" + clean(pass) + "-" + clean(attachment) + (is_rgba8(format) ? ".png" : ".exr");
}

void stage_attachment_file(const std::filesystem::path& path, const Surface& s, int tile_width_px,
                           int tile_height_px, StagedOutputs& staged) {
  const PixelFormat f = s.format();
  if (is_rgba8(f)) {
    std::vector<uint8_t> rgba(static_cast<size_t>(s.width()) * s.height() * 4);
    for (int y = 0; y < s.height(); ++y) {
      for (int x = 0; x < s.width(); ++x) {
        uint8_t* out = &rgba[(static_cast<size_t>(y) * s.width() + x) * 4];
        if (on_grid(x, y, tile_width_px, tile_height_px)) {
          out[0] = 255, out[1] = 0, out[2] = 255, out[3] = 255;
        } else if (s.samples() == 1) {
          std::copy_n(s.pixel_bytes(x, y), 4, out);
        } else {
          encode_pixel(f, pixel_value(s, x, y), out);
        }
      }
    }
    write_png_rgba8(path, s.width(), s.height(), rgba, &staged);
    return;
  }
  const bool depth = is_depth_format(f);
  const std::vector<std::string> channels =
      !depth ? std::vector<std::string>{"R", "G", "B", "A"}
             : f == PixelFormat::D24S8 ? std::vector<std::string>{"Z", "S"} : std::vector<std::string>{"Z"};
  std::vector<float> values;
  values.reserve(static_cast<size_t>(s.width()) * s.height() * channels.size());
  for (int y = 0; y < s.height(); ++y) {
    for (int x = 0; x < s.width(); ++x) {
      const bool grid = on_grid(x, y, tile_width_px, tile_height_px);
      const glm::vec4 v = grid ? (depth ? glm::vec4(0.0f) : glm::vec4(1, 0, 1, 1)) : pixel_value(s, x, y);
      for (size_t c = 0; c < channels.size(); ++c) values.push_back(v[static_cast<int>(c)]);
    }
  }
  write_exr_channels(path, s.width(), s.height(), channels, values, &staged);
}

}  // namespace ontile
