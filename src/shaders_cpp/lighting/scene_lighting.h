// Everything the lit functors of the forward and deferred pipelines shade with: ambient, the
// main directional light, the punctual lights with their screen-space light grid, and the one
// function that sums the lights, so forward and deferred add the same terms in the same order.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/lighting/brdf.h"
#include "shaders_cpp/lighting/light_grid.h"
#include "shaders_cpp/lighting/punctual_light.h"

namespace ontile {

struct SceneLighting {
  glm::vec3 ambient{0.2f};
  glm::vec3 sun_to_light{0.0f, 1.0f, 0.0f};  // unit, world space
  glm::vec3 sun_radiance{1.0f};
  std::vector<PunctualLight> lights;  // indexed by the grid
  LightGrid grid;
};

// direct_lighting over fragments [0, count) whose light-grid cells are cell[f], on SIMD lanes
// (lighting_lanes.cpp): the same operations in the same order, each light's incidence, GGX and
// Schlick power kept in registers.
void direct_lighting_lanes(const SceneLighting& lighting, const BrdfBatch& brdf, const BatchVec3& n,
                           const BatchVec3& world_position, const BatchVec3& to_view, const int32_t* cell, int count,
                           uint64_t lit, BatchVec3& sum);

// Direct light reflected towards the viewer, into sum, for the fragments of `batch` whose bit
// is set in `lit` (bit f: fragment f, all below fragment_count()): the sun, then the grid
// cell's lights in ascending index order (a fixed order, so every variant rounds identically),
// light by light over runs of fragments that share a grid cell (a fragment's sum does not depend
// on how fragments are grouped: each adds its own cell's lights in order). Other fragments keep
// sum.
inline void direct_lighting(const SceneLighting& lighting, const BrdfBatch& brdf, const BatchVec3& n,
                            const BatchVec3& world_position, const BatchVec3& to_view,
                            const FragmentBatch& batch, uint64_t lit, BatchVec3& sum) {
  const int count = batch.fragment_count();
  alignas(64) int32_t cell[kBatchFragments];
  constexpr int kLastInCell = LightGrid::kCellSizePx - 1;
  static_assert((LightGrid::kCellSizePx & kLastInCell) == 0, "cells a power of two wide");
  for (int q = 0; q < batch.quad_count; ++q) {
    const int x = batch.quad_x_px[q], y = batch.quad_y_px[q];
    int32_t* lanes = cell + q * kQuadLanes;
    // Cells are rectangles: when the quad's corners share one, so do its four pixels. At
    // x, y >= 0, (x + 1, y + 1) is in (x, y)'s cell unless x or y is a cell's last column or
    // row (a quad at even pixels never is): one lookup, with no second division.
    if (x >= 0 && y >= 0 && (x & kLastInCell) != kLastInCell && (y & kLastInCell) != kLastInCell) {
      lanes[0] = lanes[1] = lanes[2] = lanes[3] = lighting.grid.cell_at(x, y);
    } else {
      for (int lane = 0; lane < kQuadLanes; ++lane) lanes[lane] = lighting.grid.cell_at(x + (lane & 1), y + (lane >> 1));
    }
  }
  direct_lighting_lanes(lighting, brdf, n, world_position, to_view, cell, count, lit, sum);
}

}  // namespace ontile
