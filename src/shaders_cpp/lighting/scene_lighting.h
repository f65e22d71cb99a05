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
  alignas(64) int32_t lit_lanes[kBatchFragments], reached[kBatchFragments];
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
  int begin = 0;
  while (begin < count) {
    const std::span<const uint32_t> lights = lighting.grid.lights_at(batch.x_px(begin), batch.y_px(begin));
    int end = begin + 1;
    while (end < count) {
      const std::span<const uint32_t> next = lighting.grid.lights_at(batch.x_px(end), batch.y_px(end));
      if (next.data() != lights.data() || next.size() != lights.size()) break;
      ++end;
    }
    for (const uint32_t index : lights) {
      light_incidence(lighting.lights[index], world_position, lit_lanes, begin, end, to_light, radiance, reached);
      shade_ggx(brdf, n, to_view, to_light, radiance, reached, begin, end, true, sum);
    }
    begin = end;
  }
}

}  // namespace ontile
