// Shaders and materials as the SRP model has them: a shader is a set of named passes, each
// with a LightMode tag, render state and a factory that builds the pass's C++ functors for a
// draw; a material holds property values, keywords and a render queue. Keywords pick
// compile-time template variants (like multi_compile), so a disabled feature costs nothing.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "context/camera_matrices.h"
#include "context/property_block.h"
#include "raster/blend.h"
#include "raster/shader_interface.h"
#include "scene/scene.h"

namespace ontile {

struct PassState {
  CullMode cull = CullMode::Back;
  bool depth_test = true;
  bool depth_write = true;
  CompareOp depth_compare = CompareOp::LessEqual;  // Unity's default ZTest LEqual
  BlendState blend;
};

class RenderMaterial;

// Everything a pass factory may use to build the functors of one draw.
struct DrawContext {
  const MeshPrimitive* mesh = nullptr;  // null for full-screen (procedural) draws
  glm::dmat4 world{1.0};
  CameraMatrices camera;
  const RenderMaterial* material = nullptr;
  PropertyBlock properties;  // globals, then shader defaults, then material values
  int target_width_px = 0, target_height_px = 0;
  // Resolves a texture property (render targets become textures of their current contents).
  std::function<std::shared_ptr<const Texture2D>(const TextureBinding&)> resolve_texture;
  // The same for a shader that only fetches texels (nearest, level 0, Texture2D::texel_view):
  // a render target comes as a view of its surface in its stored format, whatever the format,
  // with no decoded copy (empty: resolve_texture).
  std::function<std::shared_ptr<const Texture2D>(const TextureBinding&)> resolve_texel_source;

  // The mesh of a mesh draw; throws ontile::Error naming the material when the pass is used
  // for a full-screen draw (blit) that has none.
  const MeshPrimitive& require_mesh() const;
  // The texture bound to `name` (null when unbound) and its sampler.
  std::shared_ptr<const Texture2D> texture(const std::string& name, SamplerDesc* sampler = nullptr) const;
  // The texture bound to `name` (null when unbound) for texel fetches (resolve_texel_source).
  std::shared_ptr<const Texture2D> texel_source(const std::string& name) const;
};

struct DrawFunctors {
  std::unique_ptr<VertexShader> vertex;
  std::unique_ptr<FragmentShader> fragment;  // null: depth-only pass
  uint32_t input_vertex_bytes = 0;
};

using PassFactory = std::function<DrawFunctors(const DrawContext&)>;

struct ShaderPass {
  std::string name;
  std::string light_mode;  // the "LightMode" tag draw_renderers selects passes by
  PassState state;
  PassFactory factory;
};

class Shader {
 public:
  explicit Shader(std::string name) : name_(std::move(name)) {}
  const std::string& name() const { return name_; }
  Shader& add_pass(ShaderPass pass);
  // Unity's UsePass: copies `pass_name` of `other` into this shader.
  Shader& use_pass(const Shader& other, const std::string& pass_name);
  const ShaderPass* find_pass(const std::string& name) const;
  const ShaderPass* find_light_mode(const std::string& light_mode) const;
  const std::vector<ShaderPass>& passes() const { return passes_; }
  PropertyBlock defaults;

 private:
  std::string name_;
  std::vector<ShaderPass> passes_;
};

// Unity render queues (Shader "Queue" tag values).
namespace render_queue {
constexpr int kBackground = 1000, kGeometry = 2000, kAlphaTest = 2450, kTransparent = 3000,
              kOverlay = 4000;
}

class RenderMaterial {
 public:
  RenderMaterial(std::string name, const Shader* shader) : name(std::move(name)), shader(shader) {}
  std::string name;
  const Shader* shader;
  PropertyBlock properties;
  std::set<std::string> keywords;
  int render_queue = render_queue::kGeometry;
  // Render-state overrides a material may carry (Unity's [_Cull], [_ZWrite], blend properties).
  std::optional<CullMode> cull;
  std::optional<bool> depth_write;
  std::optional<BlendMode> blend;

  bool has_keyword(const std::string& keyword) const { return keywords.count(keyword) != 0; }
  PassState state_for(const ShaderPass& pass) const;
};

// Calls f.template operator()<b...>() with one compile-time bool per runtime flag: the way a
// pass factory turns material keywords into a template variant of its functors.
template <bool... kFlags, class F>
auto dispatch_keywords(F&& f) {
  return f.template operator()<kFlags...>();
}
template <bool... kFlags, class F, class... Rest>
auto dispatch_keywords(F&& f, bool flag, Rest... rest) {
  return flag ? dispatch_keywords<kFlags..., true>(std::forward<F>(f), rest...)
              : dispatch_keywords<kFlags..., false>(std::forward<F>(f), rest...);
}

}  // namespace ontile
