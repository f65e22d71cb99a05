// Golden images: every case renders bit-identically to its reference in golden/. A mismatch
// writes NAME.actual.png and NAME.diff.png into build/test_output/golden and names them.
#include <gtest/gtest.h>

#include <unistd.h>

#include "golden/golden_images.h"
#include "io/image_io.h"

namespace ontile {
namespace {

TEST(GoldenImages, EveryCaseMatchesBitForBit) {
  const auto cases = golden_cases(std::filesystem::path(ONTILE_SOURCE_DIR) / "scenes" / "demo.glb", ONTILE_SHARED_ASSETS);
  ASSERT_GE(cases.size(), 1u);
  int compared = 0;
  for (const GoldenCase& c : cases) {
    const GoldenResult r = run_golden_case(c, std::string(ONTILE_SOURCE_DIR) + "/golden",
                                           std::string(ONTILE_TEST_OUTPUT) + "/golden", false);
    if (r.status == GoldenResult::Status::Skipped) {
      std::printf("skipped %s: %s\n", c.name.c_str(), r.message.c_str());
      continue;
    }
    ++compared;
    EXPECT_EQ(r.status, GoldenResult::Status::Match) << c.name << ": " << r.message;
  }
  EXPECT_GE(compared, 1);
}

TEST(GoldenImages, AMismatchWritesActualAndDiffImages) {
  const auto dir = std::filesystem::temp_directory_path() / ("ontile_golden_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir / "ref");
  GoldenCase c;
  c.name = "demo_lambert";
  c.scene = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";
  c.pipeline = "lambert";
  c.width_px = 64;
  c.height_px = 36;
  ASSERT_EQ(run_golden_case(c, dir / "ref", dir / "fail", true).status, GoldenResult::Status::Updated);
  EXPECT_EQ(run_golden_case(c, dir / "ref", dir / "fail", false).status, GoldenResult::Status::Match);
  // Change one channel of one pixel of the reference by 3.
  int w = 0, h = 0;
  std::vector<uint8_t> pixels = read_png_rgba8(dir / "ref" / "demo_lambert.png", w, h);
  pixels[(5 * w + 7) * 4 + 1] ^= 3;
  write_png_rgba8(dir / "ref" / "demo_lambert.png", w, h, pixels);
  const GoldenResult r = run_golden_case(c, dir / "ref", dir / "fail", false);
  EXPECT_EQ(r.status, GoldenResult::Status::Mismatch);
  EXPECT_EQ(r.differing_pixels, 1u);
  EXPECT_TRUE(std::filesystem::exists(r.actual_image));
  EXPECT_TRUE(std::filesystem::exists(r.diff_image));
  EXPECT_NE(r.message.find(r.diff_image.string()), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ontile
