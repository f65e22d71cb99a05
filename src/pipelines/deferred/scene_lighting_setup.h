// Builds the SceneLighting the forward and deferred pipelines shade with: the scene's
// KHR_lights_punctual lights (exposure-normalised as in the universal pipeline), N generated
// point lights spread deterministically over the scene, and the screen-space light grid.
#pragma once
#include <vector>

#include "pipelines/kit/pipeline_api.h"
#include "scene/scene.h"
#include "shaders_cpp/lighting/scene_lighting.h"

namespace ontile {

// `count` point lights with finite range placed by a fixed-seed generator inside the scene's
// world bounds (kept off the floor and walls), with saturated colours; the range shrinks as
// count grows (range = 0.6 x diagonal / cbrt(count)) so each pixel sees a bounded number of
// lights, and the intensity scales with range^2 so every light is equally bright at the same fraction of its
// range. Identical for identical (bounds, count).
std::vector<PunctualLight> generate_point_lights(const Bounds& scene_bounds, int count);

// Screen rectangle of each light's range sphere (its bounding box projected through the
// view-projection; the whole screen when the box reaches behind the camera), lights whose box is
// outside the frustum skipped; directional lights and lights of infinite range cover every cell.
LightGrid build_light_grid(const std::vector<PunctualLight>& lights, const CameraMatrices& camera,
                           int width_px, int height_px);

SceneLighting make_scene_lighting(const Scene& scene, int generated_lights, const CameraMatrices& camera,
                                  int width_px, int height_px);

}  // namespace ontile
