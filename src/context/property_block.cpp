// PropertyBlock lookups (see property_block.h).
#include "context/property_block.h"

namespace ontile {

float PropertyBlock::get_float(const std::string& name, float fallback) const {
  const auto it = floats.find(name);
  return it == floats.end() ? fallback : it->second;
}

glm::vec4 PropertyBlock::get_vector(const std::string& name, glm::vec4 fallback) const {
  const auto it = vectors.find(name);
  return it == vectors.end() ? fallback : it->second;
}

const TextureBinding* PropertyBlock::get_texture(const std::string& name) const {
  const auto it = textures.find(name);
  return it == textures.end() ? nullptr : &it->second;
}

void PropertyBlock::merge_from(const PropertyBlock& over) {
  for (const auto& [k, v] : over.floats) floats[k] = v;
  for (const auto& [k, v] : over.vectors) vectors[k] = v;
  for (const auto& [k, v] : over.matrices) matrices[k] = v;
  for (const auto& [k, v] : over.textures) textures[k] = v;
}

}  // namespace ontile
