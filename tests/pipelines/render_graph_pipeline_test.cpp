// Pipelines written as render graphs: deferred-classic merged moves exactly deferred-subpass's
// bytes with the same image; cartoon-multipass merges what its reads allow and reports why;
// universal merges its prepass into the forward pass;
// images are bit-identical across --render-graph off, cull and merge; a culled pass costs
// nothing.
#include <gtest/gtest.h>

#include "context/render_graph.h"
#include "pipelines/kit/render_frame.h"
#include "scene/gltf_loader.h"

namespace ontile {
namespace {

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

RenderedFrame render(const Scene& scene, const std::string& pipeline, RenderGraphMode mode,
                     std::vector<std::pair<std::string, std::string>> options = {}) {
  RenderSettings s;
  s.pipeline = pipeline;
  s.width_px = 200;
  s.height_px = 112;
  s.context.threads = 2;
  s.context.render_graph = mode;
  for (const auto& [key, value] : options) s.options.set(key, value);
  return render_frame(scene, s);
}

std::vector<uint8_t> image(const RenderedFrame& f) { return f.outputs.color->bytes(); }

TEST(RenderGraphPipelines, DeferredClassicMergedMovesDeferredSubpassBytes) {
  const Scene scene = load_gltf(kDemo);
  for (const std::string preset : {"unity", "vulkan-samples", "vulkan-samples-large"}) {
    for (const std::string tonemap : {"on", "off"}) {
      const std::vector<std::pair<std::string, std::string>> options{{"gbuffer", preset}, {"tonemap", tonemap}};
      const RenderedFrame merged = render(scene, "deferred-classic", RenderGraphMode::Merge, options);
      const RenderedFrame subpass = render(scene, "deferred-subpass", RenderGraphMode::Off, options);
      const FrameReport& m = merged.outputs.report;
      const FrameReport& s = subpass.outputs.report;
      const std::string what = preset + ", tonemap " + tonemap;
      EXPECT_EQ(m.bytes_by_category(), s.bytes_by_category()) << what;
      EXPECT_EQ(m.bytes_read(), s.bytes_read()) << what;
      EXPECT_EQ(m.bytes_written(), s.bytes_written()) << what;
      ASSERT_EQ(m.passes.size(), 1u) << what;
      ASSERT_EQ(s.passes.size(), 1u) << what;
      EXPECT_EQ(m.passes[0].tile_width_px * m.passes[0].tile_height_px,
                s.passes[0].tile_width_px * s.passes[0].tile_height_px) << what;
      EXPECT_EQ(m.passes[0].texture.bytes_read, s.passes[0].texture.bytes_read) << what;
      EXPECT_EQ(m.passes[0].tiles.fragments_shaded, s.passes[0].tiles.fragments_shaded) << what;
      for (const AttachmentTraffic& a : s.passes[0].attachments) {
        bool found = false;
        for (const AttachmentTraffic& b : m.passes[0].attachments) {
          if (b.name != a.name) continue;
          found = true;
          EXPECT_EQ(b.transient, a.transient) << what << ": " << a.name;
          EXPECT_EQ(b.bytes_loaded, a.bytes_loaded) << what << ": " << a.name;
          EXPECT_EQ(b.bytes_stored, a.bytes_stored) << what << ": " << a.name;
        }
        EXPECT_TRUE(found) << what << ": " << a.name;
      }
      EXPECT_EQ(image(merged), image(subpass)) << what;
    }
  }
}

TEST(RenderGraphPipelines, ImagesAreBitIdenticalAcrossModes) {
  const Scene scene = load_gltf(kDemo);
  for (const std::string pipeline : {"deferred-classic", "cartoon-multipass", "universal"}) {
    const RenderedFrame off = render(scene, pipeline, RenderGraphMode::Off);
    EXPECT_FALSE(off.outputs.report.graph) << pipeline << ": off reports as before, no graph section";
    for (RenderGraphMode mode : {RenderGraphMode::Cull, RenderGraphMode::Merge}) {
      const RenderedFrame f = render(scene, pipeline, mode);
      EXPECT_EQ(image(f), image(off)) << pipeline << " " << render_graph_mode_name(mode);
      ASSERT_TRUE(f.outputs.report.graph);
      EXPECT_EQ(f.outputs.report.graph->mode, render_graph_mode_name(mode));
    }
    // Nothing in these pipelines is unread: cull moves the same bytes as off.
    const RenderedFrame cull = render(scene, pipeline, RenderGraphMode::Cull);
    EXPECT_EQ(cull.outputs.report.bytes_by_category(), off.outputs.report.bytes_by_category()) << pipeline;
  }
}

TEST(RenderGraphPipelines, CartoonMultipassMergesWhatItsReadsAllow) {
  const Scene scene = load_gltf(kDemo);
  const RenderedFrame merged = render(scene, "cartoon-multipass", RenderGraphMode::Merge);
  const RenderedFrame off = render(scene, "cartoon-multipass", RenderGraphMode::Off);
  ASSERT_TRUE(merged.outputs.report.graph);
  const GraphReport& g = *merged.outputs.report.graph;
  auto reason = [&](const std::string& pass, const std::string& resource) -> std::vector<GraphReason> {
    std::vector<GraphReason> out;
    for (const GraphDecision& d : g.decisions) {
      if (d.pass == pass && d.resource == resource) out.push_back(d.reason);
    }
    return out;
  };
  // Each buffer pass tests against its own transient depth: one depth per native pass.
  EXPECT_EQ(reason("toon normals", ""), std::vector<GraphReason>{GraphReason::DepthDiffers});
  EXPECT_EQ(reason("toon border", ""), std::vector<GraphReason>{GraphReason::DepthDiffers});
  EXPECT_EQ(reason("toon depth", ""), std::vector<GraphReason>{GraphReason::DepthDiffers});
  // The Sobel pass samples neighbours: a texture read, so its inputs are stored.
  const std::string edges = g.passes.back().name;
  EXPECT_EQ(reason(edges, ""), std::vector<GraphReason>{GraphReason::TextureReadOfOutput});
  EXPECT_EQ(reason("toon colour", "color"), (std::vector<GraphReason>{GraphReason::LoadCleared, GraphReason::StoredReadLater}));
  EXPECT_EQ(reason("toon normals", "normals"), (std::vector<GraphReason>{GraphReason::LoadCleared, GraphReason::StoredReadLater}));
  EXPECT_EQ(reason("toon border", "border"), (std::vector<GraphReason>{GraphReason::LoadCleared, GraphReason::StoredReadLater}));
  EXPECT_EQ(reason("toon depth", "depth"), (std::vector<GraphReason>{GraphReason::LoadCleared, GraphReason::StoredReadLater}));
  EXPECT_EQ(reason("toon colour", "depth"), (std::vector<GraphReason>{GraphReason::LoadCleared, GraphReason::TransientNotReadLater}));
  EXPECT_EQ(reason(edges, "final"), (std::vector<GraphReason>{GraphReason::LoadDontCare, GraphReason::StoredOutput}));
  EXPECT_EQ(g.native_passes.size(), 5u);
  // Already written the cheapest way: merging changes no byte.
  EXPECT_EQ(merged.outputs.report.bytes_by_category(), off.outputs.report.bytes_by_category());
  const nlohmann::json json = frame_report_json(merged.outputs.report);
  ASSERT_TRUE(json.contains("graph"));
  bool stored_reason_in_json = false;
  for (const nlohmann::json& d : json["graph"]["decisions"]) {
    if (d["pass"] == "toon normals" && d.value("resource", "") == "normals") {
      stored_reason_in_json |= d["decision"] == "stored" && d["reason"] == "read later";
    }
  }
  EXPECT_TRUE(stored_reason_in_json) << json["graph"].dump(2);
}

TEST(RenderGraphPipelines, UniversalMergesItsPrepassIntoTheForwardPass) {
  const Scene scene = load_gltf(kDemo);
  const RenderedFrame off = render(scene, "universal", RenderGraphMode::Off);
  const RenderedFrame merged = render(scene, "universal", RenderGraphMode::Merge);
  ASSERT_TRUE(merged.outputs.report.graph);
  const GraphReport& g = *merged.outputs.report.graph;
  std::vector<std::pair<std::string, GraphReason>> pass_decisions;
  for (const GraphDecision& d : g.decisions) {
    if (d.resource.empty()) pass_decisions.emplace_back(d.pass, d.reason);
  }
  EXPECT_EQ(pass_decisions, (std::vector<std::pair<std::string, GraphReason>>{
                                {"DepthNormalPrepass", GraphReason::SizeDiffers},
                                {"ForwardRendering", GraphReason::Merged},
                                {"CopyColor", GraphReason::ExternalPass},
                                {"ScreenSpaceOutline", GraphReason::ExternalPass},
                                {"PostProcessing", GraphReason::ExternalPass}}));
  // The forward pass no longer loads the prepass depth; everything else moves the same bytes.
  std::map<std::string, uint64_t> expected = off.outputs.report.bytes_by_category();
  expected["attachment_load"] -= 200u * 112u * 4u;
  EXPECT_EQ(merged.outputs.report.bytes_by_category(), expected);
  EXPECT_EQ(image(merged), image(off));
}

TEST(RenderGraphPipelines, ACulledPassCostsNothing) {
  auto run = [](RenderGraphMode mode) {
    ContextConfig config;
    config.threads = 2;
    config.render_graph = mode;
    RenderContext ctx(config);
    RenderGraph graph;
    const GraphResource shown = graph.create({"shown", PixelFormat::RGBA8_UNORM, 64, 32, 1, glm::vec4(0.5f)});
    const GraphResource unread = graph.create({"unread", PixelFormat::RGBA16_FLOAT, 64, 32, 1, glm::vec4(1.0f)});
    graph.add_pass("shown").write_color(shown, LoadAction::Clear, StoreAction::Store);
    graph.add_pass("unread").write_color(unread, LoadAction::Clear, StoreAction::Store);
    graph.mark_output(shown);
    graph.execute(ctx);
    return ctx.submit();
  };
  const FrameReport off = run(RenderGraphMode::Off);
  const FrameReport cull = run(RenderGraphMode::Cull);
  ASSERT_EQ(off.passes.size(), 2u);
  EXPECT_EQ(off.passes[1].bytes_written(), 64u * 32 * 8) << "as written, the unread pass stores its target";
  ASSERT_EQ(cull.passes.size(), 1u);
  EXPECT_EQ(cull.passes[0].name, "shown");
  EXPECT_EQ(cull.bytes_written(), off.passes[0].bytes_written());
  EXPECT_EQ(cull.bytes_read(), off.passes[0].bytes_read());
  ASSERT_TRUE(cull.graph);
  EXPECT_TRUE(cull.graph->passes[1].culled);
  EXPECT_EQ(cull.graph->native_passes.size(), 1u);
}

}  // namespace
}  // namespace ontile
