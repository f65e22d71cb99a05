// A Lambert fragment functor: base colour (factor x sRGB texture) lit by one directional light
// plus a constant ambient term, with emissive added; alpha-mask materials discard.
#pragma once
#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "scene/scene.h"

namespace ontile {

struct DirectionalLighting {
  glm::vec3 to_light{0.0f, 1.0f, 0.0f};  // unit vector towards the light, world space
  glm::vec3 radiance{1.0f};
  glm::vec3 ambient{0.2f};
};

// The scene's strongest directional light (KHR_lights_punctual), or a default sun from the
// upper left front when it has none.
DirectionalLighting main_directional_light(const Scene& scene);

class LambertShader final : public FragmentShader {
 public:
  LambertShader(const Material& material, const DirectionalLighting& lighting);
  void shade(const QuadFragment& quad, QuadOutput& out) const override;
  bool may_discard() const override { return alpha_mask_; }

 private:
  const Material& material_;
  DirectionalLighting lighting_;
  bool alpha_mask_;
};

}  // namespace ontile
