// The render-graph compiler on small hand-built graphs: culling, each merge rule and its
// not-merged reason, derived load/store actions and transient (memoryless) attachments.
#include <gtest/gtest.h>

#include "context/render_graph_compiler.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr LoadAction kLoad = LoadAction::Load, kClear = LoadAction::Clear, kDontCareLoad = LoadAction::DontCare;
constexpr StoreAction kStore = StoreAction::Store, kDontCare = StoreAction::DontCare;

struct GraphBuilder {
  GraphDecl g;
  int resource(const std::string& name, PixelFormat format = PixelFormat::RGBA8_UNORM, int w = 64, int h = 64,
               int samples = 1) {
    g.resources.push_back({name, format, w, h, samples, glm::vec4(0.0f)});
    return static_cast<int>(g.resources.size()) - 1;
  }
  GraphPassDecl& pass(const std::string& name) {
    g.passes.push_back({});
    g.passes.back().name = name;
    return g.passes.back();
  }
};

std::vector<GraphReason> reasons_for(const CompiledGraph& c, const std::string& pass, const std::string& resource = {}) {
  std::vector<GraphReason> out;
  for (const GraphDecision& d : c.decisions) {
    if (d.pass == pass && d.resource == resource) out.push_back(d.reason);
  }
  return out;
}

CompiledGraph compile(const GraphDecl& g, RenderGraphMode mode, TilerConfig tiler = {}) {
  return compile_render_graph(g, mode, tiler);
}

// Two passes: "a" writes x, "b" reads x at its own pixel and writes the output y.
GraphBuilder own_pixel_chain() {
  GraphBuilder b;
  const int x = b.resource("x"), y = b.resource("y");
  b.pass("a").colors = {{x, kClear, kStore}};
  GraphPassDecl& p = b.pass("b");
  p.colors = {{y, kDontCareLoad, kStore}};
  p.own_pixel_reads = {x};
  b.g.outputs = {y};
  return b;
}

TEST(RenderGraphCompiler, OffRunsEveryPassAsWritten) {
  GraphBuilder b = own_pixel_chain();
  const int unused = b.resource("unused");
  b.pass("side").colors = {{unused, kClear, kStore}};
  const CompiledGraph c = compile(b.g, RenderGraphMode::Off);
  ASSERT_EQ(c.native_passes.size(), 3u);
  EXPECT_TRUE(c.decisions.empty());
  EXPECT_EQ(c.native_passes[1].attachments[0].load, kDontCareLoad);
  EXPECT_EQ(c.native_passes[2].attachments[0].store, kStore);
  EXPECT_TRUE(c.native_passes[1].subpasses[0].inputs.empty()) << "own-pixel reads are textures without merging";
  EXPECT_TRUE(c.resource_backed[0]);
}

TEST(RenderGraphCompiler, CullRemovesUnreadPassesAndAttachments) {
  GraphBuilder b;
  const int x = b.resource("x"), extra = b.resource("extra"), unused = b.resource("unused"), y = b.resource("y");
  b.pass("a").colors = {{x, kClear, kStore}, {extra, kClear, kStore}};
  b.pass("side").colors = {{unused, kClear, kStore}};
  GraphPassDecl& p = b.pass("b");
  p.colors = {{y, kClear, kStore}};
  p.texture_reads = {x};
  b.g.outputs = {y};
  const CompiledGraph c = compile(b.g, RenderGraphMode::Cull);
  EXPECT_EQ(c.pass_culled, (std::vector<bool>{false, true, false}));
  ASSERT_EQ(c.native_passes.size(), 2u);
  EXPECT_EQ(reasons_for(c, "side"), std::vector<GraphReason>{GraphReason::CulledUnread});
  EXPECT_EQ(reasons_for(c, "a", "extra"), std::vector<GraphReason>{GraphReason::CulledUnreadAttachment});
  EXPECT_EQ(c.native_passes[0].attachments[1].store, kDontCare);
  EXPECT_TRUE(c.native_passes[0].attachments[1].memoryless);
  EXPECT_FALSE(c.resource_backed[extra]);
  EXPECT_FALSE(c.resource_backed[unused]);
  EXPECT_EQ(c.native_passes[0].attachments[0].store, kStore);
}

TEST(RenderGraphCompiler, CullKeepsTheWritersALoadingPassNeeds) {
  GraphBuilder b;
  const int x = b.resource("x");
  b.pass("first").colors = {{x, kClear, kStore}};
  b.pass("overwritten").colors = {{x, kClear, kStore}};  // cleared again: "first" is unread
  b.pass("blend").colors = {{x, kLoad, kStore}};
  b.g.outputs = {x};
  const CompiledGraph c = compile(b.g, RenderGraphMode::Cull);
  EXPECT_EQ(c.pass_culled, (std::vector<bool>{true, false, false}));
}

