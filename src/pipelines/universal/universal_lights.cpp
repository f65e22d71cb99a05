// Lights of the universal pipeline (see universal_lights.h).
#include "pipelines/universal/universal_lights.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace ontile {
namespace {

float luminance(glm::vec3 rgb) { return glm::dot(rgb, glm::vec3(0.2126f, 0.7152f, 0.0722f)); }

std::string indexed(const char* name, size_t i) { return name + std::to_string(i); }

}  // namespace

UniversalLights universal_lights(const Scene& scene) {
  UniversalLights out;
  // The default sun of main_directional_light (lambert_shader.cpp), for scenes without one.
  out.main.to_light = glm::normalize(glm::vec3(-0.4f, 0.8f, 0.45f));
  out.main.radiance = glm::vec3(1.0f);
  const Light* main = nullptr;
  float best = -1.0f;
  for (const Light& light : scene.lights) {
    if (light.type != Light::Type::Directional) continue;
    const float strength = light.intensity * std::max({light.color.x, light.color.y, light.color.z});
    if (strength > best) {
      best = strength;
      main = &light;
    }
  }
  float exposure = 1.0f;
  if (main) {
    exposure = main->intensity > 0.0f ? 1.0f / main->intensity : 1.0f;
    out.main.to_light = -glm::normalize(main->direction);
    out.main.radiance = main->color * (main->intensity * exposure);
  }
  for (const Light& light : scene.lights) {
    if (&light == main) continue;
    AdditionalLight a;
    a.type = light.type == Light::Type::Spot          ? AdditionalLight::Type::Spot
             : light.type == Light::Type::Directional ? AdditionalLight::Type::Directional
                                                      : AdditionalLight::Type::Point;
    a.position = light.position;
    a.intensity = light.color * (light.intensity * exposure);
    a.range = light.range;
    a.direction = glm::normalize(light.direction);
    if (a.type == AdditionalLight::Type::Spot) {
      // KHR_lights_punctual, "Inner and Outer Cone Angles" (recommended implementation).
      const float cos_outer = std::cos(light.outer_cone_rad);
      const float cos_inner = std::cos(light.inner_cone_rad);
      a.spot_scale = 1.0f / std::max(0.001f, cos_inner - cos_outer);
      a.spot_offset = -cos_outer * a.spot_scale;
    }
    out.additional.push_back(a);
  }
  return out;
}

float light_influence(const AdditionalLight& light, const Bounds& b) {
  if (b.empty()) return 0.0f;
  if (light.type == AdditionalLight::Type::Directional) return luminance(light.intensity);
  const glm::vec3 closest = glm::clamp(light.position, b.min, b.max);
  const glm::vec3 d = closest - light.position;
  return luminance(light.intensity) * range_attenuation(glm::dot(d, d), light.range);
}

std::vector<int> select_additional_lights(const std::vector<AdditionalLight>& lights,
                                          const Bounds& world_bounds, int max_count) {
  std::vector<std::pair<float, int>> ranked;
  for (size_t i = 0; i < lights.size(); ++i) {
    const float influence = light_influence(lights[i], world_bounds);
    if (influence > 0.0f) ranked.emplace_back(influence, static_cast<int>(i));
  }
  std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  std::vector<int> chosen;
  for (size_t k = 0; k < ranked.size() && static_cast<int>(k) < max_count; ++k) {
    chosen.push_back(ranked[k].second);
  }
  return chosen;
}

void set_light_globals(CommandBuffer& cmd, const UniversalLights& lights) {
  cmd.set_global_vector("_MainLightDirection", glm::vec4(lights.main.to_light, 0.0f));
  cmd.set_global_vector("_MainLightColor", glm::vec4(lights.main.radiance, 1.0f));
  cmd.set_global_vector("_AmbientColor", glm::vec4(lights.ambient, 1.0f));
  cmd.set_global_float("_AdditionalLightsCount", static_cast<float>(lights.additional.size()));
  for (size_t i = 0; i < lights.additional.size(); ++i) {
    const AdditionalLight& a = lights.additional[i];
    cmd.set_global_vector(indexed("_AdditionalLightsPosition", i), glm::vec4(a.position, static_cast<float>(a.type)));
    cmd.set_global_vector(indexed("_AdditionalLightsColor", i), glm::vec4(a.intensity, a.range));
    cmd.set_global_vector(indexed("_AdditionalLightsDirection", i), glm::vec4(a.direction, 0.0f));
    cmd.set_global_vector(indexed("_AdditionalLightsAttenuation", i),
                          glm::vec4(a.spot_scale, a.spot_offset, 0.0f, 0.0f));
  }
}

UniversalLights read_light_globals(const PropertyBlock& p) {
  UniversalLights out;
  out.main.to_light = glm::vec3(p.get_vector("_MainLightDirection", glm::vec4(out.main.to_light, 0.0f)));
  out.main.radiance = glm::vec3(p.get_vector("_MainLightColor", glm::vec4(out.main.radiance, 1.0f)));
  out.ambient = glm::vec3(p.get_vector("_AmbientColor", glm::vec4(out.ambient, 1.0f)));
  const int count = static_cast<int>(p.get_float("_AdditionalLightsCount", 0.0f));
  for (int i = 0; i < count; ++i) {
    AdditionalLight a;
    const glm::vec4 position = p.get_vector(indexed("_AdditionalLightsPosition", i));
    const glm::vec4 color = p.get_vector(indexed("_AdditionalLightsColor", i));
    const glm::vec4 attenuation = p.get_vector(indexed("_AdditionalLightsAttenuation", i), glm::vec4(0, 1, 0, 0));
    a.position = glm::vec3(position);
    a.type = static_cast<AdditionalLight::Type>(static_cast<int>(position.w));
    a.intensity = glm::vec3(color);
    a.range = color.w;
    a.direction = glm::vec3(p.get_vector(indexed("_AdditionalLightsDirection", i), glm::vec4(0, 0, -1, 0)));
    a.spot_scale = attenuation.x;
    a.spot_offset = attenuation.y;
    out.additional.push_back(a);
  }
  return out;
}

}  // namespace ontile
