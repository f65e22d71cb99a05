// Named shader properties (Unity's MaterialPropertyBlock / shader globals): floats, vectors
// (colours are vectors), matrices and textures. Textures are either Texture2D objects or
// render targets, which are bound as textures when the draw executes.
#pragma once
#include <map>
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "context/render_target.h"
#include "raster/texture.h"

namespace ontile {

struct TextureBinding {
  std::shared_ptr<const Texture2D> texture;  // a texture, or
  RenderTargetRef render_target;             // a render target sampled as a texture
  SamplerDesc sampler;
};

struct PropertyBlock {
  std::map<std::string, float> floats;
  std::map<std::string, glm::vec4> vectors;
  std::map<std::string, glm::mat4> matrices;
  std::map<std::string, TextureBinding> textures;

  float get_float(const std::string& name, float fallback = 0.0f) const;
  glm::vec4 get_vector(const std::string& name, glm::vec4 fallback = glm::vec4(0.0f)) const;
  const TextureBinding* get_texture(const std::string& name) const;
  // Values of `over` replace those here (material over shader defaults, globals under both).
  void merge_from(const PropertyBlock& over);
};

}  // namespace ontile
