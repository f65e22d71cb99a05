// The main light's shadow map in the `universal` pipeline: the light's orthographic camera
// fitted to what the camera sees, the world-to-shadow-map transform, and the receiver-side
// lookup (biased position, 3x3 PCF depth comparison) the forward functor runs.
#pragma once
#include <glm/glm.hpp>

#include "pipelines/kit/pipeline_api.h"
#include "raster/texture.h"
#include "scene/scene.h"

namespace ontile {

struct MainLightShadowSettings {
  int map_size_px = 2048;       // square D32F shadow map
  float depth_bias_texels = 1.0f;   // URP's default Depth Bias, in shadow-map texels
  float normal_bias_texels = 1.0f;  // URP's default Normal Bias, in shadow-map texels
  float strength = 1.0f;            // 0: no shadow, 1: full shadow
};

struct MainLightShadowSetup {
  CameraMatrices light_camera;  // orthographic; culls casters and draws the ShadowCaster pass
  glm::dmat4 world_to_shadow{1.0};  // world -> (u, v, depth), u, v in [0, 1], v = 0 at the top
  float texel_size_world = 0.0f;    // the larger side of one shadow-map texel, world units
};

// The light looks along -to_light. x and y are fitted to the corners of `receivers` (the
// bounds of what the camera sees) in light space; the depth range spans the receivers and
// everything in `scene_bounds` between them and the light, so casters outside the view still
// shadow it. `receivers` must not be empty.
MainLightShadowSetup fit_main_light_shadow(glm::vec3 to_light, const Bounds& receivers,
                                           const Bounds& scene_bounds, int map_size_px);

// What the forward functor needs to look the shadow map up.
struct ShadowLookup {
  const Texture2D* map = nullptr;  // D32F depth in .x, sampled by texel fetch
  // The map's level 0, read directly (9 texels per pixel; Texture2D::fetch's dispatch per
  // texel cost more than the comparison itself); set with the map, see set_map.
  Texture2D::TexelView texels;
  glm::mat4 world_to_shadow{1.0f};
  float depth_bias_world = 0.0f;   // receiver moved this far towards the light
  float normal_bias_world = 0.0f;  // and this far x (1 - N.L) along its normal (URP's biases)
  float strength = 1.0f;
  void set_map(const Texture2D* shadow_map) {
    map = shadow_map;
    texels = shadow_map ? shadow_map->texel_view(0) : Texture2D::TexelView{};
  }
};

// The light's visibility at a world position with unit normal n: the receiver-side form of
// URP's ApplyShadowBias (the position moved towards the light and along the normal instead of
// the caster away), projected into the map, then 3x3 PCF: the fraction of the 9 texels around
// the projected point whose depth is >= the receiver's depth (clamped at the map's edges),
// mixed with 1 by (1 - strength). Positions outside the map's depth range or uv square are lit.
float main_light_visibility(const ShadowLookup& lookup, glm::vec3 world_position, glm::vec3 n,
                            glm::vec3 to_light);

}  // namespace ontile
