// The scene's main directional light for Lambert shading (see lambert_shader.h).
#include "shaders_cpp/lambert_shader.h"

namespace ontile {

DirectionalLighting main_directional_light(const Scene& scene) {
  DirectionalLighting lighting;
  lighting.to_light = glm::normalize(glm::vec3(-0.4f, 0.8f, 0.45f));
  lighting.radiance = glm::vec3(1.0f);
  float best = -1.0f;
  for (const Light& light : scene.lights) {
    if (light.type != Light::Type::Directional) continue;
    const float strength =
        light.intensity * glm::max(light.color.x, glm::max(light.color.y, light.color.z));
    if (strength > best) {
      best = strength;
      lighting.to_light = -glm::normalize(light.direction);
      // The light's colour only: glTF intensities are physical (lux) and this display-referred
      // Lambert has no exposure, so the strongest light is normalised to full brightness.
      lighting.radiance = light.color;
    }
  }
  return lighting;
}

}  // namespace ontile
