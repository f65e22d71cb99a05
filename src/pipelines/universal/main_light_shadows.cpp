// Main-light shadow map fitting and lookup (see main_light_shadows.h).
#include "pipelines/universal/main_light_shadows.h"

#include "raster/texel_trace.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace ontile {
namespace {

glm::dvec3 corner(const Bounds& b, int i) {
  return {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
}

}  // namespace

MainLightShadowSetup fit_main_light_shadow(glm::vec3 to_light, const Bounds& receivers,
                                           const Bounds& scene_bounds, int map_size_px) {
  const glm::dvec3 towards(glm::normalize(to_light));
  const glm::dvec3 up = std::abs(towards.y) > 0.99 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  const glm::dvec3 centre(receivers.center());
  const glm::dmat4 view = glm::lookAtRH(centre + towards, centre, up);

  // Light space: x, y across the map, distance from the light origin along -z.
  glm::dvec3 lo(1e300), hi(-1e300);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p(view * glm::dvec4(corner(receivers, i), 1.0));
    lo = glm::min(lo, glm::dvec3(p.x, p.y, -p.z));
    hi = glm::max(hi, glm::dvec3(p.x, p.y, -p.z));
  }
  double near_distance = lo.z;
  if (!scene_bounds.empty()) {
    for (int i = 0; i < 8; ++i) {
      near_distance = std::min(near_distance, -(view * glm::dvec4(corner(scene_bounds, i), 1.0)).z);
    }
  }
  // Margins keep surfaces exactly on the fitted box inside the depth range and a flat receiver
  // seen edge-on from the light from giving a zero-width map.
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - near_distance, 1e-3});
  const double margin = extent * 1e-3;
  lo -= margin;
  hi += margin;
  near_distance -= margin;

  MainLightShadowSetup out;
  out.light_camera.view = view;
  out.light_camera.projection = glm::orthoRH_ZO(lo.x, hi.x, lo.y, hi.y, near_distance, hi.z);
  out.light_camera.view_projection = out.light_camera.projection * view;
  // The front-to-back sort measures from here: the middle of the near plane.
  out.light_camera.position = centre + towards * (1.0 - near_distance);
  // NDC (x, y) in [-1, 1] with +y up -> texture (u, v) with v = 0 at the top row.
  glm::dmat4 ndc_to_uv(1.0);
  ndc_to_uv[0][0] = 0.5;
  ndc_to_uv[1][1] = -0.5;
  ndc_to_uv[3][0] = 0.5;
  ndc_to_uv[3][1] = 0.5;
  out.world_to_shadow = ndc_to_uv * out.light_camera.view_projection;
  out.texel_size_world = static_cast<float>(std::max(hi.x - lo.x, hi.y - lo.y) / map_size_px);
  return out;
}

float main_light_visibility(const ShadowLookup& s, glm::vec3 world_position, glm::vec3 n,
                            glm::vec3 to_light) {
  const float n_dot_l = std::clamp(glm::dot(n, to_light), 0.0f, 1.0f);
  const glm::vec3 biased = world_position + to_light * s.depth_bias_world +
                           n * (s.normal_bias_world * (1.0f - n_dot_l));
  const glm::vec4 p = s.world_to_shadow * glm::vec4(biased, 1.0f);
  // Written so that NaN coordinates also count as outside.
  if (!(p.x >= 0.0f && p.x <= 1.0f && p.y >= 0.0f && p.y <= 1.0f && p.z >= 0.0f && p.z <= 1.0f)) {
    return 1.0f;
  }
  const Texture2D::TexelView& map = s.texels;
  const int w = map.width, h = map.height;
  const int cx = std::min(static_cast<int>(p.x * static_cast<float>(w)), w - 1);
  const int cy = std::min(static_cast<int>(p.y * static_cast<float>(h)), h - 1);
  int xs[3], ys[3];
  for (int d = 0; d < 3; ++d) {
    xs[d] = std::clamp(cx + d - 1, 0, w - 1);
    ys[d] = std::clamp(cy + d - 1, 0, h - 1);
  }
  // The texel trace of 9 Texture2D::fetch calls, row by row, with the thread's sink and last
  // granule held in locals across them (record_texel_address's merge of repeats).
  std::vector<uint64_t>* const sink = texel_trace_detail::sink;
  uint64_t last_granule = texel_trace_detail::last_granule;
  int lit = 0;
  for (const int y : ys) {
    for (const int x : xs) {
      const uint64_t texel = static_cast<uint64_t>(y) * static_cast<uint64_t>(w) + x;
      const uint64_t granule = (map.address + texel * map.memory_bytes_per_texel) >> 6;
      if (sink && granule != last_granule) {
        sink->push_back(granule);
        last_granule = granule;
      }
      if (p.z <= map.load(x, y).x) ++lit;
    }
  }
  if (sink) texel_trace_detail::last_granule = last_granule;
  const float visibility = static_cast<float>(lit) / 9.0f;
  return 1.0f - s.strength * (1.0f - visibility);
}

}  // namespace ontile
