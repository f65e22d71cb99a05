// Texture2D::fetch for a whole fragment batch (shaders that read render targets at their own
// pixel, like deferred lighting's texelFetch): values through load_texels on SIMD lanes, and
// the texel trace in the order per-fragment fetch calls would have recorded it.
#pragma once
#include <cstdint>

#include "raster/shader_interface.h"
#include "raster/texture.h"

namespace ontile {

// Level 0 of `texture` as a view a batch can read, or false when it cannot: block-compressed
// storage (texels map to blocks), or a level too large for 32-bit texel indices on lanes.
bool batch_fetch_view(const Texture2D& texture, Texture2D::TexelView& view);

// The texel trace of Texture2D::fetch(0, x[f], y[f]) calls made fragment by fragment (f
// ascending) and, within a fragment, texture by texture, texture k only for the fragments whose
// bit is set in fetched[k]: what those calls append to the trace, consecutive repeats of a
// granule dropped. Nothing when no trace is being recorded.
void trace_fetches(const Texture2D::TexelView* views, int texture_count, const int32_t* x, const int32_t* y,
                   int fragment_count, const uint64_t* fetched);

}  // namespace ontile
