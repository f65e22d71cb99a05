// Batched Universal Lit lighting (see universal_lit_lighting.h). Each loop mirrors one step of
// the scalar per-fragment code it replaced, in its evaluation order: glm's vector operators
// are per component, glm::dot is (x + y) + z of the products, glm::length its square root.
#include "pipelines/universal/universal_lit_lighting.h"

#include "pipelines/universal/universal_lit_functors.h"

#include <cmath>

namespace ontile {
namespace {

using Lanes3 = float[3][kBatchFragments];

struct SurfaceLanes {
  const Lanes3& normal;
  const Lanes3& to_view;
  const Lanes3& diffuse;
  const Lanes3& specular;
};

// rgb += blinn_phong(diffuse, specular, shininess, n, to_view, to_light, radiance) per fragment;
// fragments not in `lit` or facing away (!(N.L > 0)) add vec3(0), as the scalar early return.
void add_blinn_phong(const SurfaceLanes& s, const Lanes3& to_light, const Lanes3& radiance, float shininess,
                     uint64_t lit, int count, Lanes3& rgb) {
  alignas(64) float n_dot_l[kBatchFragments], n_dot_h[kBatchFragments], power[kBatchFragments];
  const Lanes3& n = s.normal;
  for (int f = 0; f < count; ++f) {
    n_dot_l[f] = (n[0][f] * to_light[0][f] + n[1][f] * to_light[1][f]) + n[2][f] * to_light[2][f];
    const float hx = to_light[0][f] + s.to_view[0][f];
    const float hy = to_light[1][f] + s.to_view[1][f];
    const float hz = to_light[2][f] + s.to_view[2][f];
    const float half_length = std::sqrt((hx * hx + hy * hy) + hz * hz);
    const bool has_length = half_length > 0.0f;
    const float divisor = has_length ? half_length : 1.0f;  // divide only by the length it uses
    const float d = (n[0][f] * (hx / divisor) + n[1][f] * (hy / divisor)) + n[2][f] * (hz / divisor);
    n_dot_h[f] = has_length ? (d < 0.0f ? 0.0f : d) : 0.0f;  // glm::max(d, 0)
  }
  for (int f = 0; f < count; ++f) {
    const bool shaded = ((lit >> f) & 1u) && n_dot_l[f] > 0.0f;
    power[f] = shaded ? std::pow(n_dot_h[f], shininess) : 0.0f;
  }
  for (int c = 0; c < 3; ++c) {
    for (int f = 0; f < count; ++f) {
      const float term = (radiance[c][f] * n_dot_l[f]) * (s.diffuse[c][f] + s.specular[c][f] * power[f]);
      rgb[c][f] = rgb[c][f] + (n_dot_l[f] > 0.0f ? term : 0.0f);
    }
  }
}

// The additional light's to_light and radiance per fragment (the scalar loop's preamble,
// range_attenuation x spot_attenuation with light_to_surface = -to_light).
void additional_light_lanes(const AdditionalLight& light, const FragmentBatch& batch, const Lanes3& normal,
                            int count, Lanes3& to_light, Lanes3& radiance) {
  if (light.type == AdditionalLight::Type::Directional) {
    for (int c = 0; c < 3; ++c) {
      const float l = -light.direction[c], intensity = light.intensity[c];
      for (int f = 0; f < count; ++f) {
        to_light[c][f] = l;
        radiance[c][f] = intensity;
      }
    }
    return;
  }
  const float* px = batch.varyings[MeshVertexShader::kWorldPos];
  const float* py = batch.varyings[MeshVertexShader::kWorldPos + 1];
  const float* pz = batch.varyings[MeshVertexShader::kWorldPos + 2];
  const glm::vec3 p = light.position, direction = light.direction;
  const bool infinite_range = light.range <= 0.0f;
  const float range2 = light.range * light.range;
  const bool spot = light.type == AdditionalLight::Type::Spot;
  alignas(64) float falloff[kBatchFragments];
  for (int f = 0; f < count; ++f) {
    const float ox = p.x - px[f], oy = p.y - py[f], oz = p.z - pz[f];
    const float distance_squared = (ox * ox + oy * oy) + oz * oz;
    const bool has_length = distance_squared > 0.0f;
    const float length = std::sqrt(has_length ? distance_squared : 1.0f);
    const float lx = has_length ? ox / length : normal[0][f];
    const float ly = has_length ? oy / length : normal[1][f];
    const float lz = has_length ? oz / length : normal[2][f];
    // range_attenuation(distance_squared, light.range)
    const float d2 = distance_squared < 1e-4f ? 1e-4f : distance_squared;  // std::max
    const float ratio2 = d2 / range2;
    const float window_raw = 1.0f - ratio2 * ratio2;
    const float window_low = window_raw < 0.0f ? 0.0f : window_raw;  // std::clamp
    const float window = 1.0f < window_low ? 1.0f : window_low;
    const float range_factor = infinite_range ? 1.0f / d2 : window / d2;
    // spot_attenuation(light, -to_light)
    const float cd = (direction.x * -lx + direction.y * -ly) + direction.z * -lz;
    const float a_raw = cd * light.spot_scale + light.spot_offset;
    const float a_low = a_raw < 0.0f ? 0.0f : a_raw;
    const float a = 1.0f < a_low ? 1.0f : a_low;
    falloff[f] = range_factor * (spot ? a * a : 1.0f);
    to_light[0][f] = lx;
    to_light[1][f] = ly;
    to_light[2][f] = lz;
  }
  for (int c = 0; c < 3; ++c) {
    const float intensity = light.intensity[c];
    for (int f = 0; f < count; ++f) radiance[c][f] = intensity * falloff[f];
  }
}

}  // namespace

void universal_lit_lighting(const UniversalLitParams& p, const FragmentBatch& batch, const Lanes3& normal,
                            const float (&albedo)[4][kBatchFragments], const float* visibility, uint64_t lit,
                            int count, Lanes3& rgb) {
  alignas(64) Lanes3 to_view, diffuse, specular, to_light, radiance;
  const float* px = batch.varyings[MeshVertexShader::kWorldPos];
  const float* py = batch.varyings[MeshVertexShader::kWorldPos + 1];
  const float* pz = batch.varyings[MeshVertexShader::kWorldPos + 2];
  const glm::vec3 camera = p.camera_position;
  for (int f = 0; f < count; ++f) {
    const float tx = camera.x - px[f], ty = camera.y - py[f], tz = camera.z - pz[f];
    const float camera_distance = std::sqrt((tx * tx + ty * ty) + tz * tz);
    const bool has_distance = camera_distance > 0.0f;
    const float divisor = has_distance ? camera_distance : 1.0f;
    to_view[0][f] = has_distance ? tx / divisor : normal[0][f];
    to_view[1][f] = has_distance ? ty / divisor : normal[1][f];
    to_view[2][f] = has_distance ? tz / divisor : normal[2][f];
  }
  // diffuse = base x (1 - metallic); specular = glm::mix(vec3(0.04), base, metallic) =
  // 0.04 x (1 - metallic) + base x metallic; rgb = ambient x (diffuse + specular).
  const float dielectric = 1.0f - p.metallic;
  const float specular_floor = 0.04f * (1.0f - p.metallic);
  for (int c = 0; c < 3; ++c) {
    const float ambient = p.ambient[c];
    for (int f = 0; f < count; ++f) {
      const float base = albedo[c][f];
      diffuse[c][f] = base * dielectric;
      specular[c][f] = specular_floor + base * p.metallic;
      rgb[c][f] = ambient * (diffuse[c][f] + specular[c][f]);
    }
  }
  const SurfaceLanes surface{normal, to_view, diffuse, specular};
  const float shininess = std::exp2(10.0f * p.smoothness + 1.0f);
  for (int c = 0; c < 3; ++c) {
    const float l = p.main_light.to_light[c], r = p.main_light.radiance[c];
    for (int f = 0; f < count; ++f) {
      to_light[c][f] = l;
      radiance[c][f] = visibility ? r * visibility[f] : r;
    }
  }
  add_blinn_phong(surface, to_light, radiance, shininess, lit, count, rgb);
  for (int i = 0; i < p.additional_light_count; ++i) {
    additional_light_lanes(p.additional_lights[i], batch, normal, count, to_light, radiance);
    add_blinn_phong(surface, to_light, radiance, shininess, lit, count, rgb);
  }
}

}  // namespace ontile
