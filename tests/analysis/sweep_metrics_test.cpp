// Sweep error measures on hand-made images: colour PSNR and mean absolute error in sRGB8 codes,
// primitive-id mismatch fractions, and angular normal error over the pixels whose ids agree.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/sweep_metrics.h"
#include "util/error.h"

namespace ontile {
namespace {

glm::vec4 srgb_codes(int r, int g, int b) {
  const auto& decode = srgb8_decode_table();
  return {decode[r], decode[g], decode[b], 1.0f};
}

TEST(SweepMetrics, ColorErrorInSrgbCodes) {
  ReferenceImage ref;
  ref.width_px = 2;
  ref.height_px = 1;
  ref.color = {srgb_codes(10, 20, 30), srgb_codes(104, 50, 2)};
  Surface raster("c", PixelFormat::RGBA8_SRGB, 2, 1);
  raster.write(0, 0, 0, srgb_codes(10, 20, 30));
  raster.write(1, 0, 0, srgb_codes(100, 50, 0));
  const ColorError e = color_error(raster, ref);
  // Differences 0, 0, 0, 4, 0, 2 over 6 samples.
  EXPECT_DOUBLE_EQ(e.mean_abs, 1.0);
  EXPECT_EQ(e.max_abs, 4);
  EXPECT_DOUBLE_EQ(e.psnr_db, 10.0 * std::log10(255.0 * 255.0 / (20.0 / 6.0)));

  raster.write(1, 0, 0, srgb_codes(104, 50, 2));
  EXPECT_TRUE(std::isinf(color_error(raster, ref).psnr_db));
  EXPECT_EQ(color_error(raster, ref).mean_abs, 0.0);

  Surface wrong_format("c", PixelFormat::RGBA8_UNORM, 2, 1);
  EXPECT_THROW(color_error(wrong_format, ref), Error);
  Surface wrong_size("c", PixelFormat::RGBA8_SRGB, 3, 1);
  EXPECT_THROW(color_error(wrong_size, ref), Error);
}

TEST(SweepMetrics, PrimitiveIdMismatch) {
  Surface a("a", PixelFormat::R32_FLOAT, 4, 1), b("b", PixelFormat::R32_FLOAT, 4, 1);
  const float ids_a[] = {-1, 3, 7, 9}, ids_b[] = {-1, 3, 8, -1};
  for (int x = 0; x < 4; ++x) {
    a.write(x, 0, 0, glm::vec4(ids_a[x]));
    b.write(x, 0, 0, glm::vec4(ids_b[x]));
  }
  EXPECT_DOUBLE_EQ(primitive_id_mismatch(a, b), 0.5);
  ReferenceImage ref;
  ref.width_px = 4;
  ref.height_px = 1;
  ref.primitive_id = {-1, 4, 7, 9};
  EXPECT_DOUBLE_EQ(primitive_id_mismatch(a, ref), 0.25);
}

TEST(SweepMetrics, NormalErrorOverPixelsWhereIdsAgree) {
  ReferenceImage ref;
  ref.width_px = 4;
  ref.height_px = 1;
  ref.primitive_id = {5, 6, 7, -1};
  ref.normal = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 0}};
  Surface ids("ids", PixelFormat::R32_FLOAT, 4, 1);
  Surface normals("n", PixelFormat::RGBA16_FLOAT, 4, 1);
  const float raster_ids[] = {5, 6, 8, -1};
  const glm::vec4 stored[] = {{0, 0, 1, 1}, {1, 0, 1, 1}, {1, 0, 0, 1}, {0, 0, 0, 0}};
  for (int x = 0; x < 4; ++x) {
    ids.write(x, 0, 0, glm::vec4(raster_ids[x]));
    normals.write(x, 0, 0, stored[x]);
  }
  // Pixel 0: exact; pixel 1: 45 degrees; pixel 2: another triangle; pixel 3: nothing.
  const NormalError e = normal_error(normals, NormalStorage::Rgba16f, ids, ref);
  EXPECT_EQ(e.pixels, 2u);
  EXPECT_NEAR(e.max_deg, 45.0, 1e-5);
  EXPECT_NEAR(e.mean_deg, 22.5, 1e-5);
}

TEST(SweepMetrics, AngleIsAccurateForTinyAngles) {
  const double rad = 1e-6;
  const glm::vec3 b = glm::vec3(glm::dvec3(std::cos(rad), std::sin(rad), 0.0));
  EXPECT_NEAR(angle_between_deg(glm::vec3(1, 0, 0), b), rad * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_DOUBLE_EQ(angle_between_deg(glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0)), 180.0);
}

}  // namespace
}  // namespace ontile
