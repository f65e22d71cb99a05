// The tone curves (see tone_curves.h).
#include "shaders_cpp/tone_curves.h"

namespace ontile {

glm::vec3 tonemap_aces_fitted(glm::vec3 c) {
  // sRGB -> ACES AP1 with the RRT's saturation folded in (ACESInputMat, rows).
  const glm::vec3 v(0.59719f * c.x + 0.35458f * c.y + 0.04823f * c.z,
                    0.07600f * c.x + 0.90834f * c.y + 0.01566f * c.z,
                    0.02840f * c.x + 0.13383f * c.y + 0.83777f * c.z);
  // RRTAndODTFit: a rational fit of the RRT + ODT tone curve.
  const glm::vec3 a = v * (v + 0.0245786f) - 0.000090537f;
  const glm::vec3 b = v * (0.983729f * v + 0.4329510f) + 0.238081f;
  const glm::vec3 f = a / b;
  // ODT_SAT -> XYZ -> D60->D65 -> sRGB (ACESOutputMat, rows), then saturate.
  const glm::vec3 out(1.60475f * f.x - 0.53108f * f.y - 0.07367f * f.z,
                      -0.10208f * f.x + 1.10813f * f.y - 0.00605f * f.z,
                      -0.00327f * f.x - 0.07276f * f.y + 1.07602f * f.z);
  return glm::clamp(out, 0.0f, 1.0f);
}

glm::vec3 tonemap_reinhard(glm::vec3 c) {
  const glm::vec3 positive = glm::max(c, glm::vec3(0.0f));
  return positive / (1.0f + positive);
}

}  // namespace ontile
