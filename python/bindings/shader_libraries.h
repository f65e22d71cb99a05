// The shaders a Python pipeline draws with, looked up by name: each library wraps existing C++
// shaders and their functors (the Lit shader, the toon shaders and their Sobel edge material),
// makes its material for every glTF material, sets the globals its functors read, and names
// the full-screen materials it offers for blits. Python records; these C++ functors shade.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "pipelines/kit/pipeline_api.h"

namespace ontile::python {

class ShaderLibrary {
 public:
  virtual ~ShaderLibrary() = default;
  virtual std::unique_ptr<RenderMaterial> make_material(const Material& gltf) const = 0;
  // The globals the library's functors read (lights, environment), set on the context.
  virtual void set_globals(RenderContext& ctx, const FrameKit& kit) const = 0;
  // A full-screen material by name (blits); throws ontile::Error naming the valid ones.
  const RenderMaterial& material(const std::string& name) const;
  // Where nothing is drawn: the clear colour the library's C++ pipelines use.
  virtual glm::vec4 background_color() const { return glm::vec4(0.0f); }

 protected:
  std::string name_;
  std::map<std::string, const RenderMaterial*> materials_;
};

// `name` is one of shader_library_names(); `params` are its settings (toon: normals=rgb10a2|
// rgba16f). Throws ontile::Error for an unknown name or parameter.
std::unique_ptr<ShaderLibrary> make_shader_library(const std::string& name,
                                                   const std::map<std::string, std::string>& params);
std::vector<std::string> shader_library_names();

}  // namespace ontile::python
