// Colour copy and tonemapping passes (see post_processing.h).
#include "pipelines/universal/post_processing.h"

#include <algorithm>

#include "shaders_cpp/full_screen.h"
#include "util/error.h"

namespace ontile {
namespace {

std::shared_ptr<const Texture2D> main_texture(const DrawContext& ctx, SamplerDesc& sampler) {
  auto texture = ctx.texture("_MainTex", &sampler);
  if (!texture) throw Error("material '" + ctx.material->name + "': blit pass without _MainTex");
  sampler.mag_filter = sampler.min_filter = FilterMode::Nearest;
  sampler.mipmap_mode = MipmapMode::None;
  return texture;
}

class CopyShader final : public FragmentShader {
 public:
  CopyShader(std::shared_ptr<const Texture2D> source, SamplerDesc sampler)
      : source_(std::move(source)), sampler_(sampler) {}
  void shade(const QuadFragment& quad, QuadOutput& out) const override {
    glm::vec2 uv[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = quad.var2(FullScreenVertexShader::kUv, lane);
    source_->sample_quad(sampler_, uv, out.color[0]);
  }

 private:
  std::shared_ptr<const Texture2D> source_;
  SamplerDesc sampler_;
};

template <Tonemapper kTonemapper>
class TonemapShader final : public FragmentShader {
 public:
  TonemapShader(std::shared_ptr<const Texture2D> source, SamplerDesc sampler, float exposure)
      : source_(std::move(source)), sampler_(sampler), exposure_(exposure) {}
  void shade(const QuadFragment& quad, QuadOutput& out) const override {
    glm::vec2 uv[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = quad.var2(FullScreenVertexShader::kUv, lane);
    glm::vec4 hdr[kQuadLanes];
    source_->sample_quad(sampler_, uv, hdr);
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      const glm::vec3 c = glm::vec3(hdr[lane]) * exposure_;
      const glm::vec3 mapped = kTonemapper == Tonemapper::AcesFitted ? tonemap_aces_fitted(c) : tonemap_reinhard(c);
      out.color[0][lane] = glm::vec4(mapped, 1.0f);
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

glm::vec3 tonemap_aces_fitted(glm::vec3 c) {
  // sRGB -> ACES AP1 with the RRT's saturation folded in (ACESInputMat, rows).
  const glm::vec3 v(0.59719f * c.x + 0.35458f * c.y + 0.04823f * c.z,
                    0.07600f * c.x + 0.90834f * c.y + 0.01566f * c.z,
                    0.02840f * c.x + 0.13383f * c.y + 0.83777f * c.z);
  // RRTAndODTFit: a rational fit of the RRT + ODT tone curve.
  const glm::vec3 a = v * (v + 0.0245786f) - 0.000090537f;
  const glm::vec3 b = v * (0.983729f * v + 0.4329510f) + 0.238081f;
  const glm::vec3 f = a / b;
  // ODT_SAT -> XYZ -> D60->D65 -> sRGB (ACESOutputMat, rows), then saturate.
  const glm::vec3 out(1.60475f * f.x - 0.53108f * f.y - 0.07367f * f.z,
                      -0.10208f * f.x + 1.10813f * f.y - 0.00605f * f.z,
                      -0.00327f * f.x - 0.07276f * f.y + 1.07602f * f.z);
  return glm::clamp(out, 0.0f, 1.0f);
}

glm::vec3 tonemap_reinhard(glm::vec3 c) {
  const glm::vec3 positive = glm::max(c, glm::vec3(0.0f));
  return positive / (1.0f + positive);
}

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
                      f.fragment = std::make_unique<CopyShader>(std::move(source), sampler);
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