TEST(RenderGraphCompiler, MergesOwnPixelReadsIntoSubpassesWithTransientIntermediates) {
  const CompiledGraph c = compile(own_pixel_chain().g, RenderGraphMode::Merge);
  ASSERT_EQ(c.native_passes.size(), 1u);
  const NativePass& n = c.native_passes[0];
  EXPECT_EQ(n.name, "a + b");
  ASSERT_EQ(n.subpasses.size(), 2u);
  EXPECT_EQ(n.subpasses[1].inputs, std::vector<int>{0});
  EXPECT_EQ(n.subpasses[1].inputs_on_tile, std::vector<int>{0});
  EXPECT_EQ(reasons_for(c, "b"), std::vector<GraphReason>{GraphReason::Merged});
  EXPECT_EQ(reasons_for(c, "b", "x"), std::vector<GraphReason>{GraphReason::TransientNotReadLater});
  EXPECT_EQ(reasons_for(c, "b", "y"),
            (std::vector<GraphReason>{GraphReason::LoadDontCare, GraphReason::StoredOutput}));
  EXPECT_TRUE(n.attachments[0].memoryless);
  EXPECT_FALSE(c.resource_backed[0]);
  EXPECT_EQ(n.attachments[1].store, kStore);
}

TEST(RenderGraphCompiler, EachNotMergedReason) {
  struct Case {
    const char* what;
    GraphReason reason;
    void (*shape)(GraphBuilder&, GraphPassDecl& second, int written);
  };
  const Case cases[] = {
      {"texture read", GraphReason::TextureReadOfOutput,
       [](GraphBuilder&, GraphPassDecl& p, int x) { p.texture_reads = {x}; }},
      {"size", GraphReason::SizeDiffers,
       [](GraphBuilder& b, GraphPassDecl& p, int) { p.colors = {{b.resource("small", PixelFormat::RGBA8_UNORM, 32, 64), kClear, kStore}}; }},
      {"samples", GraphReason::SampleCountDiffers,
       [](GraphBuilder& b, GraphPassDecl& p, int) { p.colors = {{b.resource("msaa", PixelFormat::RGBA8_UNORM, 64, 64, 4), kClear, kStore}}; }},
      {"depth", GraphReason::DepthDiffers,
       [](GraphBuilder& b, GraphPassDecl& p, int) { p.depth = GraphWrite{b.resource("depth 2", PixelFormat::D32_FLOAT), kClear, kStore}; }},
      {"clear", GraphReason::ClearsHeldAttachment,
       [](GraphBuilder&, GraphPassDecl& p, int x) { p.colors.push_back({x, kClear, kStore}); }},
  };
  for (const Case& k : cases) {
    GraphBuilder b;
    const int x = b.resource("x"), depth = b.resource("depth", PixelFormat::D32_FLOAT);
    GraphPassDecl& a = b.pass("a");
    a.colors = {{x, kClear, kStore}};
    a.depth = GraphWrite{depth, kClear, kStore};
    b.pass("b").colors = {{b.resource("y"), kClear, kStore}};
    k.shape(b, b.g.passes[1], x);
    b.g.outputs = {x, depth};  // "a" stays live whatever "b" overwrites
    for (const GraphWrite& w : b.g.passes[1].colors) b.g.outputs.push_back(w.resource);
    if (b.g.passes[1].depth) b.g.outputs.push_back(b.g.passes[1].depth->resource);
    const CompiledGraph c = compile(b.g, RenderGraphMode::Merge);
    EXPECT_EQ(c.native_passes.size(), 2u) << k.what;
    EXPECT_EQ(reasons_for(c, "b"), std::vector<GraphReason>{k.reason}) << k.what;
  }
}

TEST(RenderGraphCompiler, WritingATextureAnEarlierSubpassSamplesIsNotMerged) {
  GraphBuilder b;
  const int x = b.resource("x"), y = b.resource("y");
  b.pass("producer").colors = {{x, kClear, kStore}};
  GraphPassDecl& sampler = b.pass("sampler");
  sampler.colors = {{y, kClear, kStore}};
  sampler.texture_reads = {x};
  b.pass("rewriter").colors = {{y, kLoad, kStore}, {x, kLoad, kStore}};
  b.g.outputs = {x, y};
  const CompiledGraph c = compile(b.g, RenderGraphMode::Merge);
  EXPECT_EQ(reasons_for(c, "sampler"), std::vector<GraphReason>{GraphReason::TextureReadOfOutput});
  EXPECT_EQ(reasons_for(c, "rewriter"), std::vector<GraphReason>{GraphReason::WritesSampledTexture});
}

