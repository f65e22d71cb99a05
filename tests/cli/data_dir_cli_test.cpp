// Where the CLI finds its bundled data (apps/ontile/data_dir.cpp): $ONTILE_DATA_DIR when set,
// else share/ontile beside the binary, which the build tree links to the sources. No source
// path is compiled in, so the variable really decides.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>

#include "support/cli_runner.h"

namespace {

namespace fs = std::filesystem;

struct DataDirRun {
  int exit_code = -1;
  std::string output;
};

DataDirRun run_with_data_dir(const std::string& data_dir, const std::string& args) {
  const std::string cmd = "ONTILE_DATA_DIR='" + data_dir + "' " + std::string(ONTILE_CLI) + " " + args + " 2>&1";
  DataDirRun r;
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

TEST(DataDir, TheEnvironmentVariableChoosesTheGoldenFolder) {
  const fs::path empty = ontile::test::temp_folder("ontile_data_dir_empty");
  const DataDirRun r = run_with_data_dir(empty.string(), "golden");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("error: --dir " + (empty / "golden").string()), std::string::npos) << r.output;
  fs::remove_all(empty);
}

TEST(DataDir, TheBuildTreeLinksTheSourcesBesideTheBinary) {
  const fs::path data = fs::path(ONTILE_CLI).parent_path() / "share" / "ontile";
  EXPECT_TRUE(fs::equivalent(data / "scenes" / "demo.glb", fs::path(ONTILE_SOURCE_DIR) / "scenes" / "demo.glb"));
  EXPECT_TRUE(fs::equivalent(data / "golden", fs::path(ONTILE_SOURCE_DIR) / "golden"));
}

}  // namespace
