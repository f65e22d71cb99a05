// Cel shadow banding (see cel_shader.h).
#include "shaders_cpp/toon/cel_shader.h"

#include <cmath>

namespace ontile {

float cel_shadow_factor(float n_dot_l, int steps, float step_size) {
  if (n_dot_l >= 0.0f) return 0.0f;
  const float bands = std::ceil(-n_dot_l / step_size) / static_cast<float>(steps);
  return bands < 1.0f ? bands : 1.0f;  // also maps NaN to 1
}

}  // namespace ontile
