// Lights of the `universal` pipeline: the scene's KHR_lights_punctual lights turned into a main
// directional light and additional lights, glTF's recommended attenuation, the per-object
// choice of the most influential additional lights, and the shader globals that carry them
// from the pipeline to the Lit shader's pass factory.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/kit/pipeline_api.h"
#include "scene/scene.h"
#include "shaders_cpp/lighting/punctual_light.h"

namespace ontile {

// The forward pass shades at most 8 lights per object, URP's per-object limit: the main
// directional light and up to 7 additional lights.
constexpr int kMaxAdditionalLightsPerObject = 7;
constexpr int kMaxLightsPerObject = 1 + kMaxAdditionalLightsPerObject;

struct MainLight {
  glm::vec3 to_light{0.0f, 1.0f, 0.0f};  // unit, world space
  glm::vec3 radiance{1.0f};              // colour x intensity x exposure
};

// Additional lights are glTF punctual lights (shaders_cpp/lighting/punctual_light.h).
using AdditionalLight = PunctualLight;

struct UniversalLights {
  MainLight main;
  // Every other light in scene order: point, spot and the other directional lights.
  std::vector<AdditionalLight> additional;
  glm::vec3 ambient{0.2f};
};

// The strongest directional light becomes the main light (main_directional_light's choice and
// default sun). Exposure normalises the main light's radiance to its colour (glTF directional
// intensities are lux, point/spot intensities candela, and this display-referred pipeline has
// no camera exposure): every light is scaled by 1 / main light intensity, so point and spot
// lights keep their strength relative to the sun. Without a directional light the scale is 1.
UniversalLights universal_lights(const Scene& scene);

// range_attenuation and spot_attenuation: shaders_cpp/lighting/punctual_light.h.

// How strongly a light can reach a box: luminance of its intensity x range attenuation at the
// box's closest point (the cone is ignored, so a spot is never wrongly dropped; directional
// lights: the luminance of their radiance). 0 = no effect.
float light_influence(const AdditionalLight& light, const Bounds& world_bounds);
// Indices of at most max_count lights with influence > 0, strongest first, ties by index.
std::vector<int> select_additional_lights(const std::vector<AdditionalLight>& lights,
                                          const Bounds& world_bounds, int max_count);

// Globals: _MainLightDirection, _MainLightColor, _AmbientColor, _AdditionalLightsCount and per
// light i _AdditionalLightsPosition<i> (xyz, w = type: 0 point, 1 spot, 2 directional),
// _AdditionalLightsColor<i> (xyz,
// w = range), _AdditionalLightsDirection<i> (xyz), _AdditionalLightsAttenuation<i> (scale,
// offset).
void set_light_globals(CommandBuffer& cmd, const UniversalLights& lights);
// Reads them back (missing values: the defaults above).
UniversalLights read_light_globals(const PropertyBlock& properties);

}  // namespace ontile
