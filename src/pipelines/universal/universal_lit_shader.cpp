// The Universal Lit shader and its materials (see universal_lit_shader.h).
#include "pipelines/universal/universal_lit_shader.h"

#include <algorithm>

#include "pipelines/lit/gltf_surface_state.h"
#include "pipelines/universal/universal_lit_functors.h"

namespace ontile {
namespace {

struct SurfaceTextures {
  UniversalSurfaceParams params;
  std::shared_ptr<const Texture2D> base_map;  // keeps the texture the params point to alive
};

SurfaceTextures surface_params(const DrawContext& ctx) {
  SurfaceTextures s;
  s.params.base_color = ctx.properties.get_vector("_BaseColor", glm::vec4(1.0f));
  s.params.alpha_cutoff = ctx.properties.get_float("_Cutoff", 0.5f);
  if (ctx.material->has_keyword("_BASEMAP")) s.base_map = ctx.texture("_BaseMap", &s.params.base_sampler);
  s.params.base_map = s.base_map.get();
  return s;
}

Bounds world_bounds(const MeshPrimitive& mesh, const glm::dmat4& world) {
  Bounds b;
  if (mesh.bounds.empty()) return b;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec4 p((i & 1) ? mesh.bounds.max.x : mesh.bounds.min.x,
                       (i & 2) ? mesh.bounds.max.y : mesh.bounds.min.y,
                       (i & 4) ? mesh.bounds.max.z : mesh.bounds.min.z, 1.0);
    b.extend(glm::vec3(world * p));
  }
  return b;
}

// Bytes per vertex the depth-style passes fetch: positions, plus what they shade with.
uint32_t vertex_bytes(const MeshPrimitive& mesh, bool normals, bool uv) {
  return 12u + (normals && !mesh.normals.empty() ? 12u : 0u) + (uv && !mesh.uv0.empty() ? 8u : 0u);
}

DrawFunctors forward_functors(const DrawContext& ctx) {
  const MeshPrimitive& mesh = ctx.require_mesh();
  DrawFunctors f;
  auto vs = std::make_unique<MeshVertexShader>(mesh, ctx.world, ctx.camera.view_projection);
  f.input_vertex_bytes = vs->input_vertex_bytes();
  f.vertex = std::move(vs);

  const PropertyBlock& props = ctx.properties;
  const SurfaceTextures surface = surface_params(ctx);
  UniversalLitParams p;
  p.surface = surface.params;
  p.metallic = props.get_float("_Metallic", 0.0f);
  p.smoothness = props.get_float("_Smoothness", 0.5f);
  p.emission = glm::vec3(props.get_vector("_EmissionColor"));
  const auto emission_map = ctx.texture("_EmissionMap", &p.emission_sampler);
  p.emission_map = emission_map.get();
  p.camera_position = glm::vec3(ctx.camera.position);

  const UniversalLights lights = read_light_globals(props);
  p.ambient = lights.ambient;
  p.main_light = lights.main;
  const int limit = std::clamp(static_cast<int>(props.get_float("_AdditionalLightsPerObject",
                                                                 kMaxAdditionalLightsPerObject)),
                               0, kMaxAdditionalLightsPerObject);
  for (int index : select_additional_lights(lights.additional, world_bounds(mesh, ctx.world), limit)) {
    p.additional_lights[p.additional_light_count++] = lights.additional[index];
  }

  const auto shadow_map = ctx.texture("_MainLightShadowmapTexture");
  if (shadow_map) {
    const glm::vec4 shadow_params = props.get_vector("_MainLightShadowParams", glm::vec4(0, 0, 1, 0));
    const auto it = props.matrices.find("_MainLightWorldToShadow");
    p.shadow.set_map(shadow_map.get());
    p.shadow.world_to_shadow = it != props.matrices.end() ? it->second : glm::mat4(1.0f);
    p.shadow.depth_bias_world = shadow_params.x;
    p.shadow.normal_bias_world = shadow_params.y;
    p.shadow.strength = shadow_params.z;
  }
  const RenderMaterial& m = *ctx.material;
  f.fragment = dispatch_keywords(
      [&]<bool kBaseMap, bool kAlphaTest, bool kEmission, bool kShadows>() -> std::unique_ptr<FragmentShader> {
        return std::make_unique<UniversalLitShader<kBaseMap, kAlphaTest, kEmission, kShadows>>(p);
      },
      p.surface.base_map != nullptr, m.has_keyword("_ALPHATEST_ON"), m.has_keyword("_EMISSION"),
      p.shadow.map != nullptr);
  return f;
}

// DepthOnly and ShadowCaster: positions only, unless alpha-tested (then the base colour's
// alpha decides what is written).
DrawFunctors depth_only_functors(const DrawContext& ctx) {
  const MeshPrimitive& mesh = ctx.require_mesh();
  const bool alpha_test = ctx.material->has_keyword("_ALPHATEST_ON");
  DrawFunctors f;
  f.vertex = std::make_unique<MeshVertexShader>(mesh, ctx.world, ctx.camera.view_projection);
  f.input_vertex_bytes = vertex_bytes(mesh, false, alpha_test);
  if (alpha_test) {
    const SurfaceTextures surface = surface_params(ctx);
    f.fragment = dispatch_keywords(
        [&]<bool kBaseMap>() -> std::unique_ptr<FragmentShader> {
          return std::make_unique<UniversalAlphaClipShader<kBaseMap>>(surface.params);
        },
        surface.params.base_map != nullptr);
  }
  return f;
}

DrawFunctors depth_normals_functors(const DrawContext& ctx) {
  const MeshPrimitive& mesh = ctx.require_mesh();
  const bool alpha_test = ctx.material->has_keyword("_ALPHATEST_ON");
  DrawFunctors f;
  f.vertex = std::make_unique<MeshVertexShader>(mesh, ctx.world, ctx.camera.view_projection);
  f.input_vertex_bytes = vertex_bytes(mesh, true, alpha_test);
  const SurfaceTextures surface = surface_params(ctx);
  const glm::mat3 world_to_view(glm::mat3(ctx.camera.view));
  f.fragment = dispatch_keywords(
      [&]<bool kAlphaTest, bool kBaseMap>() -> std::unique_ptr<FragmentShader> {
        return std::make_unique<UniversalDepthNormalsShader<kAlphaTest, kBaseMap>>(surface.params,
                                                                                  world_to_view);
      },
      alpha_test, alpha_test && surface.params.base_map != nullptr);
  return f;
}

}  // namespace

