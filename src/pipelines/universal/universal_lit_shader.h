// The universal pipeline's "Universal Lit" shader (URP's Lit/SimpleLit stand-in): passes with
// LightMode UniversalForward, ShadowCaster, DepthOnly and DepthNormals, its keyword variants
// (_BASEMAP, _ALPHATEST_ON, _EMISSION) and the mapping from glTF materials to its materials.
#pragma once
#include <memory>

#include "pipelines/kit/pipeline_api.h"

namespace ontile {

namespace universal_light_mode {
constexpr const char* kForward = "UniversalForward";
constexpr const char* kShadowCaster = "ShadowCaster";
constexpr const char* kDepthOnly = "DepthOnly";
constexpr const char* kDepthNormals = "DepthNormals";
}  // namespace universal_light_mode

// Globals the forward pass reads besides the lights (universal_lights.h):
//   _AdditionalLightsPerObject  float, 0..7: additional lights shaded per object (default 7)
//   _MainLightShadowmapTexture  the shadow map (a render target); unbound = no shadows
//   _MainLightWorldToShadow     matrix world -> (u, v, depth) of the shadow map
//   _MainLightShadowParams      (depth bias, normal bias in world units, strength, 0)
std::unique_ptr<Shader> make_universal_lit_shader();

// Properties _BaseColor, _BaseMap, _Cutoff, _Metallic, _Smoothness (1 - roughness),
// _EmissionColor, _EmissionMap. Keywords: _BASEMAP with a base colour texture, _ALPHATEST_ON for
// alpha mode MASK, _EMISSION when the emissive factor is not black (the map, when present,
// multiplies it). Queue Geometry / AlphaTest / Transparent (alpha blended, no depth write),
// cull Off when double-sided.
std::unique_ptr<RenderMaterial> make_universal_lit_material(const Shader& shader, const Material& gltf);

}  // namespace ontile
