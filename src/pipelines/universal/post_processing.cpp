// Colour copy and tonemapping passes (see post_processing.h).
#include "pipelines/universal/post_processing.h"

#include <algorithm>

#include "raster/texture_batch_simd.h"
#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/full_screen.h"
#include "shaders_cpp/tone_curves_batch.h"
#include "util/error.h"

namespace ontile {
namespace {

// The full-screen triangle's uv, the only varyings the blit functors read.
constexpr uint32_t kUvVaryings = 3u << FullScreenVertexShader::kUv;

std::shared_ptr<const Texture2D> main_texture(const DrawContext& ctx, SamplerDesc& sampler) {
  auto texture = ctx.texture("_MainTex", &sampler);
  if (!texture) throw Error("material '" + ctx.material->name + "': blit pass without _MainTex");
  sampler.mag_filter = sampler.min_filter = FilterMode::Nearest;
  sampler.mipmap_mode = MipmapMode::None;
  return texture;
}

class CopyShader final : public FragmentShader {
 public:
  // pixel_for_pixel: the source has the target's size, so the full-screen triangle's uv puts
  // every pixel centre on its own texel (nearest, base level): a plain texel copy.
  CopyShader(std::shared_ptr<const Texture2D> source, SamplerDesc sampler, bool pixel_for_pixel)
      : source_(std::move(source)), sampler_(sampler), pixel_for_pixel_(pixel_for_pixel) {}
  bool batches_across_triangles() const override { return true; }  // outputs and texels per quad
  uint32_t varyings_read() const override { return kUvVaryings; }
  int outputs_always_written() const override { return 1; }  // every channel of every fragment, both paths
  const Texture2D* texel_copy_source() const override { return pixel_for_pixel_ ? source_.get() : nullptr; }
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    // Render targets and nearest copies: the whole batch on SIMD lanes, the same texels and trace.
    if (sample_batch_nearest(*source_, sampler_, batch.varyings[FullScreenVertexShader::kUv],
                             batch.varyings[FullScreenVertexShader::kUv + 1],
                             batch.fragment_count(), out.color[0], &out.output0_codes_of)) {
      return;
    }
    for (int q = 0; q < batch.quad_count; ++q) {
      glm::vec2 uv[kQuadLanes];
      batch_quad_uv(batch, FullScreenVertexShader::kUv, q, uv);
      glm::vec4 texel[kQuadLanes];
      source_->sample_quad(sampler_, uv, texel);
      for (int lane = 0; lane < kQuadLanes; ++lane) out.set(0, q * kQuadLanes + lane, texel[lane]);
    }
  }

 private:
  std::shared_ptr<const Texture2D> source_;
  SamplerDesc sampler_;
  bool pixel_for_pixel_;
};

template <Tonemapper kTonemapper>
class TonemapShader final : public FragmentShader {
 public:
  TonemapShader(std::shared_ptr<const Texture2D> source, SamplerDesc sampler, float exposure)
      : source_(std::move(source)), sampler_(sampler), exposure_(exposure) {}
  bool batches_across_triangles() const override { return true; }  // outputs and texels per quad
  uint32_t varyings_read() const override { return kUvVaryings; }
  int outputs_always_written() const override { return 1; }  // every channel of every fragment, both paths
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    // Nearest 1:1 reads of the whole batch on SIMD lanes (the same texels and trace as
    // sample_quad), then the tone curve on lanes with the scalar curve's operations.
    if (sample_batch_nearest(*source_, sampler_, batch.varyings[FullScreenVertexShader::kUv],
                             batch.varyings[FullScreenVertexShader::kUv + 1],
                             batch.fragment_count(), out.color[0])) {
      if constexpr (kTonemapper == Tonemapper::AcesFitted) {
        tonemap_aces_fitted_batch(out.color[0], exposure_, batch.padded_fragment_count());
      } else {
        tonemap_reinhard_batch(out.color[0], exposure_, batch.padded_fragment_count());
      }
      return;
    }
    for (int q = 0; q < batch.quad_count; ++q) {
      glm::vec2 uv[kQuadLanes];
      batch_quad_uv(batch, FullScreenVertexShader::kUv, q, uv);
      glm::vec4 hdr[kQuadLanes];
      source_->sample_quad(sampler_, uv, hdr);
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        const glm::vec3 c = glm::vec3(hdr[lane]) * exposure_;
        const glm::vec3 mapped =
            kTonemapper == Tonemapper::AcesFitted ? tonemap_aces_fitted(c) : tonemap_reinhard(c);
        out.set(0, q * kQuadLanes + lane, glm::vec4(mapped, 1.0f));
      }
    }
  }

 private:
  std::shared_ptr<const Texture2D> source_;
  SamplerDesc sampler_;
  float exposure_;
};

PassState full_screen_state() {
  PassState s;
  s.cull = CullMode::None;
  s.depth_test = false;
  s.depth_write = false;
  return s;
}

}  // namespace

Tonemapper parse_tonemapper(const std::string& name) {
  if (name == "aces") return Tonemapper::AcesFitted;
  if (name == "reinhard") return Tonemapper::Reinhard;
  throw Error("pipeline option tonemap='" + name + "': expected aces or reinhard");
}

std::unique_ptr<Shader> make_universal_blit_shader() {
  auto shader = std::make_unique<Shader>("Universal Blit");
  shader->add_pass({"Copy", "", full_screen_state(), [](const DrawContext& ctx) {
                      DrawFunctors f;
                      SamplerDesc sampler;
                      auto source = main_texture(ctx, sampler);
                      f.vertex = std::make_unique<FullScreenVertexShader>();
                      const bool pixel_for_pixel = source->level_count() == 1 &&
                                                   source->width() == ctx.target_width_px &&
                                                   source->height() == ctx.target_height_px;
                      f.fragment = std::make_unique<CopyShader>(std::move(source), sampler, pixel_for_pixel);
                      return f;
                    }});
  shader->add_pass({"Tonemap", "", full_screen_state(), [](const DrawContext& ctx) {
                      DrawFunctors f;
                      SamplerDesc sampler;
                      auto source = main_texture(ctx, sampler);
                      const float exposure = ctx.properties.get_float("_Exposure", 1.0f);
                      f.vertex = std::make_unique<FullScreenVertexShader>();
                      if (ctx.properties.get_float("_Tonemapper", 0.0f) == 0.0f) {
                        f.fragment = std::make_unique<TonemapShader<Tonemapper::AcesFitted>>(std::move(source), sampler, exposure);
                      } else {
                        f.fragment = std::make_unique<TonemapShader<Tonemapper::Reinhard>>(std::move(source), sampler, exposure);
                      }
                      return f;
                    }});
  return shader;
}

std::unique_ptr<RenderMaterial> make_copy_material(const Shader& blit_shader, const std::string& name) {
  return std::make_unique<RenderMaterial>(name, &blit_shader);
}

std::unique_ptr<RenderMaterial> make_tonemap_material(const Shader& blit_shader, Tonemapper tonemapper,
                                                      float exposure) {
  auto m = std::make_unique<RenderMaterial>("PostProcessing", &blit_shader);
  m->properties.floats["_Tonemapper"] = tonemapper == Tonemapper::AcesFitted ? 0.0f : 1.0f;
  m->properties.floats["_Exposure"] = exposure;
  return m;
}

}  // namespace ontile
