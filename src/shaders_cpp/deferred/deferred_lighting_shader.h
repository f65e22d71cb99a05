// The full-screen functors of the deferred lighting and tonemap steps, written once over where
// their inputs come from: input attachments in tile memory (subpassLoad, the on-tile variant)
// or the stored targets bound as textures (texelFetch, the classic variant). Both sources give
// the same quantised values, so both variants compute bit-identical results.
#pragma once
#include <array>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
#include "shaders_cpp/deferred/gbuffer_layout.h"
#include "shaders_cpp/lighting/scene_lighting.h"
#include "shaders_cpp/tone_curves.h"

namespace ontile {

// Slot k is input attachment k of the subpass.
struct InputAttachmentSource {
  glm::vec4 load(int slot, const FragmentBatch& batch, int f) const { return batch.input(slot, f); }
};

// Slot k is texture k, read at the fragment's own pixel from the base level (every read goes
// through the texel trace, so the texture-cache model counts it).
struct TextureSource {
  std::array<const Texture2D*, 4> textures{};
  glm::vec4 load(int slot, const FragmentBatch& batch, int f) const {
    return textures[slot]->fetch(0, batch.x_px(f), batch.y_px(f));
  }
};

// Slots: 0 = depth, 1.. = the layout's G-buffer targets. Pixels at the far plane (no geometry)
// are discarded, keeping the light target's clear colour. Output 0: the lights (plus ambient
// when the layout has no light accumulation written by the G-buffer pass); with a light
// accumulation layout the pass blends it additively, so alpha is 0.
template <class Source>
class DeferredLightingShader final : public FragmentShader {
 public:
  DeferredLightingShader(Source source, const GBufferLayout& layout, const SceneLighting& lighting,
                         const glm::dmat4& inverse_view_projection, glm::dvec3 camera_position,
                         int width_px, int height_px)
      : source_(source), layout_(layout), lighting_(lighting), inverse_view_projection_(inverse_view_projection),
        camera_position_(camera_position), width_px_(width_px), height_px_(height_px) {}
  bool may_discard() const override { return true; }

  // Reads (depth, then the targets, fragment by fragment: the texel trace order of the classic
  // variant) and decoding per fragment, then the lights over the batch.
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    const int count = batch.fragment_count();
    // Zero where nothing is lit: the lighting loops run over every lane and read them.
    BrdfBatch brdf{};
    alignas(64) BatchVec3 normal = {}, world = {}, to_view = {}, direct = {};
    uint64_t lit = 0;
    for (int f = 0; f < count; ++f) {
      if (!batch.active(f)) continue;
      const float depth = source_.load(0, batch, f).x;
      if (!(depth < 1.0f)) {
        out.discard(f);
        continue;
      }
      lit |= uint64_t{1} << f;
      glm::vec4 targets[3];
      for (int k = 0; k < layout_.target_count(); ++k) targets[k] = source_.load(1 + k, batch, f);
      const DecodedGBuffer g = decode_gbuffer(layout_, targets);
      for (int c = 0; c < 3; ++c) {
        brdf.diffuse_color[c][f] = g.brdf.diffuse_color[c];
        brdf.f0[c][f] = g.brdf.f0[c];
      }
      brdf.roughness[f] = g.brdf.roughness;
      batch_set3(normal, f, g.normal);
      const glm::dvec3 w = world_position(batch.x_px(f), batch.y_px(f), depth);
      batch_set3(world, f, glm::vec3(w));
      batch_set3(to_view, f, glm::vec3(glm::normalize(camera_position_ - w)));
    }
    direct_lighting(lighting_, brdf, normal, world, to_view, batch, lit, direct);
    const bool add_ambient = !layout_.light_in_gbuffer;
    for (int c = 0; c < 3; ++c) {
      const float ambient = lighting_.ambient[c];
      for (int f = 0; f < count; ++f) {
        out.color[0][c][f] = add_ambient ? direct[c][f] + ambient * brdf.diffuse_color[c][f] : direct[c][f];
      }
    }
    const float alpha = layout_.light_in_gbuffer ? 0.0f : 1.0f;
    for (int f = 0; f < count; ++f) out.color[0][3][f] = alpha;
  }

 private:
  // The pixel centre at `depth` back through the inverse view-projection (Vulkan clip space:
  // +Y up, so the top row has NDC y = +1), in double so distant pixels keep their precision.
  glm::dvec3 world_position(int x, int y, float depth) const {
    const glm::dvec4 ndc((x + 0.5) / width_px_ * 2.0 - 1.0, 1.0 - (y + 0.5) / height_px_ * 2.0, depth, 1.0);
    const glm::dvec4 w = inverse_view_projection_ * ndc;
    return glm::dvec3(w) / w.w;
  }

  Source source_;
  GBufferLayout layout_;
  const SceneLighting& lighting_;
  glm::dmat4 inverse_view_projection_;
  glm::dvec3 camera_position_;
  int width_px_, height_px_;
};

// Slot 0: the HDR light accumulation; output 0: fitted ACES of it, alpha 1. Runs per sample,
// so a multisampled accumulation is tonemapped before it is resolved (a resolve of tonemapped
// samples keeps edges from aliasing on bright lights).
template <class Source>
class TonemapLightShader final : public FragmentShader {
 public:
  explicit TonemapLightShader(Source source) : source_(source) {}
  bool per_sample_shading() const override { return true; }
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    for (int f = 0; f < batch.fragment_count(); ++f) {
      if (!batch.active(f)) continue;
      out.set(0, f, glm::vec4(tonemap_aces_fitted(glm::vec3(source_.load(0, batch, f))), 1.0f));
    }
  }

 private:
  Source source_;
};

}  // namespace ontile
