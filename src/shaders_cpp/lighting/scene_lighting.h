// Everything the lit functors of the forward and deferred pipelines shade with: ambient, the
// main directional light, the punctual lights with their screen-space light grid, and the one
// function that sums the lights, so forward and deferred add the same terms in the same order.
#pragma once
#include <vector>

#include <glm/glm.hpp>

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

// Direct light reflected towards the viewer at one pixel: the sun, then the grid cell's lights
// in ascending index order (a fixed order, so every variant rounds identically).
inline glm::vec3 direct_lighting(const SceneLighting& lighting, const BrdfInputs& brdf, glm::vec3 n,
                                 glm::vec3 world_position, glm::vec3 to_view, int x_px, int y_px) {
  glm::vec3 sum = shade_ggx(brdf, n, to_view, lighting.sun_to_light, lighting.sun_radiance);
  for (const uint32_t index : lighting.grid.lights_at(x_px, y_px)) {
    glm::vec3 to_light, radiance;
    if (light_incidence(lighting.lights[index], world_position, to_light, radiance)) {
      sum += shade_ggx(brdf, n, to_view, to_light, radiance);
    }
  }
  return sum;
}

}  // namespace ontile
