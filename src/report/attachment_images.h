// Pictures of attachments for people: an 8-bit view of any surface format (thumbnails in the
// HTML report), the tile grid drawn over it, and the files --dump-attachments writes (8-bit
// formats as PNG, float and depth formats as OpenEXR).
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tiler/surface.h"

namespace ontile {

class StagedOutputs;

struct Rgba8Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // row-major, top row first
};

// An opaque 8-bit view of the surface, samples of a pixel averaged (depth: sample 0, as Vulkan's
// SAMPLE_ZERO resolve of depth): RGBA8 codes as stored; other UNORM formats scaled to 0..255;
// float colour formats clamped to [0, 1] and encoded linear -> sRGB; depth stretched over the
// range the frame drew (the values other than 0 and 1, the clear values) with near bright and
// cleared pixels black. view_description says which of these applies.
Rgba8Image display_image(const Surface& surface);
std::string view_description(PixelFormat format);

// A box-filtered copy at most max_width_px wide (the same image when already narrower).
Rgba8Image downscale(const Rgba8Image& image, int max_width_px);

// Tile boundaries as 1-pixel opaque magenta lines (every tile_width_px-th column and
// tile_height_px-th row, counted from the top-left as the tiler bins).
void draw_tile_grid(Rgba8Image& image, int tile_width_px, int tile_height_px);

// "<pass index>-<pass>-<attachment>.png" for 8-bit colour formats, ".exr" otherwise; characters
// other than letters, digits, '.', '-' and '_' become '_'.
std::string attachment_file_name(size_t pass_index, const std::string& pass, const std::string& attachment,
                                 PixelFormat format);

// Stages the attachment file at `path` (its extension chosen by attachment_file_name): PNG with
// the stored RGBA8 codes (samples averaged), or OpenEXR with R, G, B, A (colour, samples averaged)
// or Z (and S for d24s8; sample 0) as 32-bit floats. tile_width_px > 0 draws the tile grid:
// magenta (1, 0, 1, 1) in colour files, 0 in depth files.
void stage_attachment_file(const std::filesystem::path& path, const Surface& surface, int tile_width_px,
                           int tile_height_px, StagedOutputs& staged);

}  // namespace ontile
