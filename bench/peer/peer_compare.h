// Per-pixel comparison of ontile's and llvmpipe's outputs for the same frame: the primitive-id
// AOVs (does each pixel show the same triangle?) and the 8-bit sRGB colour images.
#pragma once
#include <cstdint>
#include <filesystem>

#include "tiler/surface.h"

namespace ontile::peer {

struct IdAgreement {
  uint64_t pixels = 0;
  uint64_t equal = 0;             // same id, or background in both
  uint64_t coverage_differs = 0;  // a surface in one image, background in the other
  uint64_t id_differs = 0;        // different triangles
  // Differing pixels (either kind) where each renderer's id also shows in the other's image
  // within one pixel: a triangle boundary shifted by a pixel (edge and depth ties), not a
  // misplaced or missing triangle.
  uint64_t boundary_shifts = 0;
  double percent() const { return pixels ? 100.0 * double(equal) / double(pixels) : 0.0; }
};

struct ColorAgreement {
  uint64_t pixels = 0;
  uint64_t close = 0;        // every channel within kColorTolerance codes
  double mean_abs_diff = 0;  // over RGB channels, in 8-bit codes
  double percent() const { return pixels ? 100.0 * double(close) / double(pixels) : 0.0; }
};
constexpr int kColorTolerance = 2;

// ontile_ids: the AOV surface of render_aov_frame (id in R as float, -1 for background);
// llvmpipe_exr: the runner's --primitive-ids file (channel primid, same encoding).
// Throws ontile::Error when the file cannot be read or the sizes differ.
IdAgreement compare_primitive_ids(const Surface& ontile_ids, const std::filesystem::path& llvmpipe_exr);
// ontile_color: lambert's RGBA8_SRGB target; llvmpipe_png: the runner's --color file.
ColorAgreement compare_colors(const Surface& ontile_color, const std::filesystem::path& llvmpipe_png);

}  // namespace ontile::peer
