// Test harness: draws raw clip-space triangles through the real context and tiler, with
// additive coverage counting (each covered sample adds 1 to an R32F target) or with the
// varyings written out, so tests can assert exact per-pixel outcomes.
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "context/render_context.h"

namespace ontile::test {

// Vertex shader over explicit clip positions and per-vertex varyings.
class ClipSpaceVertexShader final : public VertexShader {
 public:
  ClipSpaceVertexShader(std::vector<glm::vec4> positions, std::vector<float> varyings, int n)
      : positions_(std::move(positions)), varyings_(std::move(varyings)), n_(n) {}
  int varying_count() const override { return n_; }
  void shade(uint32_t first, uint32_t count, glm::vec4* clip, float* var) const override {
    for (uint32_t i = 0; i < count; ++i) {
      clip[i] = positions_[first + i];
      for (int k = 0; k < n_; ++k) var[i * n_ + k] = varyings_[(first + i) * n_ + k];
    }
  }
  uint32_t vertex_count() const { return static_cast<uint32_t>(positions_.size()); }

 private:
  std::vector<glm::vec4> positions_;
  std::vector<float> varyings_;
  int n_;
};

// Writes 1 (for additive counting) or the first four varyings.
class ConstantOneShader final : public FragmentShader {
 public:
  void shade(const QuadFragment&, QuadOutput& out) const override {
    for (int lane = 0; lane < kQuadLanes; ++lane) out.color[0][lane] = glm::vec4(1.0f);
  }
};
class VaryingsShader final : public FragmentShader {
 public:
  void shade(const QuadFragment& q, QuadOutput& out) const override {
    for (int lane = 0; lane < kQuadLanes; ++lane) out.color[0][lane] = q.var4(0, lane);
  }
};

// Pixel coordinates (y down) to clip space with w = 1 (or scaled by w).
inline glm::vec4 pixel_to_clip(double x, double y, int width, int height, double w = 1.0,
                               double z = 0.5) {
  return glm::vec4(static_cast<float>((x / width * 2.0 - 1.0) * w),
                   static_cast<float>((1.0 - y / height * 2.0) * w), static_cast<float>(z * w),
                   static_cast<float>(w));
}

// One draw of `indices` with no culling and no depth test (`vs`, `fs` and `indices` must outlive
// the frame's submit()).
inline DrawCall unculled_draw(const ClipSpaceVertexShader& vs, const FragmentShader& fs,
                              const std::vector<uint32_t>& indices) {
  DrawCall d;
  d.vertex_shader = &vs;
  d.fragment_shader = &fs;
  d.vertex_count = vs.vertex_count();
  d.indices = indices.data();
  d.index_count = static_cast<uint32_t>(indices.size());
  d.raster.cull = CullMode::None;
  d.raster.depth_test = false;
  return d;
}

// Records one pass with a single colour attachment and one draw of `indices`: no culling, no
// depth, additive blending (so overlapping coverage adds up).
inline void record_additive_pass(RenderContext& ctx, const std::string& name, int width, int height, int samples,
                                 const AttachmentDesc& target, const ClipSpaceVertexShader& vs,
                                 const FragmentShader& fs, const std::vector<uint32_t>& indices) {
  ctx.begin_render_pass(name, width, height, samples, {target}, -1);
  ctx.begin_subpass({0});
  DrawCall d = unculled_draw(vs, fs, indices);
  d.blend.mode = BlendMode::Additive;
  ctx.draw(d);
  ctx.end_subpass();
  ctx.end_render_pass();
}

struct CountResult {
  std::vector<float> counts;  // per pixel (sample 0)
  FrameReport report;
  float at(int x, int y, int width) const { return counts[static_cast<size_t>(y) * width + x]; }
};

// Draws the triangles with cull mode None, no depth, additive blending into R32F.
// With samples > 1 the target is resolved, so counts are the covered fraction of samples.
// subpixel_bits is the tiler's vertex snapping precision (TilerConfig::subpixel_bits).
inline CountResult draw_counting(const std::vector<glm::vec4>& positions,
                                 const std::vector<uint32_t>& indices, int width, int height,
                                 int tile_size_px = 16, int threads = 2, int samples = 1,
                                 int subpixel_bits = kSubpixelBits) {
  ContextConfig cfg;
  cfg.threads = threads;
  cfg.tiler.tile_size_px = tile_size_px;
  cfg.tiler.subpixel_bits = subpixel_bits;
  RenderContext ctx(cfg);
  Surface* target = ctx.create_surface("count", PixelFormat::R32_FLOAT, width, height);
  ClipSpaceVertexShader vs(positions, {}, 0);
  ConstantOneShader fs;
  AttachmentDesc count{"count", PixelFormat::R32_FLOAT, LoadAction::Clear, StoreAction::Store,
                       glm::vec4(0.0f), target, nullptr};
  if (samples > 1) {
    count.surface = nullptr;
    count.resolve_surface = target;
    count.store = StoreAction::Resolve;
  }
  record_additive_pass(ctx, "count", width, height, samples, count, vs, fs, indices);
  CountResult r;
  r.report = ctx.submit();
  r.counts.resize(static_cast<size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) r.counts[static_cast<size_t>(y) * width + x] = target->read(x, y).x;
  return r;
}

}  // namespace ontile::test
