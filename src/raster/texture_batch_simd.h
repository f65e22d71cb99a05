// Texel reads of a whole fragment batch on SIMD lanes (Highway, integer arithmetic, float
// compares and table lookups only, so every target reads the same texels and values): nearest,
// clamp-to-edge texel coordinates as Texture2D's sampler computes them, and texel loads.
#pragma once
#include <cstdint>
#include <optional>

#include "raster/shader_interface.h"
#include "raster/texture.h"

namespace ontile {

// out[f] = the texel index along an axis of `size` texels that a nearest, clamp-to-edge sample
// of level 0 reads at normalized coordinate coord[f] (texture.cpp: finite_or_zero, texel_coord,
// floor, wrap_texel_index; i = floor(u * size), OpenGL 4.6 eq. 8.9), for f < count (a multiple
// of 16).
void nearest_clamped_texels(const float* coord, int count, int size, int32_t* out);

// colour[c][f] = channel c of view.load(x[f], y[f]) for fragments f < count (a multiple of 16)
// whose bit is set in `active`; other fragments keep their values. Every view kind is read
// (8-bit through its decode tables, floats as stored, surface formats per texel).
void load_texels(const Texture2D::TexelView& view, const int32_t* x, const int32_t* y, int count,
                 uint64_t active, float (&colour)[4][kBatchFragments]);

// The RGBA8 format whose codes view.load() decodes the texels from (UNORM, or sRGB colour with
// UNORM alpha, through pixel_format.h's tables), if any: a copy of such texels into an
// attachment of that format needs no quantising (BatchOutput::output0_codes_of).
std::optional<PixelFormat> rgba8_codes_format(const Texture2D::TexelView& view);

// Texture2D::sample_quad for each quad of a batch in order, when `sampler` makes it read level 0
// with a nearest, clamp-to-edge filter whatever the level of detail (nearest min and mag
// filters, one level or no mipmapping: render targets, copies): fragments [0, fragment_count)
// are sampled, helper lanes included, and traced in that order exactly as sample_quad traces
// them; out[c][f] is written up to the padded count (padding repeats the last fragment's uv).
// Returns false, reading and tracing nothing, for any other sampler.
// When it returns true and the texels are RGBA8 codes (UNORM, or sRGB colour with UNORM alpha,
// decoded by pixel_format.h's tables), *codes_of (if given) is set to that format, else nullopt.
bool sample_batch_nearest(const Texture2D& texture, const SamplerDesc& sampler, const float* u,
                          const float* v, int fragment_count, float (&out)[4][kBatchFragments],
                          std::optional<PixelFormat>* codes_of = nullptr);

}  // namespace ontile
