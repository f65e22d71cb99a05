// Per-material cartoon settings, read from the glTF material's extras under the key "ontile"
// (documented in docs/cartoon.md), with defaults derived from the PBR material when absent so
// that any glTF renders with the cartoon pipelines.
#pragma once
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ontile {

struct ToonSettings {
  enum class Shading { Cel, MatCap, ToonEnv } shading = Shading::Cel;
  int steps = 3;
  float step_size = 0.0f;           // 0: 1 / steps
  glm::vec3 lit_color{1.0f};
  glm::vec3 shadow_color{0.5f};
  glm::vec4 border_color{0.0f, 0.0f, 0.0f, 1.0f};  // alpha 0: no border
  std::string matcap = "clay";      // clay | metal | painted | a file path
  float outline_thickness = 0.0f;   // object units; 0: 1% of the mesh's bounds diagonal
  float effective_step_size() const { return step_size > 0.0f ? step_size : 1.0f / steps; }
};

// Throws ontile::Error naming the material and the field when a value has the wrong type or
// range (steps < 1, unknown shader name, colour with the wrong number of components).
ToonSettings toon_settings(const Material& material);

}  // namespace ontile
