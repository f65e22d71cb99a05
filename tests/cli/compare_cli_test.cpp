// `ontile compare` (README, "Golden tests from your own suite"): identical images match (PSNR
// inf), differences within --max-abs or within --max-pixels match, more is a mismatch (exit 1,
// one error line), images of different sizes are a mismatch, a missing file or bad option an
// error (2); EXR images are compared in float values; --diff writes the diff picture.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli_split_runner.h"
#include "io/image_io.h"
#include "support/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using ontile::test::run_cli_split;
using ontile::test::SplitRun;

class CompareCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = ontile::test::temp_folder("ontile_compare_" + name);
    // A 16x8 gradient and a copy whose pixel (3, 2) has green changed by 2 and (5, 4) blue by 3.
    pixels_.resize(16 * 8 * 4);
    for (size_t i = 0; i < pixels_.size(); ++i) pixels_[i] = static_cast<uint8_t>(i % 4 == 3 ? 255 : (i * 7) % 200);
    changed_ = pixels_;
    changed_[(2 * 16 + 3) * 4 + 1] += 2;
    changed_[(4 * 16 + 5) * 4 + 2] += 3;
    ontile::write_png_rgba8(path("a.png"), 16, 8, pixels_);
    ontile::write_png_rgba8(path("same.png"), 16, 8, pixels_);
    ontile::write_png_rgba8(path("b.png"), 16, 8, changed_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  SplitRun run(const std::string& args) { return run_cli_split("compare " + args, dir_); }
  static void expect_one_error_line(const SplitRun& r) {
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  }
  fs::path dir_;
  std::vector<uint8_t> pixels_, changed_;
};

TEST_F(CompareCli, IdenticalImagesMatchWithInfinitePsnr) {
  const SplitRun r = run(path("a.png") + " " + path("same.png"));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("pixels over tolerance: 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("PSNR: inf dB"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("units: 8-bit codes"), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST_F(CompareCli, DifferencesWithinTheToleranceMatch) {
  const SplitRun by_value = run(path("b.png") + " " + path("a.png") + " --max-abs 3");
  EXPECT_EQ(by_value.exit_code, 0) << by_value.out << by_value.err;
  EXPECT_NE(by_value.out.find("pixels differing: 2"), std::string::npos) << by_value.out;
  EXPECT_NE(by_value.out.find("max abs difference: 3"), std::string::npos) << by_value.out;
  EXPECT_EQ(by_value.out.find("PSNR: inf"), std::string::npos) << by_value.out;
  // Over --max-abs 2 is one pixel, which --max-pixels 1 allows.
  const SplitRun by_count = run(path("b.png") + " " + path("a.png") + " --max-abs 2 --max-pixels 1");
  EXPECT_EQ(by_count.exit_code, 0) << by_count.out << by_count.err;
  EXPECT_NE(by_count.out.find("pixels over tolerance: 1 (allowed 1"), std::string::npos) << by_count.out;
}

TEST_F(CompareCli, DifferencesOverTheToleranceAreAMismatchWithADiffPicture) {
  const SplitRun r = run(path("b.png") + " " + path("a.png") + " --max-abs 2 --diff " + path("diff.png"));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("MISMATCH"), std::string::npos) << r.out;
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("1 pixels differ"), std::string::npos) << r.err;
  int w = 0, h = 0;
  const std::vector<uint8_t> diff = ontile::read_png_rgba8(path("diff.png"), w, h);
  ASSERT_EQ(w, 16);
  ASSERT_EQ(h, 8);
  const uint8_t* over = &diff[(4 * 16 + 5) * 4];    // 3 > 2: red
  const uint8_t* within = &diff[(2 * 16 + 3) * 4];  // 2 <= 2: blue
  EXPECT_GT(over[0], 128);
  EXPECT_EQ(over[2], 0);
  EXPECT_EQ(within[0], 0);
  EXPECT_GT(within[2], 128);
  EXPECT_EQ(run(path("b.png") + " " + path("a.png")).exit_code, 1);  // default: bit for bit
}

TEST_F(CompareCli, DifferentSizesAreAMismatch) {
  ontile::write_png_rgba8(path("small.png"), 8, 8, std::vector<uint8_t>(8 * 8 * 4, 255));
  const SplitRun r = run(path("a.png") + " " + path("small.png") + " --max-abs 255 --max-pixels 1000");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("16x8"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("8x8"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("sizes differ"), std::string::npos) << r.err;
}

TEST_F(CompareCli, MissingFilesAndBadOptionsAreErrors) {
  for (const std::string& args : {path("a.png") + " " + path("none.png"), path("none.png") + " " + path("a.png"),
                                  path("a.png"), std::string(), path("a.png") + " " + path("a.png") + " --bogus",
                                  path("a.png") + " " + path("a.png") + " --max-abs -1",
                                  path("a.png") + " " + path("a.png") + " --max-pixels many",
                                  path("a.png") + " " + path("a.png") + " --diff " + path("no/diff.png"),
                                  path("a.png") + " " + path("a.png") + " --diff " + path("diff.txt")}) {
    const SplitRun r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.out << r.err;
    EXPECT_TRUE(r.out.empty()) << args << ": " << r.out;
    expect_one_error_line(r);
  }
  const SplitRun missing = run(path("a.png") + " " + path("none.png"));
  EXPECT_NE(missing.err.find(path("none.png")), std::string::npos) << missing.err;
}

TEST_F(CompareCli, FloatImagesAreComparedInValues) {
  ontile::ImageRGBA32F a{4, 2, std::vector<float>(4 * 2 * 4, 0.5f)};
  ontile::ImageRGBA32F b = a;
  b.pixels[5] += 0.001f;
  ontile::write_image(path("a.exr"), a, false);
  ontile::write_image(path("b.exr"), b, false);
  const SplitRun within = run(path("b.exr") + " " + path("a.exr") + " --max-abs 0.002");
  EXPECT_EQ(within.exit_code, 0) << within.out << within.err;
  EXPECT_NE(within.out.find("units: float values"), std::string::npos) << within.out;
  EXPECT_EQ(run(path("b.exr") + " " + path("a.exr") + " --max-abs 0.0005").exit_code, 1);
}

}  // namespace
