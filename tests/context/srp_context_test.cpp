// The SRP-style context: culling, draw_renderers (sorting, filtering, LightMode tags),
// keyword variants, command buffers (clears, temporary targets, blit, skybox) and their errors.
#include <gtest/gtest.h>

#include <memory>
#include <typeinfo>

#include "context/render_context.h"
#include "context/scene_renderers.h"
#include "pipelines/lit/lit_shader.h"
#include "shaders_cpp/full_screen.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr int kW = 64, kH = 32;

// A square in the plane z = z_view (view space = world space: identity view), half size h.
MeshPrimitive square(float z, float h) {
  MeshPrimitive m;
  m.positions = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}};
  m.normals.assign(4, glm::vec3(0, 0, 1));
  m.indices = {0, 1, 2, 0, 2, 3};
  for (const auto& p : m.positions) m.bounds.extend(p);
  return m;
}

// Writes the material's _Color; no depth test, so the last draw wins (order is observable).
class ColorShader final : public FragmentShader {
 public:
  explicit ColorShader(glm::vec4 c) : c_(c) {}
  void shade(const QuadFragment&, QuadOutput& out) const override {
    for (int lane = 0; lane < kQuadLanes; ++lane) out.color[0][lane] = c_;
  }

 private:
  glm::vec4 c_;
};

DrawFunctors color_functors(const DrawContext& ctx) {
  DrawFunctors f;
  f.vertex = std::make_unique<MeshVertexShader>(*ctx.mesh, ctx.world, ctx.camera.view_projection);
  f.fragment = std::make_unique<ColorShader>(ctx.properties.get_vector("_Color"));
  return f;
}

struct Fixture {
  Shader shader{"Test"};
  std::vector<MeshPrimitive> meshes;
  std::vector<std::unique_ptr<RenderMaterial>> materials;
  std::vector<Renderer> renderers;
  CameraMatrices camera;

  Fixture() {
    PassState no_depth;
    no_depth.cull = CullMode::None;
    no_depth.depth_test = false;
    no_depth.depth_write = false;
    shader.add_pass({"Main", "Test", no_depth, color_functors});
    Camera cam;
    cam.yfov_rad = 1.0f;
    cam.znear = 0.1f;
    cam.zfar = 100.0f;
    camera = camera_matrices(cam, double(kW) / kH);
    meshes.reserve(16);
  }
  const Renderer& add(float z, float h, glm::vec4 color, int queue = render_queue::kGeometry,
                      uint32_t layer = 0, const Shader* s = nullptr) {
    meshes.push_back(square(z, h));
    auto m = std::make_unique<RenderMaterial>("m" + std::to_string(materials.size()), s ? s : &shader);
    m->properties.vectors["_Color"] = color;
    m->render_queue = queue;
    Renderer r;
    r.mesh = &meshes.back();
    r.world_bounds = meshes.back().bounds;
    r.material = m.get();
    r.layer = layer;
    materials.push_back(std::move(m));
    renderers.push_back(r);
    return renderers.back();
  }
};

// The frame keeps its context: the context owns the colour surface, which centre() reads
// after draw() returns (AddressSanitizer found the earlier version reading freed memory).
struct Frame {
  std::unique_ptr<RenderContext> context = std::make_unique<RenderContext>();
  FrameReport report;
  Surface* color = nullptr;
  glm::vec4 centre() const { return color->read(kW / 2, kH / 2); }
};

Frame draw(Fixture& f, const DrawingSettings& drawing, const FilteringSettings& filtering) {
  Frame out;
  RenderContext& ctx = *out.context;
  out.color = ctx.create_surface("c", PixelFormat::RGBA8_UNORM, kW, kH);
  const CullingResults culling = ctx.cull(f.renderers, f.camera);
  ctx.set_render_target({{RenderTargetRef::of(out.color), LoadAction::Clear, StoreAction::Store}});
  ctx.draw_renderers(culling, drawing, filtering);
  out.report = ctx.submit();
  return out;
}

const glm::vec4 kRed(1, 0, 0, 1), kBlue(0, 0, 1, 1), kGreen(0, 1, 0, 1);

