// Image comparison with a tolerance (see image_compare.h).
#include "golden/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ontile {
namespace {

uint8_t to_code8(float value) {
  const double clamped = std::clamp(static_cast<double>(value), 0.0, 1.0);
  return static_cast<uint8_t>(std::lround(clamped * 255.0));
}

}  // namespace

ImageRGBA32F image_from_rgba8(int width, int height, const std::vector<uint8_t>& rgba) {
  ImageRGBA32F image{width, height, std::vector<float>(rgba.size()), 8};
  // The same conversion OpenImageIO makes reading an 8-bit file as float: code / 255.
  for (size_t i = 0; i < rgba.size(); ++i) image.pixels[i] = static_cast<float>(rgba[i]) / 255.0f;
  return image;
}

ImageComparison compare_images(const ImageRGBA32F& actual, const ImageRGBA32F& expected,
                               const CompareTolerance& tolerance) {
  ImageComparison result;
  result.same_size = actual.width == expected.width && actual.height == expected.height &&
                     actual.pixels.size() == expected.pixels.size();
  if (!result.same_size) return result;
  result.float_units = actual.integer_bits == 0 || expected.integer_bits == 0;
  const bool both_8bit = actual.integer_bits == 8 && expected.integer_bits == 8;
  // Units per value: 8-bit codes for integer images, values for float ones.
  const double scale = result.float_units ? 1.0 : 255.0;
  const double peak = result.float_units ? 1.0 : 255.0;
  result.pixel_count = static_cast<uint64_t>(actual.width) * actual.height;
  result.diff_rgba.assign(actual.pixels.size(), 0);
  double squared_sum = 0.0;
  for (size_t px = 0; px < actual.pixels.size(); px += 4) {
    double worst = 0.0;
    for (size_t ch = 0; ch < 4; ++ch) {
      double d = std::abs(static_cast<double>(actual.pixels[px + ch]) - expected.pixels[px + ch]) * scale;
      // Both sides are code / 255 in float: the difference is a whole number of codes.
      if (both_8bit) d = std::round(d);
      if (std::isnan(d)) d = std::numeric_limits<double>::infinity();  // NaN against a number
      worst = std::max(worst, d);
      squared_sum += d * d;
    }
    result.max_abs_difference = std::max(result.max_abs_difference, worst);
    result.differing_pixels += worst > 0.0;
    const bool over = worst > tolerance.max_abs;
    result.pixels_over_tolerance += over;
    const double worst_codes = result.float_units ? worst * 255.0 : worst;
    const uint8_t bright = static_cast<uint8_t>(std::min(255.0, 128.0 + worst_codes * 8.0));
    const uint8_t grey = static_cast<uint8_t>(
        (to_code8(expected.pixels[px]) + to_code8(expected.pixels[px + 1]) + to_code8(expected.pixels[px + 2])) / 12);
    uint8_t* out = result.diff_rgba.data() + px;
    out[0] = worst == 0.0 ? grey : over ? bright : 0;
    out[1] = worst == 0.0 ? grey : 0;
    out[2] = worst == 0.0 ? grey : over ? 0 : bright;
    out[3] = 255;
  }
  const double mse = squared_sum / static_cast<double>(actual.pixels.size());
  result.psnr_db = mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(peak * peak / mse);
  result.matches = result.pixels_over_tolerance <= tolerance.max_pixels;
  return result;
}

std::string format_psnr(double psnr_db) {
  if (std::isinf(psnr_db)) return "inf";
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", psnr_db);
  return text;
}

std::string format_difference(double value) {
  char text[32];
  if (value == std::floor(value) && std::abs(value) < 1e15) {
    std::snprintf(text, sizeof(text), "%.0f", value);
  } else {
    std::snprintf(text, sizeof(text), "%.6g", value);
  }
  return text;
}

}  // namespace ontile
