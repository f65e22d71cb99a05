// `ontile render --render-graph`: merge prints the decisions after the traffic table and writes
// them under "graph" in the JSON report; off writes no graph section; a bad mode is a usage
// error (exit 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using ontile::test::CliRun;
using ontile::test::run_cli;

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

nlohmann::json render_report(const std::string& mode, std::string* output) {
  const fs::path folder = ontile::test::temp_folder("ontile_render_graph_cli_test");
  const fs::path out = folder / (mode + ".png"), report = folder / (mode + ".json");
  const CliRun r = run_cli("render --scene " + kDemo + " --pipeline deferred-classic --size 160x90 --threads 2" +
                           " --render-graph " + mode + " --out " + out.string() + " --report " + report.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  *output = r.output;
  std::ifstream f(report);
  return nlohmann::json::parse(f);
}

TEST(RenderGraphCli, MergePrintsAndReportsEveryDecision) {
  std::string output;
  const nlohmann::json report = render_report("merge", &output);
  EXPECT_NE(output.find("render graph (merge)"), std::string::npos) << output;
  EXPECT_NE(output.find("only own-pixel reads of earlier outputs"), std::string::npos) << output;
  ASSERT_TRUE(report.contains("graph"));
  EXPECT_EQ(report["graph"]["mode"], "merge");
  EXPECT_EQ(report["graph"]["native_passes"].size(), 1u);
  EXPECT_EQ(report["passes"].size(), 1u);
  bool lighting_merged = false;
  for (const nlohmann::json& d : report["graph"]["decisions"]) {
    ASSERT_TRUE(d.contains("pass") && d.contains("decision") && d.contains("reason")) << d.dump();
    lighting_merged |= d["pass"] == "lighting" && d["decision"] == "merged";
  }
  EXPECT_TRUE(lighting_merged) << report["graph"].dump(2);
}

TEST(RenderGraphCli, OffWritesNoGraphSection) {
  std::string output;
  const nlohmann::json report = render_report("off", &output);
  EXPECT_FALSE(report.contains("graph"));
  EXPECT_EQ(output.find("render graph"), std::string::npos) << output;
}

TEST(RenderGraphCli, AnUnknownModeIsAUsageError) {
  const CliRun r = run_cli("render --scene " + kDemo + " --out /tmp/never.png --render-graph fast");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--render-graph"), std::string::npos) << r.output;
}

}  // namespace
