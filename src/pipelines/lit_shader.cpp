// The Lit shader and its materials (see lit_shader.h).
#include "pipelines/lit_shader.h"

namespace ontile {
namespace {

DrawFunctors lit_forward_functors(const DrawContext& ctx) {
  DrawFunctors f;
  auto vs = std::make_unique<MeshVertexShader>(ctx.require_mesh(), ctx.world, ctx.camera.view_projection);
  f.input_vertex_bytes = vs->input_vertex_bytes();
  f.vertex = std::move(vs);
  LambertParams p;
  const PropertyBlock& props = ctx.properties;
  p.base_color = props.get_vector("_BaseColor", glm::vec4(1.0f));
  p.emission = glm::vec3(props.get_vector("_EmissionColor"));
  p.alpha_cutoff = props.get_float("_Cutoff", 0.5f);
  p.lighting.to_light = glm::vec3(props.get_vector("_MainLightDirection", glm::vec4(0, 1, 0, 0)));
  p.lighting.radiance = glm::vec3(props.get_vector("_MainLightColor", glm::vec4(1.0f)));
  p.lighting.ambient = glm::vec3(props.get_vector("_AmbientColor", glm::vec4(0.2f)));
  // Keywords without their texture fall back to the variant without it.
  const auto base_map = ctx.texture("_BaseMap", &p.base_sampler);
  const auto emission_map = ctx.texture("_EmissionMap", &p.emission_sampler);
  p.base_map = base_map.get();
  p.emission_map = emission_map.get();
  const RenderMaterial& m = *ctx.material;
  f.fragment = dispatch_keywords(
      [&]<bool kBaseMap, bool kAlphaTest, bool kEmissionMap>() -> std::unique_ptr<FragmentShader> {
        return std::make_unique<LambertShader<kBaseMap, kAlphaTest, kEmissionMap>>(p);
      },
      m.has_keyword("_BASEMAP") && p.base_map, m.has_keyword("_ALPHATEST_ON"),
      m.has_keyword("_EMISSION") && p.emission_map);
  return f;
}

DrawFunctors depth_only_functors(const DrawContext& ctx) {
  DrawFunctors f;
  auto vs = std::make_unique<MeshVertexShader>(ctx.require_mesh(), ctx.world, ctx.camera.view_projection);
  f.input_vertex_bytes = 12;  // positions only
  f.vertex = std::move(vs);
  return f;
}

}  // namespace

std::unique_ptr<Shader> make_lit_shader() {
  auto shader = std::make_unique<Shader>("Lit");
  shader->add_pass({"ForwardLit", lit::kForwardLit, PassState{}, lit_forward_functors});
  shader->add_pass({"DepthOnly", lit::kDepthOnly, PassState{}, depth_only_functors});
  return shader;
}

std::unique_ptr<RenderMaterial> make_lit_material(const Shader& lit_shader, const Material& gltf) {
  auto m = std::make_unique<RenderMaterial>(gltf.name, &lit_shader);
  m->properties.vectors["_BaseColor"] = gltf.base_color_factor;
  m->properties.vectors["_EmissionColor"] = glm::vec4(gltf.emissive_factor, 0.0f);
  m->properties.floats["_Cutoff"] = gltf.alpha_cutoff;
  if (gltf.base_color_texture.texture) {
    m->properties.textures["_BaseMap"] = {gltf.base_color_texture.texture, {}, gltf.base_color_texture.sampler};
    m->keywords.insert("_BASEMAP");
  }
  if (gltf.emissive_texture.texture && gltf.emissive_factor != glm::vec3(0.0f)) {
    m->properties.textures["_EmissionMap"] = {gltf.emissive_texture.texture, {}, gltf.emissive_texture.sampler};
    m->keywords.insert("_EMISSION");
  }
  if (gltf.double_sided) m->cull = CullMode::None;
  switch (gltf.alpha_mode) {
    case AlphaMode::Opaque: break;
    case AlphaMode::Mask:
      m->keywords.insert("_ALPHATEST_ON");
      m->render_queue = render_queue::kAlphaTest;
      break;
    case AlphaMode::Blend:
      m->render_queue = render_queue::kTransparent;
      m->blend = BlendMode::Alpha;
      m->depth_write = false;
      break;
  }
  return m;
}

void set_lighting_globals(CommandBuffer& cmd, const DirectionalLighting& l) {
  cmd.set_global_vector("_MainLightDirection", glm::vec4(l.to_light, 0.0f));
  cmd.set_global_vector("_MainLightColor", glm::vec4(l.radiance, 1.0f));
  cmd.set_global_vector("_AmbientColor", glm::vec4(l.ambient, 1.0f));
}

void set_lighting_globals(RenderContext& ctx, const DirectionalLighting& l) {
  CommandBuffer cmd("lighting globals");
  set_lighting_globals(cmd, l);
  ctx.execute_command_buffer(cmd);
}

}  // namespace ontile
