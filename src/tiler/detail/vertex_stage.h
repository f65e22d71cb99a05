// The per-draw vertex stage of binning: vertex shading, then, once per vertex rather than once
// per triangle corner, the clip outcode and the snapped screen position that setup needs.
#pragma once
#include <atomic>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "raster/clip.h"
#include "raster/triangle_setup.h"
#include "tiler/detail/parameter_buffer.h"
#include "tiler/detail/vertex_kernels.h"
#include "util/uninitialized_vector.h"

namespace ontile {

struct ShadedDraw {
  int varying_count = 0;
  UninitializedVector<glm::vec4> positions;
  UninitializedVector<float> varyings;  // varying_count per vertex, NaN/Inf replaced by 0
  // classify_and_snap() of every vertex: its outcode, and its snapped position, which is only
  // meaningful (and only used) for vertices inside every clipping plane.
  UninitializedVector<uint16_t> outcode;
  UninitializedVector<SnappedVertex> snapped;
  // Set to 1 by primitive assembly for every vertex an index references (chunks of the draw
  // assemble in parallel, hence atomics): the vertices a vertex fetch reads from memory.
  std::vector<std::atomic<uint8_t>> referenced;
  // With index-driven vertex shading only (else empty): set to 1 for every vertex a binned
  // triangle record references, the vertices whose varyings the parameter buffer holds.
  std::vector<std::atomic<uint8_t>> varyings_written;
};

// Shades every vertex of the draw in parallel on the current oneTBB arena and classifies and
// snaps it for `grid`; adds vertices_shaded and varyings_sanitized to `counters`. `idvs` sizes
// varyings_written.
ShadedDraw shade_draw(const DrawCall& draw, const TileGrid& grid, const GuardBand& guard,
                      GeometryCounters& counters, bool idvs = false);

// Vertices marked in `referenced`: the unique vertices the draw's indices reference.
uint64_t count_referenced_vertices(const ShadedDraw& shaded);
// Vertices marked in `varyings_written`.
uint64_t count_varying_vertices(const ShadedDraw& shaded);

}  // namespace ontile
