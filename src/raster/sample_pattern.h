// Standard multisample positions (Vulkan spec 25.3 "Multisampling", identical to the D3D11
// standard patterns), in subpixel units (1/256 px) from the pixel's top-left corner.
#pragma once
#include <cstdint>

#include "raster/raster_types.h"

namespace ontile {

struct SamplePattern {
  int count = 1;
  int32_t x[kMaxSamples] = {};
  int32_t y[kMaxSamples] = {};
};

// count must be 1, 2, 4 or 8; returns nullptr otherwise.
const SamplePattern* standard_sample_pattern(int count);

}  // namespace ontile
