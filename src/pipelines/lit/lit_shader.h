// The "Lit" shader pipelines draw glTF materials with: a ForwardLit pass running the Lambert
// functor (keyword variants _BASEMAP, _ALPHATEST_ON, _EMISSION) and a DepthOnly pass; the
// mapping from glTF materials to its materials; and the lighting globals it reads.
#pragma once
#include <memory>
#include <optional>

#include "pipelines/kit/pipeline_api.h"
#include "shaders_cpp/lambert_shader.h"
#include "shaders_cpp/normal_encoding.h"

namespace ontile {

namespace lit {
constexpr const char* kForwardLit = "ForwardLit";
constexpr const char* kDepthOnly = "DepthOnly";
// The clear colour of the lit pipelines (lambert, forward, deferred) where no surface is drawn;
// the reference renderer shows it for rays that hit nothing.
constexpr glm::vec4 kBackgroundColor(0.05f, 0.05f, 0.08f, 1.0f);
}  // namespace lit

// Texture filtering of the Lit materials' maps: the glTF samplers as authored, or every map
// with linear min/mag filtering and the mip mode forced: bilinear = linear within the nearest
// mip level (Vulkan VK_SAMPLER_MIPMAP_MODE_NEAREST), trilinear = blend of the two nearest levels.
enum class TextureFiltering { Gltf, Bilinear, Trilinear };

struct LitShaderOptions {
  // Compare op of both passes: LessEqual for standard depth, GreaterEqual for reversed Z.
  CompareOp depth_compare = CompareOp::LessEqual;
  TextureFiltering filtering = TextureFiltering::Gltf;
  // Extra ForwardLit outputs after the colour (output 0), in this order: the shading normal
  // (unit, flipped on back faces, as the Lambert functor lights with) encoded for the storage,
  // then the primitive id as float in R (exact below 2^24).
  std::optional<NormalStorage> normal_output;
  bool primitive_id_output = false;
};

std::unique_ptr<Shader> make_lit_shader(const LitShaderOptions& options = {});
// Properties _BaseColor, _BaseMap, _EmissionColor, _EmissionMap, _Cutoff; keywords from what
// the material uses; queue Geometry / AlphaTest / Transparent; cull Off when double-sided.
std::unique_ptr<RenderMaterial> make_lit_material(const Shader& lit_shader, const Material& gltf);
// Globals _MainLightDirection (towards the light), _MainLightColor, _AmbientColor.
// The globals below as a property block (what a draw's DrawContext sees after them).
PropertyBlock lighting_globals(const DirectionalLighting& lighting);
void set_lighting_globals(CommandBuffer& cmd, const DirectionalLighting& lighting);
void set_lighting_globals(RenderContext& ctx, const DirectionalLighting& lighting);

}  // namespace ontile
