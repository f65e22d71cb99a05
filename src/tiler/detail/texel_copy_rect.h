// Whole-tile texel copies (issue 11): a full-screen draw whose functor declares a plain texel
// copy (FragmentShader::texel_copy_source) into an attachment of the source's stored format
// moves the source's texels into tile memory a row at a time (8-bit RGBA: the bytes into the
// code plane, never decoded; RGBA16F: decoded rows, quantised as shaded outputs are)
// and traces the texels the functor would have fetched, in the same order.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "memory/pass_memory.h"
#include "raster/pixel_format.h"
#include "raster/raster_types.h"
#include "raster/shader_interface.h"

namespace ontile {

// A texel-copy source's base level as stored bytes: texels of `format` (4 bytes for the RGBA8
// formats, the code plane's), rows `width` texels apart, and the simulated address terms its
// fetches trace.
struct TexelCopyRows {
  const uint8_t* bytes = nullptr;
  PixelFormat format = PixelFormat::RGBA8_UNORM;
  int width = 0, height = 0;
  uint64_t address = 0;          // simulated byte address of texel (0, 0)
  uint64_t bytes_per_texel = 0;  // simulated bytes per texel (the trace's stride)
};

// True, filling `rows`, when `shader` declares a texel copy whose source is uncompressed,
// stores the codes of `target_format` (RGBA8 UNORM or sRGB) or is a surface of it sampled in
// place (RGBA16F) and holds every pixel of a width_px x height_px pass; false otherwise (and when the
// path is switched off).
bool texel_copy_rows_of(const FragmentShader& shader, PixelFormat target_format, int width_px,
                        int height_px, TexelCopyRows& rows);

// Quads [0, quad_count) of `rect` (even origin and size) in the tile's row-major quad order:
// each pixel's texel code written to `plane` (tile memory rows plane_width values apart, the
// rect's top left at index 0), and the texels traced as the functor fetches them (quad by quad,
// lanes (x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1), repeats of the last granule dropped)
// to the thread's texel trace (raster/texel_trace.h).
void copy_texel_quads(const TexelCopyRows& rows, const TileRect& rect, int quad_count,
                      uint32_t* plane, int plane_width);
// The same into a colour plane (RGBA16F sources).
void copy_texel_quads(const TexelCopyRows& rows, const TileRect& rect, int quad_count,
                      glm::vec4* plane, int plane_width);

// On by default; tests turn it off to compare with the shaded copy (same images and counters).
// Set between frames only.
void set_texel_copy_pass_through(bool enabled);
// How many quads (since the process started) took the path, so tests can tell a frame used it.
uint64_t texel_copy_quads_passed_through();

}  // namespace ontile
