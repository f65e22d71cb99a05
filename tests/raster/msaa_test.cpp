// Multisample coverage at the standard sample positions (Vulkan "Standard sample locations"):
// per-sample edge tests, one shading per pixel, and resolve averaging the samples.
#include <gtest/gtest.h>

#include "raster/sample_pattern.h"
#include "support/raster_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 32, kH = 16;

// A triangle whose right edge is vertical at x = edge_x and which covers everything left of it.
std::vector<glm::vec4> left_of(double edge_x) {
  return {pixel_to_clip(-40, -40, kW, kH), pixel_to_clip(edge_x, -40, kW, kH),
          pixel_to_clip(edge_x, kH + 40, kW, kH)};
}

TEST(Msaa, EdgeThroughPixelCentreCoversTheSamplesLeftOfIt) {
  for (int samples : {2, 4, 8}) {
    const SamplePattern& p = *standard_sample_pattern(samples);
    const CountResult r = draw_counting(left_of(10.5), {0, 1, 2}, kW, kH, 16, 2, samples);
    // Samples strictly left of the edge are covered; one exactly on it lies on the triangle's
    // right edge, which is not a left edge, so it is not.
    int expected = 0;
    for (int s = 0; s < samples; ++s) expected += p.x[s] < kSubpixelScale / 2;
    for (int y = 0; y < kH; ++y) {
      EXPECT_EQ(r.at(9, y, kW), 1.0f) << samples;
      EXPECT_EQ(r.at(10, y, kW), float(expected) / samples) << samples << "x, row " << y;
      EXPECT_EQ(r.at(11, y, kW), 0.0f) << samples;
    }
  }
}

TEST(Msaa, SharedEdgeCoversEverySampleExactlyOnce) {
  for (int samples : {1, 2, 4, 8}) {
    const std::vector<glm::vec4> pos = {pixel_to_clip(-40, -40, kW, kH), pixel_to_clip(kW + 40, -37, kW, kH),
                                        pixel_to_clip(kW + 43, kH + 40, kW, kH), pixel_to_clip(-38, kH + 41, kW, kH)};
    // Split along a slanted diagonal: every sample of every pixel is covered exactly once, so
    // the resolved count is exactly 1 everywhere.
    const CountResult r = draw_counting(pos, {0, 1, 2, 0, 2, 3}, kW, kH, 16, 2, samples);
    for (float c : r.counts) ASSERT_EQ(c, 1.0f) << samples << " samples";
  }
}

}  // namespace
}  // namespace ontile::test
