// The Sobel pass's texel trace for a whole batch on SIMD lanes (Highway, integer arithmetic
// only): the granules each fragment's per-tap sampling reads, in sampling order with
// consecutive repeats dropped, exactly as TapTrace::fragment and TapTrace::border record them.
#pragma once
#include <cstdint>

#include "raster/texture.h"
#include "shaders_cpp/toon/sobel_edge_kernel.h"

namespace ontile::sobel {

// Texture2D::texel_address of level 0: origin + (y * width + x) * texel_bytes.
struct TracePlane {
  uint64_t origin = 0;
  uint64_t texel_bytes = 0;
  int width = 0;
  TracePlane() = default;
  explicit TracePlane(const Texture2D::TexelView& v)
      : origin(v.address), texel_bytes(v.memory_bytes_per_texel), width(v.width) {}
};

// The planes a batch reads. Depth, normal and border share the depth grid's size.
struct BatchTracePlanes {
  TracePlane depth, normal, color, border;
  bool has_normal = false, has_border = false;
  // The lane kernels index texels (and float channels) with 32-bit integers: every plane must
  // hold fewer than 2^29 texels (callers fall back to TapTrace::fragment otherwise).
  static bool fits_lanes(const Texture2D::TexelView& depth, const Texture2D::TexelView& color);
};

// Reads per fragment in sampling order: 9 depth taps, the normal centre, the other 8 normal
// taps, the colour, the border.
constexpr int kTraceSlots = 2 * kTaps + 2;

// Writes, for each fragment f < count whose bit is set in `active` (in ascending f), the
// granules (byte address / 64) of its reads as sobel_edge_shader.h lists them: the 9 depth
// taps row by row, the normal centre (with a normal plane), the other 8 normal taps where
// depth found no edge, the colour at (color_x, color_y), the border at the nearest tap where
// there is an edge (with a border plane), each skipped when equal to the granule before it
// (`last_granule` before the first; updated). Returns how many granules it wrote to
// `granules` (room for count * kTraceSlots).
int trace_batch(const BatchTracePlanes& planes, const FragmentTaps& taps,
                const FragmentEdges& edges, int count, uint64_t active, uint64_t* granules,
                uint64_t& last_granule);

}  // namespace ontile::sobel