TEST(Culling, FrustumAndLayerMask) {
  Fixture f;
  f.add(-3.0f, 1.0f, kRed);            // in view
  f.add(+3.0f, 1.0f, kRed);            // behind the camera
  f.add(-3.0f, 0.1f, kRed).world;      // placeholder, moved off to the side below
  f.renderers[2].world_bounds.min.x += 50.0f;
  f.renderers[2].world_bounds.max.x += 50.0f;
  f.add(-3.0f, 1.0f, kRed, render_queue::kGeometry, 5);  // in view, layer 5
  const CullingResults all = cull_renderers(f.renderers, f.camera, {});
  EXPECT_EQ(all.visible, (std::vector<uint32_t>{0, 3}));
  const CullingResults masked = cull_renderers(f.renderers, f.camera, {~(1u << 5)});
  EXPECT_EQ(masked.visible, (std::vector<uint32_t>{0}));
}

TEST(DrawRenderers, OpaqueFrontToBackTransparentBackToFront) {
  Fixture f;
  f.add(-2.0f, 1.0f, kRed);   // near
  f.add(-6.0f, 3.0f, kBlue);  // far, covers the same centre pixel
  // Opaque: front to back, so the far square is drawn last and (no depth test) wins.
  EXPECT_EQ(draw(f, {{"Test"}, SortingCriteria::CommonOpaque}, {}).centre(), kBlue);
  // Renderer order.
  EXPECT_EQ(draw(f, {{"Test"}, SortingCriteria::None}, {}).centre(), kBlue);
  f.renderers[0].material = f.materials[0].get();
  std::swap(f.renderers[0], f.renderers[1]);
  EXPECT_EQ(draw(f, {{"Test"}, SortingCriteria::None}, {}).centre(), kRed);
  // Transparent: back to front, so the near square is drawn last.
  EXPECT_EQ(draw(f, {{"Test"}, SortingCriteria::CommonTransparent}, {}).centre(), kRed);
}

TEST(DrawRenderers, RenderQueueRangeLayerAndLightModeFilter) {
  Fixture f;
  Shader other("Other");
  other.add_pass({"Main", "OtherTag", PassState{}, color_functors});
  f.add(-2.0f, 1.0f, kRed);                                     // opaque, tag Test
  f.add(-2.0f, 1.0f, kBlue, render_queue::kTransparent);        // transparent
  f.add(-2.0f, 1.0f, kGreen, render_queue::kGeometry, 0, &other);  // no "Test" pass
  const uint64_t one_square = draw(f, {{"Test"}}, {RenderQueueRange::opaque()}).report.passes[0].tiles.fragments_shaded;
  EXPECT_GT(one_square, 0u);
  EXPECT_EQ(draw(f, {{"Test"}}, {RenderQueueRange::opaque()}).centre(), kRed);
  EXPECT_EQ(draw(f, {{"Test"}}, {RenderQueueRange::transparent()}).centre(), kBlue);
  EXPECT_EQ(draw(f, {{"Test"}}, {RenderQueueRange::all()}).report.passes[0].tiles.fragments_shaded, 2 * one_square);
  EXPECT_EQ(draw(f, {{"Test", "OtherTag"}}, {RenderQueueRange::all()}).report.passes[0].tiles.fragments_shaded,
            3 * one_square);
  FilteringSettings no_layer0{RenderQueueRange::all(), ~1u, ~0u};
  EXPECT_EQ(draw(f, {{"Test"}}, no_layer0).report.passes[0].tiles.fragments_shaded, 0u);
}

TEST(DrawRenderers, EveryMatchingPassDrawsInTagOrder) {
  Fixture f;
  Shader two("Two");
  PassState no_depth;
  no_depth.depth_test = false;
  two.add_pass({"First", "A", no_depth, [](const DrawContext& c) {
                  DrawFunctors d = color_functors(c);
                  d.fragment = std::make_unique<ColorShader>(kGreen);
                  return d;
                }});
  two.add_pass({"Second", "B", no_depth, color_functors});
  f.add(-2.0f, 1.0f, kRed, render_queue::kGeometry, 0, &two);
  EXPECT_EQ(draw(f, {{"A", "B"}}, {}).centre(), kRed);
  EXPECT_EQ(draw(f, {{"B", "A"}}, {}).centre(), kGreen);
}

