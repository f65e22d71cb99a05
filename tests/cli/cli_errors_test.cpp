// The CLI's error contract, verb by verb (README, "The CLI"): a bad option or input exits with
// code 2, prints nothing on stdout and exactly one line on stderr that starts with "error: "
// and names the option or file, and writes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/cli_runner.h"
#include "cli/cli_split_runner.h"

namespace {

namespace fs = std::filesystem;

using ontile::test::run_cli_split;
using ontile::test::SplitRun;

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

struct BadCase {
  std::string args;
  std::string names;  // what the error line must mention (the option or the file)
};

void expect_usage_errors(const std::vector<BadCase>& cases, const fs::path& scratch, const fs::path& outputs) {
  for (const BadCase& c : cases) {
    const SplitRun r = run_cli_split(c.args, scratch);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(r.out, "") << c.args;
    ASSERT_FALSE(r.err.empty()) << c.args;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << c.args << "\n" << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << c.args << ": not exactly one line\n" << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_TRUE(fs::is_empty(outputs)) << c.args << " wrote into " << outputs;
  }
}

class CliErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    scratch_ = ontile::test::temp_folder("ontile_cli_errors_" + name);
    out_ = scratch_ / "outputs";
    fs::remove_all(out_);
    fs::create_directories(out_);
  }
  void TearDown() override { fs::remove_all(scratch_); }
  std::string out(const std::string& name) const { return (out_ / name).string(); }
  fs::path scratch_, out_;
};

TEST_F(CliErrors, Render) {
  const std::string base = "render --scene " + kDemo + " --out " + out("x.png");
  const std::string missing_scene = (scratch_ / "missing.glb").string();
  const fs::path broken = scratch_ / "broken.gltf";
  std::ofstream(broken) << "{ this is not json";
  expect_usage_errors(
      {
          {base + " --bogus", "--bogus"},
          {base + " --size 99999999999x10", "--size"},
          {base + " --size 10x99999999999", "maximum 16384"},
          {base + " --size 16385x10", "--size"},
          {base + " --size 0x5", "--size"},
          {base + " --size -4x5", "--size"},
          {base + " --size 12", "--size"},
          {base + " --size 1920x1080x3", "--size"},
          {base + " --tile 12", "--tile"},
          {base + " --threads many", "--threads"},
          {base + " --camera -2", "--camera"},
          {base + " --arch gpu", "--arch"},
          {base + " --pipeline nope", "--pipeline"},
          {base + " --set msaa", "--set"},
          {base + " --set msaa=3", "msaa=3"},
          {base + " --set nonsense=1", "nonsense"},
          {base + " --frames 0", "--frames"},
          {base + " --aov albedo", "--aov"},
          {"render --scene " + kDemo + " --out " + out("x.exr") + " --aov depth --set depth=d16", "--aov"},
          {base + " --aov depth", "--out"},
          {base + " --camera 7", kDemo},
          {"render --scene " + kDemo + " --out " + out("x.bmp"), "x.bmp"},
          {"render --scene " + kDemo + " --out " + out("no/x.png"), out("no/x.png")},
          {"render --scene " + kDemo + " --out " + out("x.png") + " --report " + out("no/r.json"), "--report"},
          {"render --scene " + kDemo + " --out " + out("x.png") + " --report " + out("x.png"), "--report"},
          {"render --scene " + kDemo + " --out -", "--out"},
          {"render --scene " + missing_scene + " --out " + out("x.png"), missing_scene},
          {"render --scene " + broken.string() + " --out " + out("x.png"), broken.string()},
          {"render --scene " + kDemo, "--out"},
          {base + " --html " + out("no/r.html"), "--html"},
          {base + " --html " + out("r.htm"), "--html"},
          {base + " --html " + out("x.png"), "--html"},
          {base + " --html -", "--html"},
          {base + " --dump-attachments " + out("none"), "--dump-attachments"},
          {base + " --tile-grid", "--tile-grid"},
          {"render --scene " + kDemo + " --out " + out("x.exr") + " --aov depth --html " + out("r.html"), "--html"},
          {"render --scene " + missing_scene + " --out " + out("x.png") + " --html " + out("r.html"), missing_scene},
      },
      scratch_, out_);
}

TEST_F(CliErrors, GenScene) {
  expect_usage_errors(
      {
          {"gen-scene nope --out " + out("n.glb"), "nope"},
          {"gen-scene demo --size 3 --out " + out("d.glb"), "--size"},
          {"gen-scene atrium --size big --out " + out("a.glb"), "--size"},
          {"gen-scene atrium --size 1000 --out " + out("a.glb"), "size"},
          {"gen-scene demo --out " + out("d.txt"), "--out"},
          {"gen-scene demo --out " + out("no/d.glb"), out("no/d.glb")},
          {"gen-scene demo --bogus --out " + out("d.glb"), "--bogus"},
          {"gen-scene --out " + out("d.glb"), "name"},
          // An unknown option is named before a missing required one (CLI11 checks those first).
          {"gen-scene --bogus", "--bogus"},
          {"render --bogus", "--bogus"},
          {"render --scene " + kDemo + " --bogus", "--bogus"},
      },
      scratch_, out_);
}

