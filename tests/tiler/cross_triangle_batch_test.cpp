// Batches that span triangles (FragmentShader::batches_across_triangles): the same images,
// depth, counters and texture-cache traffic as one triangle per batch (so per-quad primitive ids
// and writes in triangle order), and batches that really hold several triangles.
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include "context/frame_report.h"
#include "raster/texture.h"
#include "support/raster_harness.h"

namespace ontile {
namespace {

constexpr int kW = 96, kH = 72;
constexpr int kGridPx = 7;  // one triangle pair per 7 px square: smaller than a batch, off the quad grid

// Samples a mipmapped texture per quad at the uv in varyings 0-1 (bilinear, so the LOD uses the
// quad's derivatives and every texel read is traced) and writes texel.rg, the quad's primitive
// id and varying 2. Counts its calls, its quads and the most triangles one batch held.
class ProbeShader final : public FragmentShader {
 public:
  ProbeShader(const Texture2D& texture, bool across) : texture_(texture), across_(across) {
    sampler_.mag_filter = sampler_.min_filter = FilterMode::Linear;
    sampler_.mipmap_mode = MipmapMode::Linear;
  }
  bool batches_across_triangles() const override { return across_; }
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override {
    ++calls;
    quads += static_cast<uint64_t>(batch.quad_count);
    int triangles = 1;
    for (int q = 1; q < batch.quad_count; ++q) {
      triangles += batch.quad_primitive_id[q] != batch.quad_primitive_id[q - 1];
    }
    int seen = most_triangles.load();
    while (triangles > seen && !most_triangles.compare_exchange_weak(seen, triangles)) {}
    for (int q = 0; q < batch.quad_count; ++q) {
      glm::vec2 uv[kQuadLanes];
      glm::vec4 texel[kQuadLanes];
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        uv[lane] = {batch.varyings[0][q * kQuadLanes + lane], batch.varyings[1][q * kQuadLanes + lane]};
      }
      texture_.sample_quad(sampler_, uv, texel);
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        const int f = q * kQuadLanes + lane;
        out.set(0, f, glm::vec4(texel[lane].x, texel[lane].y,
                                static_cast<float>(batch.quad_primitive_id[q]), batch.varyings[2][f]));
      }
    }
  }
  mutable std::atomic<uint64_t> calls{0}, quads{0};
  mutable std::atomic<int> most_triangles{0};

 private:
  const Texture2D& texture_;
  SamplerDesc sampler_;
  bool across_;
};

std::shared_ptr<const Texture2D> checker_texture() {
  std::vector<uint8_t> rgba;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) rgba.insert(rgba.end(), {uint8_t(x * 4), uint8_t(y * 4), uint8_t(x ^ y), 255});
  }
  return Texture2D::from_rgba8(64, 64, std::move(rgba), false, "checker");
}

// A grid of small separate triangles with perspective (w varies per vertex), uv and a third
// varying; every triangle is followed by a copy shifted by (1, 1) px with the same vertex
// depths. Depth grows with x + y, so the copy is nearer where they overlap and wins with Less:
// the copy's quads overlap the original's full and partial quads, inside one batch when
// batches span triangles, so a write out of order changes the image. Copies have odd ids.
struct Frame {
  std::vector<glm::vec4> color;
  std::vector<float> depth;  // single-sample frames only
  nlohmann::json report;
};

