// Punctual lights as glTF's KHR_lights_punctual defines them (point, spot, directional), with
// the extension's recommended range and cone attenuation. Shared by every lit functor.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>


namespace ontile {

struct PunctualLight {
  enum class Type { Point, Spot, Directional } type = Type::Point;
  glm::vec3 position{0.0f};
  // colour x intensity x exposure: candela for point and spot lights, before the distance
  // falloff; a directional light's radiance
  glm::vec3 intensity{1.0f};
  float range = 0.0f;  // 0: infinite
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit, the way the light travels (spot, directional)
  // Cone falloff saturate(cos(angle) * scale + offset)^2; a point light has scale 0, offset 1.
  float spot_scale = 0.0f, spot_offset = 1.0f;
};

// KHR_lights_punctual recommended range attenuation: clamp(1 - (d / range)^4, 0, 1) / d^2
// (range 0: 1 / d^2), with d^2 floored at 1e-4 so a surface at the light stays finite.
inline float range_attenuation(float distance_squared, float range) {
  const float d2 = std::max(distance_squared, 1e-4f);
  if (range <= 0.0f) return 1.0f / d2;
  const float ratio2 = d2 / (range * range);  // (d / range)^2
  const float window = std::clamp(1.0f - ratio2 * ratio2, 0.0f, 1.0f);
  return window / d2;
}

// The cone factor for a unit direction from the light to the surface (1 unless a spot light).
inline float spot_attenuation(const PunctualLight& light, glm::vec3 light_to_surface) {
  if (light.type != PunctualLight::Type::Spot) return 1.0f;
  const float cd = glm::dot(light.direction, light_to_surface);
  const float a = std::clamp(cd * light.spot_scale + light.spot_offset, 0.0f, 1.0f);
  return a * a;
}

// The radiance arriving at `surface` and the unit direction towards the light; false when the
// light cannot reach it (outside its range or cone).
inline bool light_incidence(const PunctualLight& light, glm::vec3 surface, glm::vec3& to_light,
                            glm::vec3& radiance) {
  if (light.type == PunctualLight::Type::Directional) {
    to_light = -light.direction;
    radiance = light.intensity;
    return true;
  }
  const glm::vec3 offset = light.position - surface;
  const float distance_squared = glm::dot(offset, offset);
  if (light.range > 0.0f && distance_squared >= light.range * light.range) return false;
  to_light = offset / std::sqrt(std::max(distance_squared, 1e-8f));
  const float falloff = range_attenuation(distance_squared, light.range) * spot_attenuation(light, -to_light);
  if (!(falloff > 0.0f)) return false;
  radiance = light.intensity * falloff;
  return true;
}

}  // namespace ontile
