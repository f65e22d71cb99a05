// The universal pipeline's full-screen passes: a colour copy (URP's CopyColor) and the final
// post-processing pass that tonemaps the HDR colour into the RGBA8 sRGB output.
#pragma once
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "pipelines/kit/pipeline_api.h"
#include "shaders_cpp/tone_curves.h"

namespace ontile {

enum class Tonemapper {
  AcesFitted,  // Stephen Hill's fit of the ACES RRT + sRGB ODT (MJP's BakingLab, ACES.hlsl)
  Reinhard,    // c / (1 + c) per channel (Reinhard et al. 2002, eq. 3)
};

// Both tonemappers take scene-linear Rec.709 colour and return display-linear [0, 1] colour;
// the sRGB target's encoding applies the transfer function.
// "aces" or "reinhard"; anything else throws Error naming the option value.
Tonemapper parse_tonemapper(const std::string& name);

// Shader "Universal Blit": pass "Copy" writes _MainTex unchanged; pass "Tonemap" writes
// tonemap(_MainTex.rgb x _Exposure) with alpha 1 (_Tonemapper: 0 ACES fitted, 1 Reinhard).
// Both read _MainTex texel for texel (nearest, base level): blits are 1:1.
std::unique_ptr<Shader> make_universal_blit_shader();
// Blit passes are named "blit <material name>" in the frame report.
std::unique_ptr<RenderMaterial> make_copy_material(const Shader& blit_shader, const std::string& name);
std::unique_ptr<RenderMaterial> make_tonemap_material(const Shader& blit_shader, Tonemapper tonemapper,
                                                      float exposure);

}  // namespace ontile