Frame draw_grid(const ProbeShader& probe, int threads, int samples) {
  std::vector<glm::vec4> positions;
  std::vector<float> varyings;
  std::vector<uint32_t> indices;
  const int nx = kW / kGridPx + 1, ny = kH / kGridPx + 1;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      for (const double shift_px : {0.0, 1.0}) {
        const double x = i * kGridPx - 1.3 + shift_px, y = j * kGridPx - 0.6 + shift_px;
        const double w = 1.0 + 0.05 * ((i * 7 + j * 3) % 5);
        const double z = 0.3 + 0.4 * (i + j) / (nx + ny);
        const uint32_t first = static_cast<uint32_t>(positions.size());
        // Legs of 0.7 grid squares: a triangle and its copy touch no other pair.
        const double leg = 0.7 * kGridPx;
        for (const glm::dvec2 corner : {glm::dvec2(0, 0), glm::dvec2(leg, 0), glm::dvec2(0, leg)}) {
          positions.push_back(test::pixel_to_clip(x + corner.x, y + corner.y, kW, kH, w,
                                                  z + 0.01 * (corner.x + corner.y) / leg));
          varyings.insert(varyings.end(), {static_cast<float>(x + corner.x) / 35.0f,
                                           static_cast<float>(y + corner.y) / 25.0f,
                                           static_cast<float>(i * 31 + j)});
        }
        indices.insert(indices.end(), {first, first + 1, first + 2});
      }
    }
  }
  ContextConfig cfg;
  cfg.threads = threads;
  cfg.tiler.tile_size_px = 32;
  RenderContext ctx(cfg);
  Surface* color = ctx.create_surface("c", PixelFormat::RGBA32_FLOAT, kW, kH);
  Surface* depth = ctx.create_surface("d", PixelFormat::D32_FLOAT, kW, kH);
  test::ClipSpaceVertexShader vs(positions, varyings, 3);
  AttachmentDesc c{"c", PixelFormat::RGBA32_FLOAT, LoadAction::Clear, StoreAction::Store, glm::vec4(0.0f), color, nullptr};
  AttachmentDesc d{"d", PixelFormat::D32_FLOAT, LoadAction::Clear, StoreAction::Store, glm::vec4(1.0f), depth, nullptr};
  if (samples > 1) {
    c.surface = nullptr;
    c.resolve_surface = color;
    c.store = StoreAction::Resolve;
    d.surface = nullptr;
    d.store = StoreAction::DontCare;
  }
  ctx.begin_render_pass("grid", kW, kH, samples, {c, d}, 1);
  ctx.begin_subpass({0});
  DrawCall draw;
  draw.vertex_shader = &vs;
  draw.fragment_shader = &probe;
  draw.vertex_count = vs.vertex_count();
  draw.indices = indices.data();
  draw.index_count = static_cast<uint32_t>(indices.size());
  draw.raster.cull = CullMode::None;
  ctx.draw(draw);
  ctx.end_subpass();
  ctx.end_render_pass();
  Frame frame;
  frame.report = frame_report_json(ctx.submit());
  frame.report.erase("timing");
  for (auto& pass : frame.report["passes"]) pass.erase("timing");
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      frame.color.push_back(color->read(x, y));
      if (samples == 1) frame.depth.push_back(depth->read(x, y).x);
    }
  }
  return frame;
}

TEST(CrossTriangleBatches, SameBitsCountersAndTextureTrafficAsOneTrianglePerBatch) {
  const auto texture = checker_texture();
  for (const int samples : {1, 4}) {
    for (const int threads : {1, 2}) {
      SCOPED_TRACE("samples " + std::to_string(samples) + ", threads " + std::to_string(threads));
      const ProbeShader per_triangle_probe(*texture, false), across_probe(*texture, true);
      const Frame per_triangle = draw_grid(per_triangle_probe, threads, samples);
      const Frame across = draw_grid(across_probe, threads, samples);
      // Compared as booleans: a mismatch would print every pixel.
      EXPECT_TRUE(across.color == per_triangle.color);
      EXPECT_TRUE(across.depth == per_triangle.depth);
      EXPECT_EQ(across.report, per_triangle.report);
      EXPECT_GT(per_triangle.report["passes"][0]["texture"]["accesses"].get<uint64_t>(), 0u);
      // Every quad shaded once either way, in far fewer calls once batches span triangles.
      EXPECT_EQ(per_triangle_probe.most_triangles, 1);
      EXPECT_EQ(across_probe.quads, per_triangle_probe.quads);
      EXPECT_LT(across_probe.calls * 3, per_triangle_probe.calls);
      EXPECT_GT(across_probe.most_triangles, 4);
    }
  }
}

}  // namespace
}  // namespace ontile
