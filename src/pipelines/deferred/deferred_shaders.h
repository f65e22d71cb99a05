// The shaders of the forward and deferred pipelines: a PBR "Deferred Lit" shader (G-buffer and
// forward passes, glTF materials mapped onto it) and the full-screen lighting and tonemap
// steps, each reading either input attachments (on tile) or stored targets bound as textures.
#pragma once
#include <memory>
#include <string>

#include "pipelines/kit/pipeline_api.h"
#include "shaders_cpp/deferred/gbuffer_layout.h"
#include "shaders_cpp/lighting/scene_lighting.h"

namespace ontile {

namespace deferred {
constexpr const char* kGBuffer = "GBuffer";        // LightMode of the G-buffer pass
constexpr const char* kForwardLit = "ForwardLit";  // LightMode of forward shading
constexpr const char* kLightingPass = "DeferredLighting";
constexpr const char* kTonemapPass = "TonemapLight";
// Textures the classic variant binds (globals): depth, G-buffer target k, light accumulation.
constexpr const char* kDepthTexture = "_GBufferDepth";
constexpr const char* kLightTexture = "_LightAccumulation";
std::string gbuffer_texture(int target);
}  // namespace deferred

// Everything the passes' factories need; it must outlive RenderContext::submit().
class DeferredShaderLibrary {
 public:
  DeferredShaderLibrary(const GBufferLayout& layout, const SceneLighting& lighting, const CameraMatrices& camera,
                        int width_px, int height_px);
  DeferredShaderLibrary(const DeferredShaderLibrary&) = delete;
  DeferredShaderLibrary& operator=(const DeferredShaderLibrary&) = delete;

  // _BaseColor/_BaseMap, _Metallic/_Roughness/_MetallicRoughnessMap, _EmissionColor/_EmissionMap,
  // _Cutoff; keywords _BASEMAP, _METALLICROUGHNESSMAP, _EMISSION, _ALPHATEST_ON; queue Geometry,
  // AlphaTest or Transparent (alpha blended, no depth write); cull Off when double-sided.
  std::unique_ptr<RenderMaterial> make_material(const Material& gltf) const;
  // Full-screen materials (keyword _GBUFFER_TEXTURES selects the texture-reading variant).
  const RenderMaterial& lighting_material(bool from_textures) const {
    return from_textures ? *lighting_from_textures_ : *lighting_from_inputs_;
  }
  const RenderMaterial& tonemap_material(bool from_textures) const {
    return from_textures ? *tonemap_from_textures_ : *tonemap_from_inputs_;
  }
  const GBufferLayout& layout() const { return layout_; }

 private:
  GBufferLayout layout_;
  const SceneLighting& lighting_;
  CameraMatrices camera_;
  int width_px_, height_px_;
  std::unique_ptr<Shader> lit_shader_, full_screen_shader_;
  std::unique_ptr<RenderMaterial> lighting_from_inputs_, lighting_from_textures_;
  std::unique_ptr<RenderMaterial> tonemap_from_inputs_, tonemap_from_textures_;
};

}  // namespace ontile