TEST_F(CliErrors, PipelinesGoldenAndTheVerbItself) {
  expect_usage_errors(
      {
          {"pipelines --bogus", "--bogus"},
          {"pipelines extra", "extra"},
          {"golden --dir " + out("none"), "--dir"},
          {"golden --bogus", "--bogus"},
          {"golden --cases", "--cases"},
          {"golden --cases " + out("none.json"), out("none.json")},
          {"compare", "ACTUAL"},
          {"compare " + kDemo, "EXPECTED"},
          {"compare " + out("a.png") + " " + out("b.png"), out("a.png")},
          {"compare " + kDemo + " " + kDemo + " --bogus", "--bogus"},
          {"compare " + kDemo + " " + kDemo + " --max-abs x", "--max-abs"},
          {"frobnicate", "frobnicate"},
          {"", "expected one of render"},
          {"--bogus", "--bogus"},
      },
      scratch_, out_);
}

TEST_F(CliErrors, ReferenceAndAccuracy) {
  const std::string ref = "reference --scene " + kDemo + " --size 8x8";
  const std::string acc = "accuracy --scene " + kDemo + " --size 8x8";
  expect_usage_errors(
      {
          {ref + " --spp 3 --out " + out("r.exr"), "--spp"},
          {ref + " --spp x --out " + out("r.exr"), "--spp"},
          {ref + " --out " + out("r.png"), "--out"},
          {ref + " --out " + out("no/r.exr"), out("no/r.exr")},
          {"reference --scene " + kDemo + " --size 8x99999999999 --out " + out("r.exr"), "--size"},
          {ref, "--out"},
          {acc + " --pipeline cartoon", "--pipeline"},
          {acc + " --json " + out("no/a.json"), "--json"},
          {"accuracy --scene " + kDemo + " --size 1x0", "--size"},
          {acc + " --threads -1", "--threads"},
      },
      scratch_, out_);
}

TEST_F(CliErrors, StudyAndSweep) {
  const std::string study = "study deferred --scene " + kDemo + " --size 32x18";
  const std::string sweep = "sweep --scene " + kDemo + " --size 32x18 --frames 1 --spp 4";
  const std::string outputs = " --csv " + out("s.csv") + " --plot " + out("s.svg");
  expect_usage_errors(
      {
          {"study", "expected one of deferred"},
          {"study shallow --scene " + kDemo, "shallow"},
          {study + " --tile 12", "--tile"},
          {study + " --frames 0", "--frames"},
          {study + " --markdown " + out("no/s.md"), "--markdown"},
          {study + " --json " + out("no/s.json"), "--json"},
          {study + " --json " + out("s.md") + " --markdown " + out("s.md"), "--json"},
          {"study architecture --scene " + kDemo + " --size 32x18 --tiles 8,12", "--tiles"},
          {"study architecture --scene " + kDemo + " --size 32x18 --pipelines lambert,nosuch", "nosuch"},
          {"study architecture --scene " + kDemo + " --size 32x18 --json " + out("no/a.json"), "--json"},
          {"study deferred --scene " + kDemo + " --size 2x", "--size"},
          {sweep + " --spp 5" + outputs, "--spp"},
          {sweep + " --csv " + out("s.txt") + " --plot " + out("s.svg"), "--csv"},
          {sweep + " --csv " + out("s.csv") + " --plot " + out("s.png"), "--plot"},
          {sweep + " --csv " + out("s.csv") + " --plot " + out("no/s.svg"), "--plot"},
          {sweep + " --csv " + out("s.csv") + " --plot -", "--plot"},
          {"sweep --scene " + kDemo + " --size 99999999999x1" + outputs, "--size"},
          {sweep + " --plot " + out("s.svg"), "--csv"},
      },
      scratch_, out_);
}

// --help and --version are not errors: exit 0, text on stdout.
TEST_F(CliErrors, HelpAndVersionExitZero) {
  for (const char* args : {"--help", "render --help", "gen-scene --help", "pipelines --help", "golden --help",
                           "reference --help", "accuracy --help", "study --help", "study deferred --help",
                           "sweep --help", "compare --help", "diff --help"}) {
    const SplitRun r = run_cli_split(args, scratch_);
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    EXPECT_NE(r.out.find("--help"), std::string::npos) << args;
  }
  const SplitRun v = run_cli_split("--version", scratch_);
  EXPECT_EQ(v.exit_code, 0) << v.err;
  EXPECT_EQ(v.out.rfind("ontile ", 0), 0u) << v.out;
  EXPECT_NE(v.out.find_first_of("0123456789"), std::string::npos) << v.out;
}

}  // namespace
