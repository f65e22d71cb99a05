// The `ontile` CLI as a user runs it: bad input gives one clear error line and a non-zero
// exit with nothing written; good input renders and prints the summary.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

#include "support/cli_runner.h"

namespace {

namespace fs = std::filesystem;

using ontile::test::CliRun;
using ontile::test::run_cli;

fs::path temp_folder() { return ontile::test::temp_folder("ontile_cli_test"); }

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

TEST(Cli, RendersTheDemoAndPrintsTheSummary) {
  const fs::path out = temp_folder() / "demo.png", report = temp_folder() / "demo.json";
  const CliRun r = run_cli("render --scene " + kDemo + " --size 320x180 --threads 2 --out " +
                        out.string() + " --report " + report.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("320x180"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("external traffic"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out));
  std::ifstream f(report);
  const std::string json((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("\"bytes_written\""), std::string::npos);
}

TEST(Cli, EveryVerbHasHelp) {
  for (const char* verb : {"render", "gen-scene", "pipelines"}) {
    const CliRun r = run_cli(std::string(verb) + " --help");
    EXPECT_EQ(r.exit_code, 0) << verb;
    EXPECT_NE(r.output.find("--help"), std::string::npos) << verb;
  }
}

void expect_error(const std::string& args, const std::string& phrase) {
  const CliRun r = run_cli(args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
  EXPECT_NE(r.output.find(phrase), std::string::npos) << args << "\n" << r.output;
}

TEST(Cli, BadInputGivesAClearErrorAndNoOutput) {
  const fs::path dir = temp_folder();
  const fs::path out = dir / "never.png";
  expect_error("render --scene " + kDemo + " --out " + out.string() + " --bogus", "--bogus");
  expect_error("render --scene " + (dir / "missing.glb").string() + " --out " + out.string(), "missing.glb");
  expect_error("render --scene " + kDemo + " --out " + out.string() + " --size 0x5", "--size");
  expect_error("render --scene " + kDemo + " --out " + out.string() + " --size 99999x10", "size");
  expect_error("render --scene " + kDemo + " --out " + out.string() + " --tile 12", "--tile");
  expect_error("render --scene " + kDemo + " --out " + out.string() + " --camera 7", "camera 7");
  expect_error("render --scene " + kDemo + " --out " + out.string() + " --pipeline nope", "unknown pipeline");
  expect_error("render --scene " + kDemo + " --out " + (dir / "x.bmp").string(), "x.bmp");
  const fs::path broken = dir / "broken.gltf";
  std::ofstream(broken) << "{ this is not json";
  expect_error("render --scene " + broken.string() + " --out " + out.string(), "error: " + broken.string());
  expect_error("gen-scene nope --out " + (dir / "n.glb").string(), "nope");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir / "x.bmp"));
  EXPECT_FALSE(fs::exists(dir / "n.glb"));
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
}

TEST(Cli, GenSceneReproducesTheBundledDemoByteForByte) {
  const fs::path out = temp_folder() / "demo.glb";
  ASSERT_EQ(run_cli("gen-scene demo --out " + out.string()).exit_code, 0);
  std::ifstream a(out, std::ios::binary), b(kDemo, std::ios::binary);
  const std::string x((std::istreambuf_iterator<char>(a)), {}), y((std::istreambuf_iterator<char>(b)), {});
  EXPECT_TRUE(x == y) << "scenes/demo.glb is stale: run `build/ontile gen-scene demo --out scenes/demo.glb`";
}

}  // namespace

// More threads than cores (determinism is tested at 7 and 16 threads on 2-core machines): the
// render runs them without oneTBB's "number of workers is limited" warning on stderr.
TEST(Cli, MoreThreadsThanCoresRunWithoutAWarning) {
  const fs::path out = temp_folder() / "threads.png";
  const CliRun r = run_cli("render --scene " + kDemo + " --size 128x72 --threads 17 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("TBB Warning"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("on 17 threads"), std::string::npos) << r.output;
}
