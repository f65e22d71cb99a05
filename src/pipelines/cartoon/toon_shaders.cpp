// Toon shaders and materials (see toon_shaders.h).
#include "pipelines/cartoon/toon_shaders.h"

#include <map>
#include <mutex>

#include "pipelines/cartoon/toon_settings.h"
#include "pipelines/lit/lit_shader.h"
#include "shaders_cpp/full_screen.h"
#include "shaders_cpp/lambert_shader.h"
#include "shaders_cpp/toon/cel_shader.h"
#include "shaders_cpp/toon/matcap_generator.h"
#include "shaders_cpp/toon/matcap_shader.h"
#include "shaders_cpp/toon/outline_shader.h"
#include "shaders_cpp/toon/sobel_edge_shader.h"
#include "shaders_cpp/toon/toon_env_shader.h"
#include "shaders_cpp/toon/toon_vertex_shader.h"

namespace ontile {
namespace {

constexpr int kSkyFacePx = 128;

// The generated sky and MatCaps are pure functions of their parameters and immutable, but
// generating them costs more than a frame (the demo's three 512x512 MatCaps took ~380 ms of
// every cartoon frame), so all frames of a process share one copy of each. Texture ids and
// addresses do not reach the reports: the texture-cache model places textures per frame in
// first-use order.
std::shared_ptr<const CubeMap> shared_gradient_sky() {
  static const std::shared_ptr<const CubeMap> sky = generate_gradient_sky(kSkyFacePx);
  return sky;
}

std::shared_ptr<const Texture2D> shared_generated_matcap(MatCapStyle style) {
  static std::mutex mutex;
  static std::map<MatCapStyle, std::shared_ptr<const Texture2D>> generated;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& slot = generated[style];
  if (!slot) slot = generate_matcap(style);
  return slot;
}

ToonOutputParams output_params(const DrawContext& ctx, NormalEncoding encoding) {
  return {encoding, ctx.properties.get_vector("_BorderColor")};
}

std::unique_ptr<VertexShader> toon_vertices(const DrawContext& ctx, DrawFunctors& f) {
  auto vs = std::make_unique<ToonVertexShader>(ctx.require_mesh(), ctx.world, ctx.camera.view,
                                               ctx.camera.view_projection);
  f.input_vertex_bytes = vs->input_vertex_bytes();
  return vs;
}

template <uint32_t kOutputs>
DrawFunctors cel_functors(const DrawContext& ctx, NormalEncoding encoding) {
  DrawFunctors f;
  f.vertex = toon_vertices(ctx, f);
  CelParams p;
  p.to_light = glm::vec3(ctx.properties.get_vector("_MainLightDirection", glm::vec4(0, 1, 0, 0)));
  p.steps = static_cast<int>(ctx.properties.get_float("_Steps", 1.0f));
  p.step_size = ctx.properties.get_float("_StepSize", 0.0f);
  p.lit_color = ctx.properties.get_vector("_LitColor", glm::vec4(1.0f));
  p.shadow_color = ctx.properties.get_vector("_ShadowColor", glm::vec4(0.5f));
  const auto base = ctx.texture("_BaseMap", &p.lit_sampler);
  p.shadow_sampler = p.lit_sampler;
  p.lit_map = p.shadow_map = base.get();
  p.outputs = output_params(ctx, encoding);
  const bool textured = base && ctx.material->has_keyword("_BASEMAP");
  f.fragment = textured ? std::unique_ptr<FragmentShader>(std::make_unique<CelShader<kOutputs, true>>(p))
                        : std::unique_ptr<FragmentShader>(std::make_unique<CelShader<kOutputs, false>>(p));
  return f;
}

template <uint32_t kOutputs>
DrawFunctors matcap_functors(const DrawContext& ctx, NormalEncoding encoding) {
  DrawFunctors f;
  f.vertex = toon_vertices(ctx, f);
  MatCapParams p;
  const auto matcap = ctx.texture("_MatCap");
  const auto base = ctx.texture("_BaseMap", &p.base_sampler);
  const auto normal = ctx.texture("_NormalMap", &p.normal_sampler);
  p.matcap = matcap.get();
  p.base_color = ctx.properties.get_vector("_BaseColor", glm::vec4(1.0f));
  p.base_map = base.get();
  p.normal_map = normal.get();
  p.normal_scale = ctx.properties.get_float("_NormalScale", 1.0f);
  p.world_to_view = glm::mat3(ctx.camera.view);
  p.outputs = output_params(ctx, encoding);
  f.fragment = dispatch_keywords(
      [&]<bool kBaseMap, bool kNormalMap>() -> std::unique_ptr<FragmentShader> {
        return std::make_unique<MatCapShader<kOutputs, kBaseMap, kNormalMap>>(p);
      },
      base && ctx.material->has_keyword("_BASEMAP"), normal && ctx.material->has_keyword("_NORMALMAP"));
  return f;
}

template <uint32_t kOutputs>
DrawFunctors env_functors(const DrawContext& ctx, NormalEncoding encoding, const CubeMap* sky) {
  DrawFunctors f;
  f.vertex = toon_vertices(ctx, f);
  ToonEnvParams p;
  const auto base = ctx.texture("_BaseMap", &p.base_sampler);
  p.environment = sky;
  p.base_color = ctx.properties.get_vector("_BaseColor", glm::vec4(1.0f));
  p.base_map = ctx.material->has_keyword("_BASEMAP") ? base.get() : nullptr;
  p.outputs = output_params(ctx, encoding);
  f.fragment = dispatch_keywords(
      [&]<bool kCameraBased>() -> std::unique_ptr<FragmentShader> {
        return std::make_unique<ToonEnvShader<kOutputs, kCameraBased>>(p);
      },
      ctx.material->has_keyword("CAMERA_BASED_ENVIRONMENT"));
  return f;
}

DrawFunctors outline_functors(const DrawContext& ctx, NormalEncoding encoding) {
  DrawFunctors f;
  OutlineParams p;
  p.mode = OutlineMode::ObjectSpace;
  const MeshPrimitive& mesh = ctx.require_mesh();
  const float thickness = ctx.properties.get_float("_OutlineThickness", 0.0f);
  // Default: 1% of the mesh's size, so any model gets a visible but thin hull.
  p.thickness_object_units = thickness > 0.0f ? thickness : 0.01f * glm::length(mesh.bounds.max - mesh.bounds.min);
  auto vs = std::make_unique<OutlineVertexShader>(mesh, ctx.world, ctx.camera.view_projection, p);
  f.input_vertex_bytes = vs->input_vertex_bytes();
  f.vertex = std::move(vs);
  const glm::vec4 border = ctx.properties.get_vector("_BorderColor");
  f.fragment = std::make_unique<OutlineColorShader<ToonOutput::kColor>>(glm::vec4(glm::vec3(border), 1.0f), encoding);
  return f;
}

DrawFunctors depth_functors(const DrawContext& ctx) {
  DrawFunctors f;
  f.vertex = toon_vertices(ctx, f);
  return f;
}

// One shader with the same functor family in every output pass.
template <class Make>
std::unique_ptr<Shader> toon_shader(const char* name, Make make) {
  auto s = std::make_unique<Shader>(name);
  s->add_pass({"MRT", toon::kMrt, PassState{}, make.template operator()<ToonOutput::kAll>()});
  s->add_pass({"Color", toon::kColor, PassState{}, make.template operator()<ToonOutput::kColor>()});
  s->add_pass({"Normal", toon::kNormal, PassState{}, make.template operator()<ToonOutput::kNormal>()});
  s->add_pass({"Border", toon::kBorder, PassState{}, make.template operator()<ToonOutput::kBorder>()});
  s->add_pass({"DepthOnly", toon::kDepthOnly, PassState{}, depth_functors});
  return s;
}

}  // namespace

ToonShaderLibrary::ToonShaderLibrary(NormalEncoding encoding)
    : encoding_(encoding), sky_(shared_gradient_sky()) {
  const NormalEncoding e = encoding;
  const CubeMap* sky = sky_.get();
  cel_ = toon_shader("ToonCel", [e]<uint32_t k>() -> PassFactory {
    return [e](const DrawContext& c) { return cel_functors<k>(c, e); };
  });
  matcap_ = toon_shader("ToonMatCap", [e]<uint32_t k>() -> PassFactory {
    return [e](const DrawContext& c) { return matcap_functors<k>(c, e); };
  });
  auto make_env = [e, sky]<uint32_t k>() -> PassFactory {
    return [e, sky](const DrawContext& c) { return env_functors<k>(c, e, sky); };
  };
  env_ = toon_shader("ToonEnv", make_env);
  env_outlined_ = toon_shader("ToonEnvOutlined", make_env);
  PassState hull;
  hull.cull = CullMode::Front;  // the inverted hull: only its back faces, behind the object
  env_outlined_->add_pass({"Outline", toon::kOutline, hull,
                           [e](const DrawContext& c) { return outline_functors(c, e); }});

  edges_ = std::make_unique<Shader>("ToonEdges");
  PassState full_screen;
  full_screen.cull = CullMode::None;
  full_screen.depth_test = false;
  full_screen.depth_write = false;
  edges_->add_pass({"Edges", "", full_screen, [e](const DrawContext& c) {
                      DrawFunctors f;
                      f.vertex = std::make_unique<FullScreenVertexShader>();
                      SobelEdgeParams p;
                      p.depth_linearization = DepthLinearization::from_projection(c.camera.projection);
                      p.view_ray_scale = view_ray_scale(c.camera.projection);
                      p.normal_encoding = e;
                      const auto color = c.texel_source("_MainTex");
                      const auto depth = c.texel_source("_DepthTex");
                      const auto normal = c.texel_source("_NormalTex");
                      const auto border = c.texel_source("_BorderTex");
                      p.color = color.get();
                      p.depth = depth.get();
                      p.normal = normal.get();
                      p.border = border.get();
                      f.fragment = std::make_unique<SobelEdgeShader>(p);
                      return f;
                    }});
  edges_material_ = std::make_unique<RenderMaterial>("toon edges", edges_.get());
}

ToonShaderLibrary::~ToonShaderLibrary() = default;

std::shared_ptr<const Texture2D> ToonShaderLibrary::matcap(const std::string& name) const {
  auto& slot = matcaps_[name];
  if (!slot) {
    slot = (name == "clay" || name == "metal" || name == "painted") ? shared_generated_matcap(parse_matcap_style(name))
                                                                    : load_matcap(name);
  }
  return slot;
}

std::unique_ptr<RenderMaterial> ToonShaderLibrary::make_material(const Material& gltf, ToonLook look) const {
  const ToonSettings s = toon_settings(gltf);
  const Shader* shader = nullptr;
  if (look == ToonLook::Environment) {
    shader = s.border_color.w > 0.0f ? env_outlined_.get() : env_.get();
  } else {
    switch (s.shading) {
      case ToonSettings::Shading::Cel: shader = cel_.get(); break;
      case ToonSettings::Shading::MatCap: shader = matcap_.get(); break;
      case ToonSettings::Shading::ToonEnv: shader = env_.get(); break;
    }
  }
  auto m = std::make_unique<RenderMaterial>(gltf.name, shader);
  PropertyBlock& p = m->properties;
  p.vectors["_BaseColor"] = gltf.base_color_factor;
  p.vectors["_LitColor"] = glm::vec4(s.lit_color, 1.0f);
  p.vectors["_ShadowColor"] = glm::vec4(s.shadow_color, 1.0f);
  p.vectors["_BorderColor"] = s.border_color;
  p.floats["_Steps"] = static_cast<float>(s.steps);
  p.floats["_StepSize"] = s.effective_step_size();
  p.floats["_OutlineThickness"] = s.outline_thickness;
  p.floats["_NormalScale"] = gltf.normal_scale;
  if (s.shading == ToonSettings::Shading::MatCap) {
    p.textures["_MatCap"] = TextureBinding{matcap(s.matcap), {}, {}};
  }
  if (gltf.base_color_texture.texture) {
    p.textures["_BaseMap"] = {gltf.base_color_texture.texture, {}, gltf.base_color_texture.sampler};
    m->keywords.insert("_BASEMAP");
  }
  if (gltf.normal_texture.texture && gltf.normal_texture.texture) {
    p.textures["_NormalMap"] = {gltf.normal_texture.texture, {}, gltf.normal_texture.sampler};
    m->keywords.insert("_NORMALMAP");
  }
  if (gltf.double_sided) m->cull = CullMode::None;
  return m;
}

void set_toon_globals(RenderContext& ctx, const Scene& scene, const Camera&, const CameraMatrices&) {
  set_lighting_globals(ctx, main_directional_light(scene));
}

}  // namespace ontile
