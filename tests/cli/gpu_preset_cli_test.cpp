// `ontile render --gpu NAME`, `--transaction-elimination` and `--camera-pan` from the command
// line: a preset renders and says what it set in the report; transaction elimination over
// `--frames` removes every colour write of a static camera and fewer of a panning one; tiles
// other than 16x16 and unknown presets are usage errors (exit 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace {

namespace fs = std::filesystem;

using ontile::test::CliRun;
using ontile::test::run_cli;

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

fs::path temp_folder() { return ontile::test::temp_folder("ontile_gpu_preset_cli_test"); }

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// Colour tile writes eliminated and colour bytes stored in the last pass of a report.
uint64_t sum_over_attachments(const nlohmann::json& report, const char* field) {
  uint64_t total = 0;
  for (const auto& pass : report["passes"]) {
    for (const auto& a : pass["attachments"]) total += a[field].get<uint64_t>();
  }
  return total;
}

TEST(GpuPresetCli, MaliG76RendersAndReportsWhatItSet) {
  const fs::path out = temp_folder() / "g76.png", report = temp_folder() / "g76.json";
  const CliRun r = run_cli("render --scene " + kDemo + " --size 160x96 --threads 2 --gpu mali-g76 --frames 1 --out " +
                           out.string() + " --report " + report.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = read_json(report);
  EXPECT_EQ(j["run"]["gpu"], "mali-g76");
  EXPECT_EQ(j["run"]["afbc"], true);
  EXPECT_EQ(j["run"]["transaction_elimination"], true);
  EXPECT_EQ(j["run"]["transaction_elimination_targets"], "on") << "one CRC render target per pass (Bifrost v7)";
  EXPECT_EQ(j["run"]["idvs"], true);
  EXPECT_EQ(j["run"]["varying_precision"], "fp32") << "the application's choice, not the preset's";
  EXPECT_EQ(j["run"]["texture_compression"], "none") << "the assets' choice, not the preset's";
  EXPECT_EQ(j["run"]["parameter_cache_bytes"], 512 * 1024);
  EXPECT_EQ(j["run"]["texture_cache_bytes"], 512 * 1024);
  // A static camera: the second frame writes no colour tile the first wrote.
  EXPECT_GT(sum_over_attachments(j, "te_tiles_eliminated"), 0u);
}

TEST(GpuPresetCli, APanningCameraEliminatesFewerTiles) {
  const fs::path out = temp_folder() / "pan.png", still = temp_folder() / "still.json",
                 moving = temp_folder() / "moving.json";
  const std::string common = "render --scene " + kDemo + " --size 160x96 --threads 2 --transaction-elimination on "
                             "--frames 1 --out " + out.string();
  ASSERT_EQ(run_cli(common + " --report " + still.string()).exit_code, 0);
  ASSERT_EQ(run_cli(common + " --camera-pan 5 --report " + moving.string()).exit_code, 0);
  const nlohmann::json a = read_json(still), b = read_json(moving);
  EXPECT_EQ(b["run"]["camera_pan_deg_per_frame"], 5.0);
  EXPECT_LT(sum_over_attachments(b, "te_tiles_eliminated"), sum_over_attachments(a, "te_tiles_eliminated"));
  EXPECT_GT(sum_over_attachments(b, "bytes_stored"), sum_over_attachments(a, "bytes_stored"));
}

TEST(GpuPresetCli, MaliG71ComparesOnlyPassesWithOneColourTarget) {
  const fs::path out = temp_folder() / "g71.png", report = temp_folder() / "g71.json";
  const CliRun r = run_cli("render --scene " + kDemo + " --size 160x96 --threads 2 --gpu mali-g71 --out " +
                           out.string() + " --report " + report.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_json(report)["run"]["transaction_elimination_targets"], "single-target-passes");
  const CliRun every = run_cli("render --scene " + kDemo + " --size 160x96 --threads 2 --transaction-elimination "
                               "every-target --out " + out.string() + " --report " + report.string());
  ASSERT_EQ(every.exit_code, 0) << every.output;
  EXPECT_EQ(read_json(report)["run"]["transaction_elimination_targets"], "every-target");
}

TEST(GpuPresetCli, ExplicitOptionsOverrideThePreset) {
  const fs::path out = temp_folder() / "override.png", report = temp_folder() / "override.json";
  const CliRun r = run_cli("render --scene " + kDemo + " --size 96x64 --gpu mali-g76 --afbc off --idvs off --out " +
                           out.string() + " --report " + report.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_json(report)["run"]["afbc"], false);
  EXPECT_EQ(read_json(report)["run"]["idvs"], false);
}

TEST(GpuPresetCli, OtherRulesRender) {
  for (const std::string gpu : {"panfrost", "apple-g13", "adreno-630", "mali-g71"}) {
    const fs::path out = temp_folder() / (gpu + ".png");
    const CliRun r = run_cli("render --scene " + kDemo + " --size 200x120 --threads 2 --gpu " + gpu + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 0) << gpu << ": " << r.output;
  }
}

TEST(GpuPresetCli, BadCombinationsAreUsageErrors) {
  const fs::path out = temp_folder() / "bad.png";
  const std::string base = "render --scene " + kDemo + " --size 64x64 --out " + out.string();
  EXPECT_EQ(run_cli(base + " --gpu no-such-gpu").exit_code, 2);
  const CliRun tile = run_cli(base + " --tile 32 --transaction-elimination on");
  EXPECT_EQ(tile.exit_code, 2);
  EXPECT_NE(tile.output.find("16x16"), std::string::npos) << tile.output;
  EXPECT_EQ(run_cli(base + " --gpu apple-g13 --transaction-elimination on").exit_code, 2);
  EXPECT_EQ(run_cli(base + " --gpu mali-g76 --tile 32").exit_code, 2) << "TE is on in the preset";
}

}  // namespace