TEST(RenderGraphCompiler, TileBudgetBlocksAMergeTheSmallestTileCannotHold) {
  GraphBuilder b;
  const int x = b.resource("x", PixelFormat::RGBA32_FLOAT), y = b.resource("y", PixelFormat::RGBA32_FLOAT);
  b.pass("a").colors = {{x, kClear, kStore}};
  GraphPassDecl& p = b.pass("b");
  p.colors = {{y, kClear, kStore}};
  p.own_pixel_reads = {x};
  b.g.outputs = {y};
  TilerConfig small;
  small.tile_size_px = 4;
  small.color_budget_bits_per_px = 32;  // 512 bits a tile: one 128-bit target fits 2x2 pixels, two do not
  EXPECT_EQ(reasons_for(compile(b.g, RenderGraphMode::Merge, small), "b"),
            std::vector<GraphReason>{GraphReason::TileBudgetExceeded});
  EXPECT_EQ(reasons_for(compile(b.g, RenderGraphMode::Merge), "b"), std::vector<GraphReason>{GraphReason::Merged});
}

TEST(RenderGraphCompiler, LoadAndStoreDerivation) {
  GraphBuilder b;
  const int x = b.resource("x"), scratch = b.resource("scratch"), y = b.resource("y");
  b.pass("a").colors = {{x, kLoad, kStore}, {scratch, kDontCareLoad, kStore}};  // Load of nothing
  GraphPassDecl& sampler = b.pass("b");
  sampler.colors = {{y, kClear, kStore}};
  sampler.texture_reads = {x, scratch};
  GraphPassDecl& blend = b.pass("c");
  blend.colors = {{y, kLoad, kStore}};
  blend.texture_reads = {x};
  b.g.outputs = {y};
  const CompiledGraph c = compile(b.g, RenderGraphMode::Merge);
  ASSERT_EQ(c.native_passes.size(), 2u);
  EXPECT_EQ(c.native_passes[0].attachments[0].load, kClear) << "nothing earlier wrote x: Clear, not Load";
  EXPECT_EQ(c.native_passes[0].attachments[1].load, kDontCareLoad);
  EXPECT_EQ(reasons_for(c, "a", "x"), (std::vector<GraphReason>{GraphReason::LoadCleared, GraphReason::StoredReadLater}));
  EXPECT_EQ(reasons_for(c, "a", "scratch"),
            (std::vector<GraphReason>{GraphReason::LoadDontCare, GraphReason::StoredReadLater}));
  EXPECT_EQ(reasons_for(c, "c"), std::vector<GraphReason>{GraphReason::Merged});
  EXPECT_EQ(c.native_passes[1].attachments[0].store, kStore);
  EXPECT_EQ(reasons_for(c, "c", "y"), std::vector<GraphReason>{GraphReason::StoredOutput});
}

TEST(RenderGraphCompiler, LoadKeptWhereAnEarlierRenderPassWrote) {
  GraphBuilder b;
  const int x = b.resource("x"), y = b.resource("y");
  b.pass("a").colors = {{x, kClear, kStore}};
  GraphPassDecl& sampler = b.pass("b");
  sampler.colors = {{y, kClear, kStore}};
  sampler.texture_reads = {x};
  b.pass("c").colors = {{x, kLoad, kStore}};
  b.g.outputs = {x, y};
  const CompiledGraph c = compile(b.g, RenderGraphMode::Merge);
  EXPECT_EQ(reasons_for(c, "c").at(0), GraphReason::WritesSampledTexture);
  EXPECT_EQ(reasons_for(c, "c", "x").at(0), GraphReason::LoadKept);
  EXPECT_EQ(c.native_passes.back().attachments[0].load, kLoad);
}

