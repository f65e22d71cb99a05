// The `reference`, `accuracy` and `render --aov` verbs as a user runs them: outputs with the
// documented EXR channels, and one clear error line with a non-zero exit for bad arguments.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

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

fs::path temp_folder() { return ontile::test::temp_folder("ontile_reference_cli_test"); }

std::vector<std::string> exr_channels(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return {};
  std::vector<std::string> names = in->spec().channelnames;
  in->close();
  return names;
}

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

TEST(ReferenceCli, ReferenceWritesAllChannels) {
  const fs::path out = temp_folder() / "ref.exr";
  const CliRun r = run_cli("reference --scene " + kDemo + " --size 64x36 --spp 4 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<std::string> expected = {"R", "G", "B", "A", "Z", "primid", "N.x", "N.y", "N.z"};
  EXPECT_EQ(exr_channels(out), expected);
}

TEST(ReferenceCli, RenderAovWritesTheAovChannels) {
  const fs::path dir = temp_folder();
  // One AOV through the CLI (each run costs a process start); the kinds are tested in-process.
  const fs::path out = dir / "normal.exr";
  const CliRun r = run_cli("render --scene " + kDemo + " --size 64x36 --aov normal --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(exr_channels(out), (std::vector<std::string>{"N.x", "N.y", "N.z"}));
}

TEST(ReferenceCli, AccuracyPrintsAndWritesMetrics) {
  const fs::path json = temp_folder() / "acc.json";
  const CliRun r = run_cli("accuracy --scene " + kDemo + " --size 64x36 --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("coverage agreement"), std::string::npos) << r.output;
  std::ifstream f(json);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"coverage_agreement\""), std::string::npos);
  EXPECT_NE(text.find("\"mismatch_edge_ties\""), std::string::npos);
  EXPECT_NE(text.find("\"mismatch_depth_ties\""), std::string::npos);
  EXPECT_NE(r.output.find("depth ties"), std::string::npos) << r.output;
}

TEST(ReferenceCli, BadArgumentsGiveOneErrorLineAndWriteNothing) {
  const fs::path dir = temp_folder();
  const std::string out = (dir / "bad.exr").string();
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {"reference --scene " + kDemo + " --size 8x8 --spp 3 --out " + out, "perfect square"},
      {"reference --scene " + kDemo + " --size 8x8 --out " + (dir / "bad.png").string(), "unsupported output extension"},
      {"accuracy --scene " + kDemo + " --size 8x8 --pipeline cartoon", "only for 'lambert'"},
      {"render --scene " + kDemo + " --size 8x8 --aov depth --out " + (dir / "bad.png").string(), "use an .exr output"},
  };
  for (const Case& c : cases) {
    const CliRun r = run_cli(c.args);
    EXPECT_NE(r.exit_code, 0) << c.args;
    EXPECT_NE(r.output.find("error: "), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
  }
  EXPECT_NE(run_cli("render --scene " + kDemo + " --aov albedo --out " + out).exit_code, 0);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir / "bad.png"));
}

}  // namespace
