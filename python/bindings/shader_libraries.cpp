// The shader libraries Python pipelines look up by name (see shader_libraries.h).
#include "shader_libraries.h"

#include "pipelines/cartoon/toon_shaders.h"
#include "pipelines/lit/lit_shader.h"
#include "util/error.h"

namespace ontile::python {
namespace {

// lit: the Lit shader of lambert, forward and graph-example (passes ForwardLit, DepthOnly).
class LitLibrary final : public ShaderLibrary {
 public:
  LitLibrary() : shader_(make_lit_shader()) { name_ = "lit"; }
  std::unique_ptr<RenderMaterial> make_material(const Material& gltf) const override {
    return make_lit_material(*shader_, gltf);
  }
  void set_globals(RenderContext& ctx, const FrameKit& kit) const override {
    set_lighting_globals(ctx, main_directional_light(kit.scene()));
  }
  glm::vec4 background_color() const override { return lit::kBackgroundColor; }

 private:
  std::unique_ptr<Shader> shader_;
};

// toon / toon-env: the cartoon pipelines' shaders (passes ToonMRT, ToonColor, ToonNormal,
// ToonBorder, DepthOnly, ToonOutline) and the Sobel edge blit ("edges", pass Edges).
class ToonLibrary final : public ShaderLibrary {
 public:
  ToonLibrary(const std::string& name, ToonLook look, NormalEncoding encoding) : library_(encoding), look_(look) {
    name_ = name;
    materials_["edges"] = &library_.edges_material();
  }
  std::unique_ptr<RenderMaterial> make_material(const Material& gltf) const override {
    return library_.make_material(gltf, look_);
  }
  void set_globals(RenderContext& ctx, const FrameKit& kit) const override {
    set_toon_globals(ctx, kit.scene(), kit.camera(), kit.matrices());
  }

 private:
  ToonShaderLibrary library_;
  ToonLook look_;
};

std::string take(std::map<std::string, std::string>& params, const std::string& key, const std::string& fallback) {
  const auto it = params.find(key);
  if (it == params.end()) return fallback;
  std::string value = it->second;
  params.erase(it);
  return value;
}

}  // namespace

const RenderMaterial& ShaderLibrary::material(const std::string& name) const {
  const auto it = materials_.find(name);
  if (it != materials_.end()) return *it->second;
  std::string valid;
  for (const auto& [n, m] : materials_) {
    if (!valid.empty()) valid += ", ";
    valid += n;
  }
  throw Error("shader library '" + name_ + "' has no material '" + name + "' (valid: " +
              (valid.empty() ? "none" : valid) + ")");
}

std::vector<std::string> shader_library_names() { return {"lit", "toon", "toon-env"}; }

std::unique_ptr<ShaderLibrary> make_shader_library(const std::string& name,
                                                   const std::map<std::string, std::string>& given) {
  std::map<std::string, std::string> params = given;
  std::unique_ptr<ShaderLibrary> library;
  if (name == "lit") {
    library = std::make_unique<LitLibrary>();
  } else if (name == "toon" || name == "toon-env") {
    // The cartoon pipelines' --set normals: the normal buffer's encoding (toon_shaders.h).
    const std::string normals = take(params, "normals", "rgb10a2");
    if (normals != "rgb10a2" && normals != "rgba16f") {
      throw Error("shader library '" + name + "': normals='" + normals + "', expected rgb10a2 or rgba16f");
    }
    const NormalEncoding encoding = normals == "rgba16f" ? NormalEncoding::Float : NormalEncoding::Unorm;
    library = std::make_unique<ToonLibrary>(name, name == "toon" ? ToonLook::PerMaterial : ToonLook::Environment,
                                            encoding);
  } else {
    std::string valid;
    for (const auto& n : shader_library_names()) {
      if (!valid.empty()) valid += ", ";
      valid += n;
    }
    throw Error("unknown shader library '" + name + "' (valid: " + valid + ")");
  }
  if (!params.empty()) throw Error("shader library '" + name + "' has no parameter '" + params.begin()->first + "'");
  return library;
}

}  // namespace ontile::python
