// The gradient sky of GradientSkyShader (full_screen.h) over a whole fragment batch on SIMD lanes.
#pragma once
#include <glm/glm.hpp>

#include "raster/shader_interface.h"

namespace ontile {

struct SkyColours {
  glm::vec3 zenith, horizon, ground;
};

// For fragments [0, n) rounded up to whole vectors (n <= kBatchFragments), from the view
// direction (dx, dy, dz): up = the direction's unit y (0 for a zero or NaN length); above the
// horizon (up >= 0) mix(horizon, zenith, sqrt(up)), below it mix(horizon, ground, min(1, -up * 4));
// alpha 1. The scalar formula's IEEE operations in its order, so every target gives its bits.
void gradient_sky_batch(const float* dx, const float* dy, const float* dz, int n, const SkyColours& sky,
                        float (&colour)[4][kBatchFragments]);

}  // namespace ontile
