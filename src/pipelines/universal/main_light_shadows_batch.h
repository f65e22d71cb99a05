// Main-light shadow lookups of a whole fragment batch on SIMD lanes: the visibility bits of
// main_light_visibility for every fragment, and its texel trace emitted quad by quad so the
// functor can keep the per-quad order of its texture reads.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "pipelines/universal/main_light_shadows.h"
#include "raster/shader_interface.h"

namespace ontile {

constexpr int kShadowTaps = 9;  // 3x3 PCF, row by row

struct ShadowBatch {
  alignas(64) float visibility[kBatchFragments];
  // Tap t's 64-byte granule minus the granule of the map's texel (0, 0), per fragment.
  alignas(64) uint32_t granule_offset[kShadowTaps][kBatchFragments];
  // Bit t - 1 (t = 1..8): tap t's granule differs from tap t - 1's, i.e. the trace keeps it.
  alignas(64) int32_t tap_changes[kBatchFragments];
  uint64_t inside = 0;  // bit f: fragment f's point projects into the map (its taps are read)
};

// Whether main_light_visibility_batch can read this map on lanes: 32-bit float texels (a D32F or
// R32F surface in place, or float texels), a 64-byte aligned level 0 under 2 GiB. Otherwise call
// main_light_visibility per fragment.
bool shadow_batch_supported(const ShadowLookup& lookup);

// main_light_visibility of fragments [0, count) (count a multiple of 16) at world positions
// (x, y, z)[f] with unit normals normal[c][f], computed with the same float operations in the
// same order, so every bit matches; traces nothing (see trace_shadow_quad). Requires
// shadow_batch_supported(lookup).
void main_light_visibility_batch(const ShadowLookup& lookup, const float* x, const float* y,
                                 const float* z, const float (&normal)[3][kBatchFragments],
                                 glm::vec3 to_light, int count, ShadowBatch& out);

constexpr int kMaxShadowQuadGranules = kQuadLanes * kShadowTaps;

// What trace_shadow_quad appends, written to granules[0 ..) instead (at most
// kMaxShadowQuadGranules), repeats of `last` (the trace's last granule, updated) removed;
// returns the count.
int shadow_quad_granules(const ShadowLookup& lookup, const ShadowBatch& batch, int q, unsigned lanes,
                         uint64_t* granules, uint64_t& last);

// Appends to the thread's texel trace what main_light_visibility records for the fragments of
// quad q whose lane bit is set in `lanes`, in lane order.
void trace_shadow_quad(const ShadowLookup& lookup, const ShadowBatch& batch, int q, unsigned lanes);

}  // namespace ontile
