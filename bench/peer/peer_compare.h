// Per-pixel comparison of ontile's and llvmpipe's outputs for the same frame: the primitive-id
// AOVs (does each pixel show the same triangle?), the cartoon frame's Sobel edge masks (does
// each pixel get the same edge / no-edge decision?) and the 8-bit sRGB colour images.
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

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

struct EdgeAgreement {
  uint64_t pixels = 0;
  uint64_t equal = 0;  // both edge or both not
  uint64_t ontile_edges = 0, llvmpipe_edges = 0;
  uint64_t only_ontile = 0, only_llvmpipe = 0;
  // Differing pixels next to (within one pixel of) an edge pixel of the other image: a line
  // shifted or thickened by a pixel, not a line one renderer lacks.
  uint64_t shifted = 0;
  double percent() const { return pixels ? 100.0 * double(equal) / double(pixels) : 0.0; }
};

// ontile_ids: the AOV surface of render_aov_frame (id in R as float, -1 for background);
// llvmpipe_exr: the runner's --primitive-ids file (channel primid, same encoding).
// Throws ontile::Error when the file cannot be read or the sizes differ.
IdAgreement compare_primitive_ids(const Surface& ontile_ids, const std::filesystem::path& llvmpipe_exr);
// ontile_mask: width x height flags, row-major, nonzero = edge; llvmpipe_png: the runner's
// --edges file (R = 255 on an edge). Throws ontile::Error when the file cannot be read or the
// sizes differ.
EdgeAgreement compare_edge_masks(const std::vector<uint8_t>& ontile_mask, int width, int height,
                                 const std::filesystem::path& llvmpipe_png);
// ontile_color: the frame's RGBA8_SRGB target; llvmpipe_png: the runner's --color file.
ColorAgreement compare_colors(const Surface& ontile_color, const std::filesystem::path& llvmpipe_png);

}  // namespace ontile::peer
