// Progress on stderr: with --progress, the long verbs say what runs, n of N and the elapsed time;
// without it and with stderr not a terminal (as here, a pipe), they print none of it.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using ontile::test::CliRun;
using ontile::test::run_cli;

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

TEST(ProgressCli, RenderFramesCountsTimedFrames) {
  const fs::path out = ontile::test::temp_folder("ontile_progress_cli_test") / "frames.png";
  const std::string args = "render --scene " + kDemo + " --size 64x36 --threads 2 --frames 2 --out " + out.string();
  const CliRun quiet = run_cli(args);
  ASSERT_EQ(quiet.exit_code, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("render: "), std::string::npos) << quiet.output;
  const CliRun shown = run_cli(args + " --progress");
  ASSERT_EQ(shown.exit_code, 0) << shown.output;
  EXPECT_NE(shown.output.find("render: 0/2 warm-up frame, "), std::string::npos) << shown.output;
  EXPECT_NE(shown.output.find("render: 1/2 timed frame, "), std::string::npos) << shown.output;
  EXPECT_NE(shown.output.find("render: 2/2 timed frame, "), std::string::npos) << shown.output;
}

TEST(ProgressCli, ReferenceAndAccuracyReportTheirSteps) {
  const fs::path out = ontile::test::temp_folder("ontile_progress_cli_test") / "reference.exr";
  const CliRun reference = run_cli("reference --scene " + kDemo + " --size 16x16 --progress --out " + out.string());
  ASSERT_EQ(reference.exit_code, 0) << reference.output;
  EXPECT_NE(reference.output.find("reference: 8/8 rows of quads ray-cast, "), std::string::npos) << reference.output;
  const CliRun accuracy = run_cli("accuracy --scene " + kDemo + " --size 32x18 --threads 2 --progress");
  ASSERT_EQ(accuracy.exit_code, 0) << accuracy.output;
  for (const char* step : {"accuracy: 0/3 rasterizing", "accuracy: 1/3 ray-casting the reference",
                           "accuracy: 2/3 comparing", "accuracy: 3/3 done"}) {
    EXPECT_NE(accuracy.output.find(step), std::string::npos) << step << "\n" << accuracy.output;
  }
}

}  // namespace
