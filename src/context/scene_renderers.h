// Turns a scene into renderers: one per mesh primitive of every instance, with its world
// bounds, a stable primitive-id range, and a material made by the pipeline's mapping.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "context/culling.h"

namespace ontile {

struct SceneRenderers {
  std::vector<std::unique_ptr<RenderMaterial>> materials;  // one per scene material, + default
  std::vector<Renderer> renderers;
};

// make_material is called once per scene material (and once for primitives without one, with
// a default-constructed Material). Primitive ids run over instances and primitives in scene
// order, so the same triangle has the same id whatever is culled.
SceneRenderers make_scene_renderers(
    const Scene& scene,
    const std::function<std::unique_ptr<RenderMaterial>(const Material&)>& make_material);

}  // namespace ontile
