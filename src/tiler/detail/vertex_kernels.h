// SIMD classification and snapping of shaded vertices for binning: the clip outcode of
// clip_outcode() and the snapped position of snap_vertex(), bit for bit, on every Highway target.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/clip.h"
#include "raster/triangle_setup.h"

namespace ontile {

// Vertex class bit for a position with a NaN/Inf component (its triangles are dropped).
constexpr uint16_t kNonFiniteVertex = 0x8000;
static_assert(kNonFiniteVertex > (1u << clip_plane::kPlaneCount));

// For each of `count` positions: outcode[i] = kNonFiniteVertex if a component is NaN/Inf, else
// clip_outcode(position[i], guard); and snapped[i] = snap_vertex(position[i], ...) for every
// vertex whose outcode has no bit of kNonFiniteVertex | kClippingPlaneMask (the others'
// snapped[i] is written with unspecified values).
void classify_and_snap(const glm::vec4* position, uint32_t count, const GuardBand& guard,
                       int width_px, int height_px, int subpixel_bits, uint16_t* outcode,
                       SnappedVertex* snapped);

}  // namespace ontile
