// `ontile golden --cases FILE.json` (docs/golden.md): a user's case is created with --update,
// then matches; a reference changed beyond the case's tolerance fails (exit 1) and writes the
// actual and diff images; within the tolerance it passes; a malformed or invalid file, a missing
// scene and --cases together with --dir are errors (2, one line naming the file).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli/cli_split_runner.h"
#include "io/image_io.h"
#include "support/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using ontile::test::run_cli_split;
using ontile::test::SplitRun;

class GoldenCasesCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = ontile::test::temp_folder("ontile_golden_cases_" + name);
    fs::create_directories(dir_ / "refs");
    fs::copy_file(fs::path(ONTILE_SOURCE_DIR) / "scenes" / "demo.glb", dir_ / "demo.glb",
                  fs::copy_options::overwrite_existing);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // One case, paths relative to the file; `tolerance` is the JSON object or empty.
  std::string write_cases(const std::string& tolerance, const std::string& file = "cases.json") {
    std::ofstream(dir_ / file) << R"({"cases": [{"name": "demo-toon", "scene": "demo.glb", "pipeline": "cartoon",
      "size": "64x36", "camera": 0, "options": {"normals": "rgba16f"}, "reference": "refs/demo-toon.png")"
                               << (tolerance.empty() ? "" : ", \"tolerance\": " + tolerance) << "}]}";
    return (dir_ / file).string();
  }
  SplitRun run(const std::string& args) {
    return run_cli_split("golden " + args + " --failures " + (dir_ / "failures").string(), dir_);
  }
  static void expect_one_error_line(const SplitRun& r) {
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  }
  fs::path dir_;
};

TEST_F(GoldenCasesCli, UpdateThenMatch) {
  const std::string cases = write_cases("");
  const SplitRun missing = run("--cases " + cases);
  EXPECT_EQ(missing.exit_code, 1) << missing.out << missing.err;
  EXPECT_NE(missing.out.find("MISSING"), std::string::npos) << missing.out;
  const SplitRun update = run("--cases " + cases + " --update");
  ASSERT_EQ(update.exit_code, 0) << update.out << update.err;
  ASSERT_TRUE(fs::exists(dir_ / "refs" / "demo-toon.png"));
  const SplitRun match = run("--cases " + cases);
  EXPECT_EQ(match.exit_code, 0) << match.out << match.err;
  EXPECT_NE(match.out.find("demo-toon"), std::string::npos) << match.out;
  EXPECT_NE(match.out.find("match"), std::string::npos) << match.out;
}

TEST_F(GoldenCasesCli, ADifferenceOverTheToleranceFailsAndWritesImages) {
  ASSERT_EQ(run("--cases " + write_cases("") + " --update").exit_code, 0);
  int w = 0, h = 0;
  const fs::path reference = dir_ / "refs" / "demo-toon.png";
  std::vector<uint8_t> pixels = ontile::read_png_rgba8(reference, w, h);
  pixels[(10 * w + 20) * 4] ^= 4;  // one channel of one pixel off by 4
  ontile::write_png_rgba8(reference, w, h, pixels);

  const SplitRun fail = run("--cases " + write_cases(R"({"max_abs": 3})"));
  EXPECT_EQ(fail.exit_code, 1) << fail.out << fail.err;
  EXPECT_NE(fail.out.find("MISMATCH"), std::string::npos) << fail.out;
  expect_one_error_line(fail);
  EXPECT_TRUE(fs::exists(dir_ / "failures" / "demo-toon.actual.png"));
  EXPECT_TRUE(fs::exists(dir_ / "failures" / "demo-toon.diff.png"));

  fs::remove_all(dir_ / "failures");
  const SplitRun within = run("--cases " + write_cases(R"({"max_abs": 4})"));
  EXPECT_EQ(within.exit_code, 0) << within.out << within.err;
  EXPECT_NE(within.out.find("within the tolerance"), std::string::npos) << within.out;
  const SplitRun counted = run("--cases " + write_cases(R"({"max_abs": 0, "max_pixels": 1})"));
  EXPECT_EQ(counted.exit_code, 0) << counted.out << counted.err;
  EXPECT_FALSE(fs::exists(dir_ / "failures"));
}

TEST_F(GoldenCasesCli, MalformedOrInvalidFilesAreInputErrors) {
  const std::string case_start = R"({"cases": [{"name": "a", "scene": "demo.glb", "pipeline": "lambert", )";
  const std::pair<std::string, std::string> files[] = {
      {R"({"cases": [)", "malformed JSON"},
      {R"({"cases": []})", "empty"},
      {R"({"case": []})", "unknown key"},
      {case_start + R"("reference": "a.png", "tolerence": {}}]})", "tolerence"},
      {case_start + R"("reference": "a.png", "size": "64by36"}]})", "size"},
      {case_start + R"("reference": "a.png", "tolerance": {"max_abs": -1}}]})", "max_abs"},
      {case_start + R"("reference": 3}]})", "reference"},
      {case_start + R"("reference": "a.png"}, )" + case_start.substr(11) + R"("reference": "b.png"}]})",
       "duplicate"},
      {R"({"cases": [{"name": "a", "scene": "none.glb", "pipeline": "lambert", "reference": "a.png"}]})",
       "none.glb"},
      {R"({"cases": [{"name": "../a", "scene": "demo.glb", "pipeline": "lambert", "reference": "a.png"}]})",
       "name"}};
  for (const auto& [json, problem] : files) {
    std::ofstream(dir_ / "bad.json") << json;
    const SplitRun r = run("--cases " + (dir_ / "bad.json").string());
    EXPECT_EQ(r.exit_code, 2) << json << ": " << r.out << r.err;
    EXPECT_TRUE(r.out.empty()) << json << ": " << r.out;
    expect_one_error_line(r);
    EXPECT_NE(r.err.find((dir_ / "bad.json").string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(problem), std::string::npos) << json << ": " << r.err;
  }
  EXPECT_EQ(run("--cases " + (dir_ / "none.json").string()).exit_code, 2);
  const SplitRun with_dir = run("--cases " + write_cases("") + " --dir " + dir_.string());
  EXPECT_EQ(with_dir.exit_code, 2) << with_dir.out << with_dir.err;
  expect_one_error_line(with_dir);
}

}  // namespace
