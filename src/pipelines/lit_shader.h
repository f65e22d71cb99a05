// The "Lit" shader pipelines draw glTF materials with: a ForwardLit pass running the Lambert
// functor (keyword variants _BASEMAP, _ALPHATEST_ON, _EMISSION) and a DepthOnly pass; the
// mapping from glTF materials to its materials; and the lighting globals it reads.
#pragma once
#include <memory>

#include "context/render_context.h"
#include "shaders_cpp/lambert_shader.h"

namespace ontile {

namespace lit {
constexpr const char* kForwardLit = "ForwardLit";
constexpr const char* kDepthOnly = "DepthOnly";
}  // namespace lit

std::unique_ptr<Shader> make_lit_shader();
// Properties _BaseColor, _BaseMap, _EmissionColor, _EmissionMap, _Cutoff; keywords from what
// the material uses; queue Geometry / AlphaTest / Transparent; cull Off when double-sided.
std::unique_ptr<RenderMaterial> make_lit_material(const Shader& lit_shader, const Material& gltf);
// Globals _MainLightDirection (towards the light), _MainLightColor, _AmbientColor.
void set_lighting_globals(CommandBuffer& cmd, const DirectionalLighting& lighting);
void set_lighting_globals(RenderContext& ctx, const DirectionalLighting& lighting);

}  // namespace ontile
