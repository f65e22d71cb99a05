// The example pipeline of docs/context-api.md (`graph-example`): registered by itself, the same
// image in every --render-graph mode, attachment bytes that follow from its passes exactly, and
// the doc shows the file as it is compiled.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "pipelines/kit/render_frame.h"
#include "scene/gltf_loader.h"

namespace ontile {
namespace {

const std::string kSource = std::string(ONTILE_SOURCE_DIR);
constexpr int kWidth = 200, kHeight = 112;
constexpr uint64_t kTargetBytes = uint64_t(kWidth) * kHeight * 4;  // RGBA8 and D32F alike

RenderedFrame render(const Scene& scene, RenderGraphMode mode) {
  RenderSettings s;
  s.pipeline = "graph-example";
  s.width_px = kWidth;
  s.height_px = kHeight;
  s.context.threads = 2;
  s.context.render_graph = mode;
  return render_frame(scene, s);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(GraphExamplePipeline, RegistersItself) {
  const std::vector<std::string> names = pipeline_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "graph-example"), names.end());
  EXPECT_EQ(make_pipeline("graph-example")->name(), "graph-example");
}

TEST(GraphExamplePipeline, BytesFollowFromItsPassesInEveryMode) {
  const Scene scene = load_gltf(kSource + "/scenes/demo.glb");
  const RenderedFrame off = render(scene, RenderGraphMode::Off);
  const RenderedFrame cull = render(scene, RenderGraphMode::Cull);
  const RenderedFrame merge = render(scene, RenderGraphMode::Merge);
  auto category = [](const RenderedFrame& f, const std::string& name) {
    return f.outputs.report.bytes_by_category().at(name);
  };
  // As written: depth stored by the prepass and the opaques, loaded by the opaques and the
  // transparents; colour stored by the opaques and the transparents, loaded by the
  // transparents; the unread sky stored once.
  EXPECT_EQ(category(off, "attachment_store"), 5 * kTargetBytes);
  EXPECT_EQ(category(off, "attachment_load"), 3 * kTargetBytes);
  // cull: the sky pass is gone, every other store is read later.
  EXPECT_EQ(category(cull, "attachment_store"), 4 * kTargetBytes);
  EXPECT_EQ(category(cull, "attachment_load"), 3 * kTargetBytes);
  // merge: one render pass, depth transient, colour cleared on tile and stored once.
  EXPECT_EQ(category(merge, "attachment_store"), kTargetBytes);
  EXPECT_EQ(category(merge, "attachment_load"), 0u);
  ASSERT_TRUE(merge.outputs.report.graph);
  const GraphReport& g = *merge.outputs.report.graph;
  ASSERT_EQ(g.native_passes.size(), 1u);
  EXPECT_EQ(g.native_passes[0].subpasses, (std::vector<std::string>{"depth prepass", "opaques", "transparents"}));
  std::vector<std::pair<std::string, GraphReason>> pass_decisions;
  for (const GraphDecision& d : g.decisions) {
    if (d.resource.empty()) pass_decisions.emplace_back(d.pass, d.reason);
  }
  EXPECT_EQ(pass_decisions, (std::vector<std::pair<std::string, GraphReason>>{
                                {"opaques", GraphReason::Merged},
                                {"transparents", GraphReason::Merged},
                                {"sky for nobody", GraphReason::CulledUnread}}));
  EXPECT_EQ(off.outputs.color->bytes(), merge.outputs.color->bytes());
  EXPECT_EQ(off.outputs.color->bytes(), cull.outputs.color->bytes());
}

TEST(GraphExamplePipeline, TheGuideShowsTheCompiledFile) {
  const std::string code = read_text(kSource + "/src/pipelines/examples/graph_example_pipeline.cpp");
  const std::string guide = read_text(kSource + "/docs/context-api.md");
  ASSERT_FALSE(code.empty());
  EXPECT_NE(guide.find("```cpp\n" + code + "```"), std::string::npos)
      << "docs/context-api.md must quote src/pipelines/examples/graph_example_pipeline.cpp verbatim";
}

}  // namespace
}  // namespace ontile
