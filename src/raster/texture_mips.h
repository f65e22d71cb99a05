// Builds a texture's full mip chain from its base level (used by Texture2D's factories).
#pragma once
#include <vector>

#include "raster/texture.h"

namespace ontile {

// Levels down to 1x1 from `base` (box filter in linear space; see texture.h from_rgba8).
std::vector<Texture2D::Level> build_mip_chain(Texture2D::Level base, TexelEncoding encoding);

}  // namespace ontile
