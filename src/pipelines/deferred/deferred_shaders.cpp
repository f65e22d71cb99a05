// The Deferred Lit shader, its materials and the full-screen steps (see deferred_shaders.h).
#include "pipelines/deferred/deferred_shaders.h"

#include "pipelines/lit/gltf_surface_state.h"
#include "shaders_cpp/deferred/deferred_lighting_shader.h"
#include "shaders_cpp/deferred/gbuffer_shader.h"
#include "shaders_cpp/full_screen.h"
#include "shaders_cpp/lighting/forward_lit_shader.h"
#include "util/error.h"

namespace ontile {

std::string deferred::gbuffer_texture(int target) { return "_GBuffer" + std::to_string(target); }

namespace {

constexpr const char* kFromTextures = "_GBUFFER_TEXTURES";

// Texture pointers stay valid after the shared_ptrs here go: the material's properties own
// scene textures, and the frame executor keeps render-target snapshots for the pass.
PbrMaterialParams material_params(const DrawContext& ctx) {
  const PropertyBlock& props = ctx.properties;
  PbrMaterialParams p;
  p.base_color = props.get_vector("_BaseColor", glm::vec4(1.0f));
  p.metallic = props.get_float("_Metallic", 1.0f);
  p.roughness = props.get_float("_Roughness", 1.0f);
  p.emission = glm::vec3(props.get_vector("_EmissionColor"));
  p.alpha_cutoff = props.get_float("_Cutoff", 0.5f);
  p.base_map = ctx.texture("_BaseMap", &p.base_sampler).get();
  p.metallic_roughness_map = ctx.texture("_MetallicRoughnessMap", &p.metallic_roughness_sampler).get();
  p.emission_map = ctx.texture("_EmissionMap", &p.emission_sampler).get();
  return p;
}

// Keywords pick the template variant; a keyword whose texture is missing falls back to the
// variant without it.
template <template <bool, bool, bool, bool> class Functor, class... Args>
std::unique_ptr<FragmentShader> lit_variant(const RenderMaterial& m, const PbrMaterialParams& p, Args&&... args) {
  return dispatch_keywords(
      [&]<bool kBase, bool kAlphaTest, bool kMr, bool kEmission>() -> std::unique_ptr<FragmentShader> {
        return std::make_unique<Functor<kBase, kAlphaTest, kMr, kEmission>>(p, args...);
      },
      m.has_keyword("_BASEMAP") && p.base_map, m.has_keyword("_ALPHATEST_ON"),
      m.has_keyword("_METALLICROUGHNESSMAP") && p.metallic_roughness_map,
      m.has_keyword("_EMISSION") && p.emission_map);
}

// The lighting pass only fetches texels (TextureSource), so a G-buffer target comes as a view
// of its surface in its stored format (texel_source): no decoded float copy of a packed
// format such as RGB10A2 normals, which cost a zero-filled 32 MiB vector and a decode per
// 1080p frame; the values (decode_pixel) and the texel addresses are the copy's.
const Texture2D* required_texture(const DrawContext& ctx, const std::string& name) {
  const std::shared_ptr<const Texture2D> t = ctx.texel_source(name);
  if (!t) throw Error("deferred lighting: texture '" + name + "' is not bound (the classic variant binds it after the G-buffer pass)");
  return t.get();  // the frame executor keeps render-target snapshots alive for the pass
}

PassState full_screen_state(bool additive) {
  PassState s;
  s.cull = CullMode::None;
  s.depth_test = false;
  s.depth_write = false;
  if (additive) s.blend.mode = BlendMode::Additive;
  return s;
}

}  // namespace

DeferredShaderLibrary::DeferredShaderLibrary(const GBufferLayout& layout, const SceneLighting& lighting,
                                             const CameraMatrices& camera, int width_px, int height_px)
    : layout_(layout), lighting_(lighting), camera_(camera), width_px_(width_px), height_px_(height_px) {
  lit_shader_ = std::make_unique<Shader>("Deferred Lit");
  auto mesh_functors = [](const DrawContext& ctx, DrawFunctors& f) {
    auto vs = std::make_unique<MeshVertexShader>(ctx.require_mesh(), ctx.world, ctx.camera.view_projection);
    f.input_vertex_bytes = vs->input_vertex_bytes();
    f.vertex = std::move(vs);
  };
  lit_shader_->add_pass({"GBuffer", deferred::kGBuffer, PassState{}, [this, mesh_functors](const DrawContext& ctx) {
                           DrawFunctors f;
                           mesh_functors(ctx, f);
                           const PbrMaterialParams p = material_params(ctx);
                           f.fragment = lit_variant<GBufferShader>(*ctx.material, p, layout_, lighting_.ambient);
                           return f;
                         }});
  lit_shader_->add_pass({"ForwardLit", deferred::kForwardLit, PassState{}, [this, mesh_functors](const DrawContext& ctx) {
                           DrawFunctors f;
                           mesh_functors(ctx, f);
                           const PbrMaterialParams p = material_params(ctx);
                           f.fragment = lit_variant<ForwardLitShader>(*ctx.material, p, lighting_,
                                                                     glm::vec3(ctx.camera.position));
                           return f;
                         }});

  full_screen_shader_ = std::make_unique<Shader>("Deferred Full Screen");
  const glm::dmat4 inverse_vp = glm::inverse(camera_.view_projection);
  full_screen_shader_->add_pass(
      {deferred::kLightingPass, "", full_screen_state(layout_.light_in_gbuffer), [this, inverse_vp](const DrawContext& ctx) {
         DrawFunctors f;
         f.vertex = std::make_unique<FullScreenVertexShader>();
         if (ctx.material->has_keyword(kFromTextures)) {
           TextureSource source;
           source.textures[0] = required_texture(ctx, deferred::kDepthTexture);
           for (int k = 0; k < layout_.target_count(); ++k) {
             source.textures[1 + k] = required_texture(ctx, deferred::gbuffer_texture(k));
           }
           f.fragment = std::make_unique<DeferredLightingShader<TextureSource>>(
               source, layout_, lighting_, inverse_vp, camera_.position, width_px_, height_px_);
         } else {
           f.fragment = std::make_unique<DeferredLightingShader<InputAttachmentSource>>(
               InputAttachmentSource{}, layout_, lighting_, inverse_vp, camera_.position, width_px_, height_px_);
         }
         return f;
       }});
  full_screen_shader_->add_pass({deferred::kTonemapPass, "", full_screen_state(false), [](const DrawContext& ctx) {
                                   DrawFunctors f;
                                   f.vertex = std::make_unique<FullScreenVertexShader>();
                                   if (ctx.material->has_keyword(kFromTextures)) {
                                     TextureSource source;
                                     source.textures[0] = required_texture(ctx, deferred::kLightTexture);
                                     f.fragment = std::make_unique<TonemapLightShader<TextureSource>>(source);
                                   } else {
                                     f.fragment = std::make_unique<TonemapLightShader<InputAttachmentSource>>(InputAttachmentSource{});
                                   }
                                   return f;
                                 }});
  auto full_screen_material = [&](const char* name, bool from_textures) {
    auto m = std::make_unique<RenderMaterial>(name, full_screen_shader_.get());
    if (from_textures) m->keywords.insert(kFromTextures);
    return m;
  };
  lighting_from_inputs_ = full_screen_material("deferred lighting (input attachments)", false);
  lighting_from_textures_ = full_screen_material("deferred lighting (textures)", true);
  tonemap_from_inputs_ = full_screen_material("tonemap (input attachment)", false);
  tonemap_from_textures_ = full_screen_material("tonemap (texture)", true);
}

std::unique_ptr<RenderMaterial> DeferredShaderLibrary::make_material(const Material& gltf) const {
  auto m = std::make_unique<RenderMaterial>(gltf.name, lit_shader_.get());
  m->properties.vectors["_BaseColor"] = gltf.base_color_factor;
  m->properties.floats["_Metallic"] = gltf.metallic_factor;
  m->properties.floats["_Roughness"] = gltf.roughness_factor;
  m->properties.vectors["_EmissionColor"] = glm::vec4(gltf.emissive_factor, 0.0f);
  m->properties.floats["_Cutoff"] = gltf.alpha_cutoff;
  auto bind = [&](const TextureSlot& slot, const char* property, const char* keyword) {
    if (!slot.texture) return;
    m->properties.textures[property] = {slot.texture, {}, slot.sampler};
    m->keywords.insert(keyword);
  };
  bind(gltf.base_color_texture, "_BaseMap", "_BASEMAP");
  bind(gltf.metallic_roughness_texture, "_MetallicRoughnessMap", "_METALLICROUGHNESSMAP");
  if (gltf.emissive_factor != glm::vec3(0.0f)) bind(gltf.emissive_texture, "_EmissionMap", "_EMISSION");
  apply_gltf_surface_state(*m, gltf);
  return m;
}

}  // namespace ontile