TEST(Shaders, KeywordsSelectCompileTimeVariantsAndUsePassCopies) {
  const auto lit = make_lit_shader();
  Material gltf;
  MeshPrimitive mesh = square(-2.0f, 1.0f);
  auto build = [&](const RenderMaterial& m) {
    DrawContext ctx;
    ctx.mesh = &mesh;
    ctx.material = &m;
    ctx.properties = m.properties;
    return lit->find_light_mode(lit::kForwardLit)->factory(ctx);
  };
  auto plain = make_lit_material(*lit, gltf);
  EXPECT_EQ(typeid(*build(*plain).fragment), typeid(LambertShader<false, false, false>));
  gltf.alpha_mode = AlphaMode::Mask;
  auto masked = make_lit_material(*lit, gltf);
  EXPECT_TRUE(masked->has_keyword("_ALPHATEST_ON"));
  EXPECT_EQ(typeid(*build(*masked).fragment), typeid(LambertShader<false, true, false>));
  EXPECT_TRUE(build(*masked).fragment->may_discard());
  EXPECT_FALSE(build(*plain).fragment->may_discard());

  Shader outline("Outline");
  outline.use_pass(*lit, "DepthOnly");
  ASSERT_NE(outline.find_light_mode(lit::kDepthOnly), nullptr);
  EXPECT_THROW(outline.use_pass(*lit, "Nope"), Error);
}

TEST(CommandBuffers, ClearBeforeDrawsIsALoadActionAfterDrawsAFullScreenDraw) {
  Fixture f;
  f.add(-2.0f, 1.0f, kRed);
  RenderContext ctx;
  Surface* c = ctx.create_surface("c", PixelFormat::RGBA8_UNORM, kW, kH);
  CommandBuffer cmd;
  cmd.set_render_target({{RenderTargetRef::of(c), LoadAction::Load, StoreAction::Store}});
  cmd.clear_render_target(false, true, kGreen);
  ctx.execute_command_buffer(cmd);
  FrameReport r = ctx.submit();
  EXPECT_EQ(r.passes[0].attachments[0].bytes_loaded, 0u) << "the clear replaced the load";
  EXPECT_EQ(r.passes[0].tiles.fragments_shaded, 0u);
  EXPECT_EQ(c->read(0, 0), kGreen);

  const CullingResults culling = ctx.cull(f.renderers, f.camera);
  ctx.set_render_target({{RenderTargetRef::of(c), LoadAction::Load, StoreAction::Store}});
  ctx.draw_renderers(culling, {{"Test"}}, {});
  ctx.clear_render_target(false, true, kBlue);
  r = ctx.submit();
  EXPECT_EQ(r.passes[0].attachments[0].bytes_loaded, 4u * kW * kH);
  EXPECT_GE(r.passes[0].tiles.fragments_shaded, uint64_t{kW} * kH) << "a clear after draws costs fragments";
  EXPECT_EQ(c->read(kW / 2, kH / 2), kBlue);
}

TEST(CommandBuffers, TemporaryTargetsArePooledByDescriptor) {
  RenderTargetPool pool;
  const RenderTargetDesc a{kW, kH, PixelFormat::RGBA8_UNORM, 1};
  const RenderTargetDesc b{kW, kH, PixelFormat::RGBA16_FLOAT, 1};
  Surface* first = pool.acquire(a, "t");
  EXPECT_NE(pool.acquire(a, "t2"), first) << "in use: a second one is made";
  pool.release(first);
  EXPECT_EQ(pool.acquire(a, "t3"), first) << "released: reused";
  EXPECT_NE(pool.acquire(b, "t4"), first) << "another descriptor: not reused";
  EXPECT_EQ(pool.entries.size(), 3u);
}

// Copies _MainTex (nearest) to the target.
class CopyShader final : public FragmentShader {
 public:
  CopyShader(std::shared_ptr<const Texture2D> t, SamplerDesc s) : t_(std::move(t)), s_(s) {
    s_.mag_filter = s_.min_filter = FilterMode::Nearest;
  }
  void shade(const QuadFragment& q, QuadOutput& out) const override {
    glm::vec2 uv[kQuadLanes];
    for (int lane = 0; lane < kQuadLanes; ++lane) uv[lane] = q.var2(FullScreenVertexShader::kUv, lane);
    t_->sample_quad(s_, uv, out.color[0]);
  }

 private:
  std::shared_ptr<const Texture2D> t_;
  SamplerDesc s_;
};

