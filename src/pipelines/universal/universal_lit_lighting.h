// The Universal Lit forward functor's lighting over a whole batch as structure-of-arrays loops
// (ambient, the main light, the additional lights): blinn_phong, range_attenuation and
// spot_attenuation bit for bit (the same float operations in the same order, std::max, std::clamp
// and glm::max as their comparisons, branches as selects), so the compiler can run them on SIMD
// lanes; only std::pow stays one call per lit fragment and light, skipped where its result
// cannot change the bits (a light that does not reach the fragment).
#pragma once
#include <cstdint>

#include "raster/shader_interface.h"

namespace ontile {

struct UniversalLitParams;  // universal_lit_functors.h

// rgb[c][f] := the Lit functor's colour before emission, for fragments f < count whose bit is
// set in `lit` (others are left undefined). normal: unit shading normals; albedo: base colour
// (x texture); visibility: the main light's shadow visibility per fragment, or null (lit).
void universal_lit_lighting(const UniversalLitParams& p, const FragmentBatch& batch,
                            const float (&normal)[3][kBatchFragments], const float (&albedo)[4][kBatchFragments],
                            const float* visibility, uint64_t lit, int count, float (&rgb)[3][kBatchFragments]);

}  // namespace ontile
