// Late Z at one sample (functors that may discard) written back a batch at a time: colour,
// stored depth and the shaded / written / depth-rejected counters of layered full-screen
// triangles whose functors discard patterns of pixels, against a per-pixel reference.
#include <gtest/gtest.h>

#include <vector>

#include "context/frame_report.h"
#include "support/raster_harness.h"

namespace ontile {
namespace {

constexpr int kW = 72, kH = 40;  // tiles of several sizes and a partial last batch

// Writes varying 0 and discards the pixels where (x * a + y) % m == 0 (m = 0: none).
class PatternDiscardShader final : public FragmentShader {
 public:
  PatternDiscardShader(int a, int m) : a_(a), m_(m) {}
  bool may_discard() const override { return m_ != 0; }
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    for (int f = 0; f < batch.fragment_count(); ++f) {
      if (!batch.active(f)) continue;
      out.set(0, f, glm::vec4(batch.varyings[0][f], 0.0f, 0.0f, 1.0f));
      if (discards(batch.x_px(f), batch.y_px(f))) out.discard(f);
    }
  }
  bool discards(int x, int y) const { return m_ != 0 && (x * a_ + y) % m_ == 0; }

 private:
  int a_, m_;
};

struct Layer {
  float z;
  PatternDiscardShader shader;
};

TEST(LateZBatches, LayeredDiscardsMatchAPerPixelReference) {
  // Far and plain, then near with discards (always passes depth), then in between with
  // discards (fails depth wherever the near layer stayed).
  const std::vector<Layer> layers = {{0.8f, {1, 0}}, {0.2f, {1, 3}}, {0.5f, {7, 5}}};
  std::vector<glm::vec4> pos;
  std::vector<float> var;
  std::vector<uint32_t> idx;
  for (const Layer& layer : layers) {
    for (const glm::vec2 p : {glm::vec2(-1, -1), glm::vec2(3, -1), glm::vec2(-1, 3)}) {
      idx.push_back(static_cast<uint32_t>(pos.size()));
      pos.emplace_back(p.x, p.y, layer.z, 1.0f);
      var.push_back(layer.z);
    }
  }
  ContextConfig cfg;
  cfg.threads = 2;
  RenderContext ctx(cfg);
  Surface* color = ctx.create_surface("c", PixelFormat::R32_FLOAT, kW, kH);
  Surface* depth = ctx.create_surface("d", PixelFormat::D32_FLOAT, kW, kH);
  test::ClipSpaceVertexShader vs(pos, var, 1);
  ctx.begin_render_pass("layers", kW, kH, 1,
                        {{"c", PixelFormat::R32_FLOAT, LoadAction::Clear, StoreAction::Store, glm::vec4(0.0f), color, nullptr},
                         {"d", PixelFormat::D32_FLOAT, LoadAction::Clear, StoreAction::Store, glm::vec4(1.0f), depth, nullptr}},
                        1);
  ctx.begin_subpass({0});
  for (size_t k = 0; k < layers.size(); ++k) {
    DrawCall d;
    d.vertex_shader = &vs;
    d.fragment_shader = &layers[k].shader;
    d.vertex_count = vs.vertex_count();
    d.indices = idx.data() + 3 * k;
    d.index_count = 3;
    d.raster.cull = CullMode::None;
    ctx.draw(d);
  }
  ctx.end_subpass();
  ctx.end_render_pass();
  const FrameReport report = ctx.submit();

  uint64_t written = 0, rejected = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      float stored = 1.0f;
      for (const Layer& layer : layers) {
        if (layer.shader.discards(x, y)) continue;  // discarded lanes leave coverage: not rejected
        if (!(layer.z < stored)) {
          ++rejected;
          continue;
        }
        stored = layer.z;
        ++written;
      }
      ASSERT_EQ(depth->read(x, y).x, stored) << x << "," << y;
      ASSERT_EQ(color->read(x, y).x, stored) << x << "," << y;
    }
  }
  const TileCounters& t = report.passes[0].tiles;
  EXPECT_EQ(t.fragments_shaded, uint64_t{3} * kW * kH);
  EXPECT_EQ(t.samples_written, written);
  EXPECT_EQ(t.fragments_depth_rejected, rejected);
  EXPECT_GT(rejected, 0u);
}

}  // namespace
}  // namespace ontile