TEST(CommandBuffers, BlitCopiesThroughTheMaterialPassAndCountsTextureBytes) {
  Shader copy("Copy");
  PassState state;
  state.cull = CullMode::None;
  state.depth_test = false;
  copy.add_pass({"Copy", "", state, [](const DrawContext& ctx) {
                   DrawFunctors d;
                   d.vertex = std::make_unique<FullScreenVertexShader>();
                   SamplerDesc s;
                   auto tex = ctx.texture("_MainTex", &s);
                   d.fragment = std::make_unique<CopyShader>(tex, s);
                   return d;
                 }});
  RenderMaterial material("copy", &copy);
  RenderContext ctx;
  Surface* src = ctx.create_surface("src", PixelFormat::RGBA8_UNORM, kW, kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) src->write(x, y, 0, glm::vec4(x / 255.0f, y / 255.0f, 0.5f, 1.0f));
  CommandBuffer cmd;
  cmd.get_temporary_rt(7, {kW, kH, PixelFormat::RGBA8_UNORM, 1});
  cmd.blit(RenderTargetRef::of(src), RenderTargetRef::temporary(7), &material, "Copy");
  Surface* dst = ctx.create_surface("dst", PixelFormat::RGBA8_UNORM, kW, kH);
  cmd.blit(RenderTargetRef::temporary(7), RenderTargetRef::of(dst), &material, "Copy");
  cmd.release_temporary_rt(7);
  ctx.execute_command_buffer(cmd);
  const FrameReport r = ctx.submit();
  ASSERT_EQ(r.passes.size(), 2u);
  EXPECT_TRUE(dst->bytes() == src->bytes());
  // Each pass reads its whole source once: 4 bytes per texel through 64-byte lines.
  EXPECT_EQ(r.passes[0].texture.bytes_read, 4u * kW * kH);
  EXPECT_EQ(r.passes[0].attachments[0].bytes_loaded, 0u);
  EXPECT_EQ(r.passes[0].attachments[0].bytes_stored, 4u * kW * kH);
}

TEST(CommandBuffers, SkyboxFillsOnlyWhereNothingWasDrawn) {
  Fixture f;
  f.add(-2.0f, 0.5f, kRed);
  Shader depth_tested("DepthTested");
  depth_tested.add_pass({"Main", "Test", PassState{}, color_functors});
  f.renderers[0].material = f.materials[0].get();
  f.materials[0]->shader = &depth_tested;
  RenderContext ctx;
  Surface* c = ctx.create_surface("c", PixelFormat::RGBA8_UNORM, kW, kH);
  Surface* z = ctx.create_surface("z", PixelFormat::D32_FLOAT, kW, kH);
  ctx.set_render_target({{RenderTargetRef::of(c), LoadAction::Clear, StoreAction::Store}},
                        TargetBinding{RenderTargetRef::of(z), LoadAction::Clear, StoreAction::DontCare});
  ctx.clear_render_target(true, true, glm::vec4(0.0f), 1.0f);
  ctx.draw_renderers(ctx.cull(f.renderers, f.camera), {{"Test"}}, {});
  ctx.draw_skybox(f.camera);
  ctx.submit();
  EXPECT_EQ(c->read(kW / 2, kH / 2), kRed);
  const glm::vec4 corner = c->read(0, 0);
  EXPECT_NE(corner, glm::vec4(0.0f));
  EXPECT_NE(corner, kRed);
}

TEST(CommandBuffers, Errors) {
  Fixture f;
  f.add(-2.0f, 1.0f, kRed);
  auto expect_error = [](RenderContext& ctx, const std::string& phrase) {
    try {
      ctx.submit();
      ADD_FAILURE() << "expected: " << phrase;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
    }
  };
  {
    RenderContext ctx;
    ctx.draw_renderers(ctx.cull(f.renderers, f.camera), {{"Test"}}, {});
    expect_error(ctx, "outside a render pass");
  }
  {
    RenderContext ctx;
    Surface* c = ctx.create_surface("c", PixelFormat::RGBA8_UNORM, kW, kH);
    RenderMaterial m("m", &f.shader);
    ctx.blit(RenderTargetRef::temporary(3), RenderTargetRef::of(c), &m, "Main");
    expect_error(ctx, "temporary render target 3 was not allocated");
  }
  {
    RenderContext ctx;
    Surface* c = ctx.create_surface("c", PixelFormat::RGBA8_UNORM, kW, kH);
    const auto lit = make_lit_shader();
    const auto m = make_lit_material(*lit, Material{});
    ctx.blit(RenderTargetRef::of(c), RenderTargetRef::of(ctx.create_surface("d", PixelFormat::RGBA8_UNORM, kW, kH)),
             m.get(), "ForwardLit");
    expect_error(ctx, "its pass draws meshes but was used for a full-screen draw");
  }
  {
    RenderContext ctx;
    ctx.release_temporary_rt(9);
    expect_error(ctx, "release_temporary_rt: id 9 is not allocated");
  }
}

}  // namespace
}  // namespace ontile
