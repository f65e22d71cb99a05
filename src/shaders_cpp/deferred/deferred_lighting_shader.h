// The full-screen functors of the deferred lighting and tonemap steps, written once over where
// their inputs come from: input attachments in tile memory (subpassLoad, the on-tile variant)
// or the stored targets bound as textures (texelFetch, the classic variant). Both sources give
// the same quantised values, so both variants compute bit-identical results.
#pragma once
#include <array>
#include <bit>
#include <cstring>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texel_fetch_batch.h"
#include "raster/texture.h"
#include "raster/texture_batch_simd.h"
#include "shaders_cpp/deferred/gbuffer_decode_lanes.h"
#include "shaders_cpp/deferred/gbuffer_layout.h"
#include "shaders_cpp/lighting/scene_lighting.h"
#include "shaders_cpp/tone_curves.h"

namespace ontile {

// Slot k is input attachment k of the subpass.
struct InputAttachmentSource {
  static constexpr bool kLoadsWholeBatches = true;  // reads leave no trace: any order will do
  glm::vec4 load(int slot, const FragmentBatch& batch, int f) const { return batch.input(slot, f); }
  void load_all(int slot, const FragmentBatch& batch, float* const channel[4]) const { batch.inputs(slot, channel); }
};

// Slot k is texture k, read at the fragment's own pixel from the base level (every read goes
// through the texel trace, so the texture-cache model counts it).
struct TextureSource {
  static constexpr bool kLoadsWholeBatches = false;
  std::array<const Texture2D*, 4> textures{};
  glm::vec4 load(int slot, const FragmentBatch& batch, int f) const {
    return textures[slot]->fetch(0, batch.x_px(f), batch.y_px(f));
  }
  // Slots [0, count) as batch views, or false when one cannot be read a batch at a time.
  bool views(int count, Texture2D::TexelView* out) const {
    for (int k = 0; k < count; ++k) {
      if (!batch_fetch_view(*textures[k], out[k])) return false;
    }
    return true;
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
      : source_(source), layout_(layout), lighting_(lighting),
        view_{inverse_view_projection, camera_position, width_px, height_px} {}
  bool may_discard() const override { return true; }
  uint32_t varyings_read() const override { return 0; }  // pixel coordinates only
  int outputs_always_written() const override { return 1; }  // the lights, every fragment

  // Reads (depth, then the targets, fragment by fragment: the texel trace order of the classic
  // variant), then the decoding and the lights over the batch on SIMD lanes.
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    const int count = batch.fragment_count();
    alignas(64) GBufferLanes in;
    for (int q = 0; q < batch.quad_count; ++q) {
      const int x = batch.quad_x_px[q], y = batch.quad_y_px[q];
      int32_t* xs = in.x_px + q * kQuadLanes;
      int32_t* ys = in.y_px + q * kQuadLanes;
      xs[0] = xs[2] = x;
      xs[1] = xs[3] = x + 1;
      ys[0] = ys[1] = y;
      ys[2] = ys[3] = y + 1;
    }
    const uint64_t active = batch.active_mask();
    // Active fragments in front of the far plane are lit, the others discarded (keeping the
    // light target's clear colour).
    const auto split_at_far_plane = [&](const float* depth) {
      const uint64_t near = in_front_of_far_plane(depth, count);
      in.lit = active & near;
      out.discard_mask |= active & ~near;
    };
    if constexpr (Source::kLoadsWholeBatches) {
      float* const depth[4] = {in.depth, nullptr, nullptr, nullptr};
      source_.load_all(0, batch, depth);
      for (int k = 0; k < layout_.target_count(); ++k) {
        float* const target[4] = {in.targets[k][0], in.targets[k][1], in.targets[k][2], in.targets[k][3]};
        source_.load_all(1 + k, batch, target);
      }
      split_at_far_plane(in.depth);
    } else if (Texture2D::TexelView views[4]; source_.views(1 + layout_.target_count(), views)) {
      // texelFetch a batch at a time: depth of the active fragments, then the targets of those
      // in front of the far plane, traced as per-fragment fetches would be.
      alignas(64) int32_t xs[kBatchFragments] = {}, ys[kBatchFragments] = {};
      if (active == (count >= 64 ? ~uint64_t{0} : (uint64_t{1} << count) - 1)) {
        // Every fragment active (whole-tile batches): the pixels as they are.
        std::memcpy(xs, in.x_px, sizeof(int32_t) * static_cast<size_t>(count));
        std::memcpy(ys, in.y_px, sizeof(int32_t) * static_cast<size_t>(count));
      } else {
        for (uint64_t rest = active; rest != 0; rest &= rest - 1) {
          const int f = std::countr_zero(rest);
          xs[f] = in.x_px[f];
          ys[f] = in.y_px[f];
        }
      }
      const int padded = batch.padded_fragment_count();
      alignas(64) float depth[4][kBatchFragments];
      load_texels(views[0], xs, ys, padded, active, depth);
      split_at_far_plane(depth[0]);
      for (int f = 0; f < count; ++f) in.depth[f] = depth[0][f];
      uint64_t fetched[4] = {active, in.lit, in.lit, in.lit};
      for (int k = 0; k < layout_.target_count(); ++k) load_texels(views[1 + k], xs, ys, padded, in.lit, in.targets[k]);
      trace_fetches(views, 1 + layout_.target_count(), xs, ys, count, fetched);
    } else {
      for (int f = 0; f < count; ++f) {
        if (!((active >> f) & 1u)) continue;
        const float depth = source_.load(0, batch, f).x;
        if (!(depth < 1.0f)) {
          out.discard(f);
          continue;
        }
        in.depth[f] = depth;
        in.lit |= uint64_t{1} << f;
        for (int k = 0; k < layout_.target_count(); ++k) {
          const glm::vec4 value = source_.load(1 + k, batch, f);
          for (int c = 0; c < 4; ++c) in.targets[k][c][f] = value[c];
        }
      }
    }
    const uint64_t lit = in.lit;
    BrdfBatch brdf;
    alignas(64) BatchVec3 normal, world, to_view, direct = {};
    decode_gbuffer_lanes(layout_, view_, in, count, brdf, normal, world, to_view);
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
  Source source_;
  GBufferLayout layout_;
  const SceneLighting& lighting_;
  ViewReconstruction view_;
};

// Slot 0: the HDR light accumulation; output 0: fitted ACES of it, alpha 1. Runs per sample,
// so a multisampled accumulation is tonemapped before it is resolved (a resolve of tonemapped
// samples keeps edges from aliasing on bright lights).
template <class Source>
class TonemapLightShader final : public FragmentShader {
 public:
  explicit TonemapLightShader(Source source) : source_(source) {}
  bool per_sample_shading() const override { return true; }
  uint32_t varyings_read() const override { return 0; }  // pixel coordinates only
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