std::unique_ptr<Shader> make_universal_lit_shader() {
  auto shader = std::make_unique<Shader>("Universal Lit");
  shader->add_pass({"ForwardLit", universal_light_mode::kForward, PassState{}, forward_functors});
  shader->add_pass({"ShadowCaster", universal_light_mode::kShadowCaster, PassState{}, depth_only_functors});
  shader->add_pass({"DepthOnly", universal_light_mode::kDepthOnly, PassState{}, depth_only_functors});
  shader->add_pass({"DepthNormals", universal_light_mode::kDepthNormals, PassState{}, depth_normals_functors});
  return shader;
}

std::unique_ptr<RenderMaterial> make_universal_lit_material(const Shader& shader, const Material& gltf) {
  auto m = std::make_unique<RenderMaterial>(gltf.name, &shader);
  m->properties.vectors["_BaseColor"] = gltf.base_color_factor;
  m->properties.floats["_Cutoff"] = gltf.alpha_cutoff;
  m->properties.floats["_Metallic"] = gltf.metallic_factor;
  m->properties.floats["_Smoothness"] = 1.0f - gltf.roughness_factor;
  m->properties.vectors["_EmissionColor"] = glm::vec4(gltf.emissive_factor, 0.0f);
  if (gltf.base_color_texture.texture) {
    m->properties.textures["_BaseMap"] = {gltf.base_color_texture.texture, {}, gltf.base_color_texture.sampler};
    m->keywords.insert("_BASEMAP");
  }
  if (gltf.emissive_factor != glm::vec3(0.0f)) {
    m->keywords.insert("_EMISSION");
    if (gltf.emissive_texture.texture) {
      m->properties.textures["_EmissionMap"] = {gltf.emissive_texture.texture, {}, gltf.emissive_texture.sampler};
    }
  }
  apply_gltf_surface_state(*m, gltf);
  return m;
}

}  // namespace ontile
