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

// Direct light reflected towards the viewer, into sum, for the fragments of `batch` whose bit
// is set in `lit` (bit f: fragment f, all below fragment_count()): the sun, then the grid
// cell's lights in ascending index order (a fixed order, so every variant rounds identically),
// light by light over runs of fragments that share a grid cell.
inline void direct_lighting(const SceneLighting& lighting, const BrdfBatch& brdf, const BatchVec3& n,
                            const BatchVec3& world_position, const BatchVec3& to_view,
                            const FragmentBatch& batch, uint64_t lit, BatchVec3& sum) {
  const int count = batch.fragment_count();
  // Whole arrays: the lanes round the batch up to a vector (their results are not kept).
  alignas(64) int32_t lit_lanes[kBatchFragments] = {}, reached[kBatchFragments] = {};
  alignas(64) BatchVec3 to_light, radiance;
  for (int f = 0; f < count; ++f) lit_lanes[f] = static_cast<int32_t>((lit >> f) & 1u);
  for (int c = 0; c < 3; ++c) {
    // glm's operator[] is a switch: read once so the fills vectorise.
    const float to_light_value = lighting.sun_to_light[c], radiance_value = lighting.sun_radiance[c];
    for (int f = 0; f < count; ++f) {
      to_light[c][f] = to_light_value;
      radiance[c][f] = radiance_value;
    }
  }
  shade_ggx(brdf, n, to_view, to_light, radiance, lit_lanes, 0, count, false, sum);
  // Runs of fragments in one grid cell share its light list (a fragment's sum does not depend
  // on how fragments are grouped: each adds its cell's lights in order).
  alignas(64) int32_t cell[kBatchFragments];
  for (int f = 0; f < count; ++f) cell[f] = lighting.grid.cell_at(batch.x_px(f), batch.y_px(f));
  int begin = 0;
  while (begin < count) {
    int end = begin + 1;
    while (end < count && cell[end] == cell[begin]) ++end;
    for (const uint32_t index : lighting.grid.lights_in(cell[begin])) {
      light_incidence(lighting.lights[index], world_position, lit_lanes, begin, end, to_light, radiance, reached);
      shade_ggx(brdf, n, to_view, to_light, radiance, reached, begin, end, true, sum);
    }
    begin = end;
  }
}

}  // namespace ontile
