// The shaders of the cartoon pipelines: Cel, MatCap and ToonEnv, each with the same functor
// in several passes (the MRT pass writes colour, normals and border; the naive pipeline's
// passes write one each, bit-identically), a DepthOnly pass, an inverted-hull outline pass,
// and the full-screen Sobel edge material. Materials come from glTF extras (toon_settings.h).
#pragma once
#include <map>
#include <memory>
#include <string>

#include "pipelines/kit/pipeline_api.h"
#include "shaders_cpp/toon/cube_map.h"
#include "shaders_cpp/toon/toon_outputs.h"

namespace ontile {

namespace toon {
constexpr const char* kMrt = "ToonMRT";          // colour + normals + border
constexpr const char* kColor = "ToonColor";
constexpr const char* kNormal = "ToonNormal";
constexpr const char* kBorder = "ToonBorder";
constexpr const char* kDepthOnly = "DepthOnly";
constexpr const char* kOutline = "ToonOutline";  // inverted hull, only on bordered materials
constexpr const char* kEdgesPass = "Edges";
}  // namespace toon

// PerMaterial: each material's own shader from its extras (cel, matcap, toon_env).
// Environment: every material with ToonEnv shading and hull outlines (cartoon-hull).
enum class ToonLook { PerMaterial, Environment };

class ToonShaderLibrary {
 public:
  explicit ToonShaderLibrary(NormalEncoding normal_encoding);
  ~ToonShaderLibrary();
  std::unique_ptr<RenderMaterial> make_material(const Material& gltf, ToonLook look) const;
  const RenderMaterial& edges_material() const { return *edges_material_; }

 private:
  std::shared_ptr<const Texture2D> matcap(const std::string& name) const;
  NormalEncoding encoding_;
  std::shared_ptr<const CubeMap> sky_;
  std::unique_ptr<Shader> cel_, matcap_, env_, env_outlined_, edges_;
  std::unique_ptr<RenderMaterial> edges_material_;
  mutable std::map<std::string, std::shared_ptr<const Texture2D>> matcaps_;
};

// Globals the toon functors read: the scene's main directional light (towards the light).
void set_toon_globals(RenderContext& ctx, const Scene& scene, const Camera& camera,
                      const CameraMatrices& matrices);

}  // namespace ontile
