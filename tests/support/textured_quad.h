// A textured full-screen quad: one texel per pixel of a size x size texture, nearest, clamped,
// with the pass's texture traffic and the pixels drawn (texture-cache tests).
#pragma once
#include <memory>
#include <vector>

#include "raster/texture.h"
#include "support/raster_harness.h"

namespace ontile::test {

// Samples texture unit 0 at the uv in varyings 0-1, nearest, as a real material shader does.
class TexturedShader final : public FragmentShader {
 public:
  explicit TexturedShader(std::shared_ptr<const Texture2D> texture) : texture_(std::move(texture)) {
    sampler_.mag_filter = sampler_.min_filter = FilterMode::Nearest;
    sampler_.mipmap_mode = MipmapMode::None;
    sampler_.wrap_u = sampler_.wrap_v = WrapMode::ClampToEdge;
  }
  void shade(const QuadFragment& q, QuadOutput& out) const override {
    glm::vec2 uv[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = q.var2(0, lane);
    texture_->sample_quad(sampler_, uv, out.color[0]);
  }

 private:
  std::shared_ptr<const Texture2D> texture_;
  SamplerDesc sampler_;
};

struct TexturedQuadResult {
  TextureTraffic texture;
  std::vector<glm::vec4> pixels;
};

// Draws a size x size quad covering the target with uv 0..1, so pixel (x, y) samples texel
// (x, y) of a size x size texture: one texel per pixel.
inline TexturedQuadResult draw_textured_quad(std::shared_ptr<const Texture2D> texture, int size,
                                      int threads) {
  ContextConfig cfg;
  cfg.threads = threads;
  cfg.tiler.tile_size_px = 16;
  RenderContext ctx(cfg);
  Surface* target = ctx.create_surface("color", PixelFormat::RGBA8_UNORM, size, size);
  ClipSpaceVertexShader vs(
      {pixel_to_clip(0, 0, size, size), pixel_to_clip(size, 0, size, size),
       pixel_to_clip(0, size, size, size), pixel_to_clip(size, size, size, size)},
      {0, 0, 1, 0, 0, 1, 1, 1}, 2);
  TexturedShader fs(std::move(texture));
  const std::vector<uint32_t> indices = {0, 1, 2, 2, 1, 3};
  ctx.begin_render_pass("textured", size, size, 1,
                        {{"color", PixelFormat::RGBA8_UNORM, LoadAction::DontCare,
                          StoreAction::Store, glm::vec4(0.0f), target, nullptr}},
                        -1);
  ctx.begin_subpass({0});
  ctx.draw(unculled_draw(vs, fs, indices));
  ctx.end_subpass();
  ctx.end_render_pass();
  const FrameReport frame = ctx.submit();
  TexturedQuadResult result;
  result.texture = frame.passes.at(0).texture;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) result.pixels.push_back(target->read(x, y));
  return result;
}

}  // namespace ontile::test