TEST(RenderGraphCompiler, DepthJoinsAndOtherSubpassesKeepItReadOnly) {
  GraphBuilder b;
  const int x = b.resource("x"), depth = b.resource("depth", PixelFormat::D32_FLOAT), y = b.resource("y");
  GraphPassDecl& a = b.pass("a");
  a.colors = {{x, kClear, kStore}};
  a.depth = GraphWrite{depth, kClear, kStore};
  GraphPassDecl& p = b.pass("b");
  p.colors = {{y, kClear, kStore}};
  p.own_pixel_reads = {depth, x};
  b.g.outputs = {y};
  const CompiledGraph c = compile(b.g, RenderGraphMode::Merge);
  ASSERT_EQ(c.native_passes.size(), 1u);
  const NativePass& n = c.native_passes[0];
  EXPECT_EQ(n.depth_index, 1);
  EXPECT_FALSE(n.subpasses[0].depth_read_only);
  EXPECT_TRUE(n.subpasses[1].depth_read_only);
  EXPECT_EQ(n.subpasses[1].inputs, (std::vector<int>{1, 0}));
  EXPECT_TRUE(n.attachments[1].memoryless);
}

TEST(RenderGraphCompiler, ExternalPassesRunAlwaysBreakMergingAndKeepWhatTheyReadInMemory) {
  GraphBuilder b;
  const int x = b.resource("x"), y = b.resource("y");
  b.pass("a").colors = {{x, kClear, kStore}};
  GraphPassDecl& external = b.pass("feature");
  external.external = true;
  external.texture_reads = {x};
  GraphPassDecl& p = b.pass("b");
  p.colors = {{y, kClear, kStore}};
  p.own_pixel_reads = {x};
  b.pass("side effects only").external = true;
  b.g.outputs = {y};
  const CompiledGraph c = compile(b.g, RenderGraphMode::Merge);
  EXPECT_EQ(c.pass_culled, (std::vector<bool>{false, false, false, false}));
  ASSERT_EQ(c.native_passes.size(), 4u);
  EXPECT_TRUE(c.native_passes[1].external);
  EXPECT_TRUE(c.native_passes[1].attachments.empty());
  EXPECT_EQ(reasons_for(c, "feature"), std::vector<GraphReason>{GraphReason::ExternalPass});
  EXPECT_EQ(reasons_for(c, "b"), std::vector<GraphReason>{GraphReason::ExternalPass});
  EXPECT_EQ(reasons_for(c, "a", "x"), (std::vector<GraphReason>{GraphReason::LoadCleared, GraphReason::StoredReadLater}));
  EXPECT_TRUE(c.resource_backed[x]);
}

TEST(RenderGraphCompiler, AsWrittenOnlyDeclaredMemorylessResourcesStayOutOfMemory) {
  GraphBuilder b;
  const int x = b.resource("x"), scratch = b.resource("scratch depth", PixelFormat::D32_FLOAT),
            lazy = b.resource("lazy depth", PixelFormat::D32_FLOAT);
  b.g.resources[lazy].memoryless = true;
  GraphPassDecl& a = b.pass("a");
  a.colors = {{x, kClear, kStore}};
  a.depth = GraphWrite{scratch, kClear, kDontCare};
  GraphPassDecl& p = b.pass("b");
  p.colors = {{x, kLoad, kStore}};
  p.depth = GraphWrite{lazy, kClear, kDontCare};
  b.g.outputs = {x};
  const CompiledGraph off = compile(b.g, RenderGraphMode::Off);
  EXPECT_FALSE(off.native_passes[0].attachments[1].memoryless) << "a surface the author did not give up";
  EXPECT_TRUE(off.resource_backed[scratch]);
  EXPECT_TRUE(off.native_passes[1].attachments[1].memoryless);
  EXPECT_FALSE(off.resource_backed[lazy]);
  const CompiledGraph merged = compile(b.g, RenderGraphMode::Merge);
  EXPECT_TRUE(merged.native_passes[0].attachments[1].memoryless);
  EXPECT_FALSE(merged.resource_backed[scratch]);
  b.g.passes[1].depth->store = kStore;
  EXPECT_THROW(compile(b.g, RenderGraphMode::Off), Error) << "a memoryless resource cannot be stored";
}

TEST(RenderGraphCompiler, InvalidGraphsAreErrors) {
  GraphBuilder b;
  const int x = b.resource("x");
  b.pass("empty");
  EXPECT_THROW(compile(b.g, RenderGraphMode::Off), Error);
  b.g.passes[0].colors = {{x + 5, kClear, kStore}};
  EXPECT_THROW(compile(b.g, RenderGraphMode::Off), Error);
  b.g.passes[0].colors = {{x, kClear, StoreAction::Resolve}};
  EXPECT_THROW(compile(b.g, RenderGraphMode::Off), Error);
  EXPECT_THROW(parse_render_graph_mode("fast"), Error);
  EXPECT_EQ(parse_render_graph_mode("merge"), RenderGraphMode::Merge);
}

}  // namespace
}  // namespace ontile
