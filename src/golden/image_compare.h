// Image comparison with a tolerance, for `ontile compare` and the golden cases: per-channel
// absolute differences, the pixels over the tolerance counted, PSNR, and a diff picture.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "io/image_io.h"

namespace ontile {

// Units of a difference: 8-bit code values (0..255) when both images come from integer formats
// (PNG), plain values when either is a float format (EXR). 16-bit integer files are measured in
// 8-bit units too, which may then be fractional.
struct CompareTolerance {
  double max_abs = 0.0;     // largest per-channel difference a pixel may have and still match
  uint64_t max_pixels = 0;  // how many pixels may exceed max_abs before the images mismatch
};

struct ImageComparison {
  bool same_size = false;
  bool float_units = false;              // differences in values, not 8-bit codes (see above)
  uint64_t pixel_count = 0;
  uint64_t differing_pixels = 0;         // a channel differs at all
  uint64_t pixels_over_tolerance = 0;    // a channel differs by more than max_abs
  double max_abs_difference = 0.0;       // largest per-channel difference, in the units above
  double psnr_db = 0.0;                  // over R, G, B and A; infinite for identical images
  bool matches = false;                  // same size and at most max_pixels over max_abs
  // Diff picture (RGBA8, the images' size; empty when the sizes differ): pixels over the
  // tolerance in red, brighter for larger differences; differences within it in blue; the rest a
  // dim grey copy of the expected image so the differences can be located.
  std::vector<uint8_t> diff_rgba;
};

ImageComparison compare_images(const ImageRGBA32F& actual, const ImageRGBA32F& expected,
                               const CompareTolerance& tolerance);

// RGBA8 bytes as an image of 8-bit values (code / 255, integer_bits 8), as read_image gives a PNG.
ImageRGBA32F image_from_rgba8(int width, int height, const std::vector<uint8_t>& rgba);

// "inf" for infinity, else the value with two decimals (e.g. "48.13").
std::string format_psnr(double psnr_db);
// A difference in the comparison's units: integers as integers ("3"), others with up to 6
// significant digits ("0.00125").
std::string format_difference(double value);

}  // namespace ontile
