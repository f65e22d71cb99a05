// The Lit shader and its materials (see lit_shader.h).
#include "pipelines/lit/lit_shader.h"

#include "pipelines/lit/gltf_surface_state.h"
#include "shaders_cpp/batch_helpers.h"

namespace ontile {
namespace {

// Runs the Lambert functor (output 0), then writes the extra outputs of LitShaderOptions for
// every fragment (the core stores only those it kept). The normal is computed exactly as
// LambertShader computes the one it lights.
class LitExtraOutputs final : public FragmentShader {
 public:
  LitExtraOutputs(std::unique_ptr<FragmentShader> lit, std::optional<NormalStorage> normal_output,
                  bool primitive_id_output)
      : lit_(std::move(lit)), normal_output_(normal_output), primitive_id_output_(primitive_id_output) {}
  bool may_discard() const override { return lit_->may_discard(); }

  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    lit_->shade_batch(batch, out);
    const int count = batch.fragment_count();
    int k = 1;
    if (normal_output_) {
      alignas(64) BatchVec3 normal;
      batch_unit_normals(batch, MeshVertexShader::kNormal, count, normal);
      for (int f = 0; f < count; ++f) out.set(k, f, encode_normal(*normal_output_, batch_get3(normal, f)));
      ++k;
    }
    if (primitive_id_output_) {
      const glm::vec4 id(static_cast<float>(batch.primitive_id), 0.0f, 0.0f, 1.0f);
      for (int f = 0; f < count; ++f) out.set(k, f, id);
    }
  }

 private:
  std::unique_ptr<FragmentShader> lit_;
  std::optional<NormalStorage> normal_output_;
  bool primitive_id_output_;
};

void apply_filtering(TextureFiltering filtering, SamplerDesc& sampler) {
  if (filtering == TextureFiltering::Gltf) return;
  sampler.min_filter = FilterMode::Linear;
  sampler.mag_filter = FilterMode::Linear;
  sampler.mipmap_mode = filtering == TextureFiltering::Bilinear ? MipmapMode::Nearest : MipmapMode::Linear;
}

DrawFunctors lit_forward_functors(const DrawContext& ctx, const LitShaderOptions& options) {
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
  apply_filtering(options.filtering, p.base_sampler);
  apply_filtering(options.filtering, p.emission_sampler);
  p.base_map = base_map.get();
  p.emission_map = emission_map.get();
  const RenderMaterial& m = *ctx.material;
  f.fragment = dispatch_keywords(
      [&]<bool kBaseMap, bool kAlphaTest, bool kEmissionMap>() -> std::unique_ptr<FragmentShader> {
        return std::make_unique<LambertShader<kBaseMap, kAlphaTest, kEmissionMap>>(p);
      },
      m.has_keyword("_BASEMAP") && p.base_map, m.has_keyword("_ALPHATEST_ON"),
      m.has_keyword("_EMISSION") && p.emission_map);
  if (options.normal_output || options.primitive_id_output) {
    f.fragment = std::make_unique<LitExtraOutputs>(std::move(f.fragment), options.normal_output,
                                                   options.primitive_id_output);
  }
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

std::unique_ptr<Shader> make_lit_shader(const LitShaderOptions& options) {
  auto shader = std::make_unique<Shader>("Lit");
  PassState state;
  state.depth_compare = options.depth_compare;
  shader->add_pass({"ForwardLit", lit::kForwardLit, state,
                    [options](const DrawContext& ctx) { return lit_forward_functors(ctx, options); }});
  shader->add_pass({"DepthOnly", lit::kDepthOnly, state, depth_only_functors});
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
  apply_gltf_surface_state(*m, gltf);
  return m;
}

PropertyBlock lighting_globals(const DirectionalLighting& l) {
  PropertyBlock globals;
  globals.vectors["_MainLightDirection"] = glm::vec4(l.to_light, 0.0f);
  globals.vectors["_MainLightColor"] = glm::vec4(l.radiance, 1.0f);
  globals.vectors["_AmbientColor"] = glm::vec4(l.ambient, 1.0f);
  return globals;
}

void set_lighting_globals(CommandBuffer& cmd, const DirectionalLighting& l) {
  for (const auto& [name, value] : lighting_globals(l).vectors) cmd.set_global_vector(name, value);
}

void set_lighting_globals(RenderContext& ctx, const DirectionalLighting& l) {
  CommandBuffer cmd("lighting globals");
  set_lighting_globals(cmd, l);
  ctx.execute_command_buffer(cmd);
}

}  // namespace ontile
