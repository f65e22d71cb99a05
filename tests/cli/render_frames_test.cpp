// `ontile render --frames N`: the CLI's own timing mode prints the frame count, median and
// minimum after the usual summary and still writes the image; N < 1 is a usage error (exit 2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "support/cli_runner.h"

namespace {

namespace fs = std::filesystem;

using ontile::test::CliRun;
using ontile::test::run_cli;

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

fs::path temp_folder() { return ontile::test::temp_folder("ontile_render_frames_test"); }

// The number after "key: " on the line starting with it; NaN when no such line.
double value_after(const std::string& output, const std::string& key) {
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(key + ": ", 0) == 0) return std::strtod(line.c_str() + key.size() + 2, nullptr);
  }
  return std::nan("");
}

TEST(RenderFrames, PrintsMedianAndMinimumAndWritesTheLastFrame) {
  const fs::path out = temp_folder() / "frames.png";
  const CliRun r = run_cli("render --scene " + kDemo + " --size 160x90 --threads 2 --frames 3 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("frames: 3 after 1 warm-up\n"), std::string::npos) << r.output;
  const double median = value_after(r.output, "median_ms"), min = value_after(r.output, "min_ms");
  EXPECT_GT(min, 0.0) << r.output;
  EXPECT_GE(median, min) << r.output;
  EXPECT_NE(r.output.find("external traffic"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out));
}

TEST(RenderFrames, WorksWithAnAov) {
  const fs::path out = temp_folder() / "ids.exr";
  const CliRun r = run_cli("render --scene " + kDemo + " --size 160x90 --aov primitive_id --frames 1 --out " +
                           out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("frames: 1 after 1 warm-up\n"), std::string::npos) << r.output;
  EXPECT_GT(value_after(r.output, "min_ms"), 0.0) << r.output;
  EXPECT_TRUE(fs::exists(out));
}

TEST(RenderFrames, WithoutTheOptionNoTimesArePrinted) {
  const fs::path out = temp_folder() / "once.png";
  const CliRun r = run_cli("render --scene " + kDemo + " --size 160x90 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("median_ms"), std::string::npos) << r.output;
}

TEST(RenderFrames, ACountBelowOneIsAnErrorWithExitCode2) {
  const fs::path out = temp_folder() / "never.png";
  for (const char* bad : {"0", "-3"}) {
    const CliRun r = run_cli("render --scene " + kDemo + " --size 160x90 --frames " + std::string(bad) +
                             " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.output;
    EXPECT_EQ(r.output, "error: --frames " + std::string(bad) + ": expected a frame count >= 1\n");
  }
  const CliRun text = run_cli("render --scene " + kDemo + " --frames many --out " + out.string());
  EXPECT_NE(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("--frames"), std::string::npos) << text.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
