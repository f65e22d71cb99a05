// Shader, material and draw-context helpers (see shader.h).
#include "context/shader.h"

#include "util/error.h"

namespace ontile {

std::shared_ptr<const Texture2D> DrawContext::texture(const std::string& name,
                                                      SamplerDesc* sampler) const {
  const TextureBinding* binding = properties.get_texture(name);
  if (!binding) return nullptr;
  if (sampler) *sampler = binding->sampler;
  if (binding->texture) return binding->texture;
  return resolve_texture ? resolve_texture(*binding) : nullptr;
}

std::shared_ptr<const Texture2D> DrawContext::texel_source(const std::string& name) const {
  const TextureBinding* binding = properties.get_texture(name);
  if (!binding) return nullptr;
  if (binding->texture) return binding->texture;
  if (resolve_texel_source) return resolve_texel_source(*binding);
  return resolve_texture ? resolve_texture(*binding) : nullptr;
}

const MeshPrimitive& DrawContext::require_mesh() const {
  if (!mesh) {
    throw Error("material '" + (material ? material->name : std::string("?")) +
                "': its pass draws meshes but was used for a full-screen draw (blit)");
  }
  return *mesh;
}

Shader& Shader::add_pass(ShaderPass pass) {
  if (find_pass(pass.name)) throw Error("shader '" + name_ + "': duplicate pass '" + pass.name + "'");
  passes_.push_back(std::move(pass));
  return *this;
}

Shader& Shader::use_pass(const Shader& other, const std::string& pass_name) {
  const ShaderPass* pass = other.find_pass(pass_name);
  if (!pass) {
    throw Error("shader '" + name_ + "': UsePass of unknown pass '" + other.name() + "/" + pass_name + "'");
  }
  return add_pass(*pass);
}

const ShaderPass* Shader::find_pass(const std::string& name) const {
  for (const ShaderPass& p : passes_) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

const ShaderPass* Shader::find_light_mode(const std::string& light_mode) const {
  for (const ShaderPass& p : passes_) {
    if (p.light_mode == light_mode) return &p;
  }
  return nullptr;
}

PassState RenderMaterial::state_for(const ShaderPass& pass) const {
  PassState s = pass.state;
  if (cull) s.cull = *cull;
  if (depth_write) s.depth_write = *depth_write;
  if (blend) s.blend.mode = *blend;
  return s;
}

}  // namespace ontile
