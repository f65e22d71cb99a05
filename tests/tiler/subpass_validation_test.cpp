// Subpasses and framebuffer fetch: a later subpass reads what an earlier one wrote at its own
// pixel, and each validation error fires with its message.
#include <gtest/gtest.h>

#include "support/raster_harness.h"
#include "util/error.h"

namespace ontile::test {
namespace {

constexpr int kW = 40, kH = 24;

// Writes the pixel's coordinates so the reader can check it saw its own pixel.
class CoordinateShader final : public FragmentShader {
 public:
  void shade(const QuadFragment& q, QuadOutput& out) const override {
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      out.color[0][lane] = glm::vec4(q.x_px + (lane & 1), q.y_px + (lane >> 1), 7.0f, 1.0f);
    }
  }
};
// Reads input slot `slot` and writes it doubled.
class FetchShader final : public FragmentShader {
 public:
  explicit FetchShader(int slot) : slot_(slot) {}
  void shade(const QuadFragment& q, QuadOutput& out) const override {
    for (int lane = 0; lane < kQuadLanes; ++lane) out.color[0][lane] = 2.0f * q.input(slot_, lane);
  }

 private:
  int slot_;
};

struct FullScreen {
  ClipSpaceVertexShader vs{{{-1, -1, 0.5f, 1}, {3, -1, 0.5f, 1}, {-1, 3, 0.5f, 1}}, {}, 0};
  std::vector<uint32_t> idx{0, 1, 2};
  DrawCall draw(const FragmentShader* fs) {
    DrawCall d;
    d.vertex_shader = &vs;
    d.fragment_shader = fs;
    d.vertex_count = 3;
    d.indices = idx.data();
    d.index_count = 3;
    d.raster.cull = CullMode::None;
    d.raster.depth_test = false;
    return d;
  }
};

AttachmentDesc color(const char* name, Surface* s, LoadAction load = LoadAction::Clear) {
  return {name, PixelFormat::RGBA32_FLOAT, load, s ? StoreAction::Store : StoreAction::DontCare,
          glm::vec4(0.0f), s, nullptr};
}

TEST(Subpasses, LaterSubpassFetchesItsOwnPixelFromTileMemory) {
  RenderContext ctx;
  Surface* out = ctx.create_surface("out", PixelFormat::RGBA32_FLOAT, kW, kH);
  FullScreen fs;
  CoordinateShader writer;
  FetchShader reader(0);
  ctx.begin_render_pass("two", kW, kH, 1, {color("out", out), color("gbuffer", nullptr)}, -1);
  ctx.begin_subpass({1});
  ctx.draw(fs.draw(&writer));
  ctx.end_subpass();
  ctx.begin_subpass({0}, {1});
  ctx.draw(fs.draw(&reader));
  ctx.end_subpass();
  ctx.end_render_pass();
  const FrameReport r = ctx.submit();
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) ASSERT_EQ(out->read(x, y), glm::vec4(2 * x, 2 * y, 14, 2));
  EXPECT_EQ(r.bytes_written(), 16u * kW * kH + r.passes[0].geometry.parameter_bytes_written);
  EXPECT_EQ(r.passes[0].attachments[1].bytes_stored, 0u) << "the G-buffer stays on tile";
}

void expect_invalid(RenderContext& ctx, const std::string& phrase) {
  try {
    ctx.submit();
    ADD_FAILURE() << "no error, expected: " << phrase;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
  }
}

TEST(Subpasses, ValidationErrors) {
  FullScreen fs;
  CoordinateShader writer;
  FetchShader reader(0), bad_reader(1);
  {  // writing an input
    RenderContext ctx;
    ctx.begin_render_pass("p", kW, kH, 1, {color("a", nullptr), color("b", nullptr)}, -1);
    ctx.begin_subpass({0, 1}, {1});
    ctx.end_subpass();
    ctx.end_render_pass();
    expect_invalid(ctx, "writes its input attachment 'b'");
  }
  {  // reading what no earlier subpass wrote
    RenderContext ctx;
    ctx.begin_render_pass("p", kW, kH, 1, {color("a", nullptr), color("b", nullptr, LoadAction::DontCare)}, -1);
    ctx.begin_subpass({0}, {1});
    ctx.end_subpass();
    ctx.end_render_pass();
    expect_invalid(ctx, "reads 'b', which no earlier subpass wrote");
  }
  {  // fetching an input slot the subpass did not declare
    RenderContext ctx;
    ctx.begin_render_pass("p", kW, kH, 1, {color("a", nullptr), color("b", nullptr)}, -1);
    ctx.begin_subpass({1});
    ctx.draw(fs.draw(&writer));
    ctx.end_subpass();
    ctx.begin_subpass({0}, {1});
    ctx.draw(fs.draw(&bad_reader));
    ctx.end_subpass();
    ctx.end_render_pass();
    expect_invalid(ctx, "input slot 1, but the subpass declares 1 inputs");
  }
  {  // size mismatch
    RenderContext ctx;
    Surface* s = ctx.create_surface("s", PixelFormat::RGBA32_FLOAT, kW + 1, kH);
    ctx.begin_render_pass("p", kW, kH, 1, {color("a", s)}, -1);
    ctx.end_render_pass();
    expect_invalid(ctx, "surface is 41x24, the pass is 40x24");
  }
  {  // sample-count mismatch
    RenderContext ctx;
    Surface* s = ctx.create_surface("s", PixelFormat::RGBA32_FLOAT, kW, kH, 1);
    ctx.begin_render_pass("p", kW, kH, 4, {color("a", s)}, -1);
    ctx.end_render_pass();
    expect_invalid(ctx, "surface has 1 samples, expected 4");
  }
  {  // more than 8 colour attachments
    RenderContext ctx;
    std::vector<AttachmentDesc> many(9, color("c", nullptr));
    ctx.begin_render_pass("p", kW, kH, 1, many, -1);
    ctx.end_render_pass();
    expect_invalid(ctx, "9 colour attachments (at most 8)");
  }
  {  // Load on a transient attachment
    RenderContext ctx;
    ctx.begin_render_pass("p", kW, kH, 1, {color("a", nullptr, LoadAction::Load)}, -1);
    ctx.end_render_pass();
    expect_invalid(ctx, "transient but its load action is Load");
  }
}

}  // namespace
}  // namespace ontile::test
