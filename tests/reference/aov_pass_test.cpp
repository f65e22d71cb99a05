// The rasterizer's AOV pass on the analytic quad: exact primitive ids on both sides of the
// diagonal, the orthographic depth of the plane, unit normals, clear values, and its errors.
#include <gtest/gtest.h>

#include "aov/aov_pass.h"
#include "reference/reference_test_scenes.h"
#include "util/error.h"

namespace ontile {
namespace {

TEST(AovPass, WritesIdsDepthAndNormalsOfTheQuad) {
  const Scene scene = test::textured_quad_scene();
  RenderSettings settings;
  settings.width_px = settings.height_px = test::kQuadTargetPx;
  settings.context.threads = 2;
  const AovFrame frame = render_aov_frame(scene, settings, {AovKind::Depth, AovKind::PrimitiveId, AovKind::Normal});
  ASSERT_EQ(frame.surfaces.size(), 3u);
  const Surface& depth = *frame.surfaces[0];
  const Surface& id = *frame.surfaces[1];
  const Surface& normal = *frame.surfaces[2];
  // Orthographic depth of z = 0 seen from z = 5: (view z * 1/(n - f) + n/(n - f)) with view z = -5.
  const double plane_depth = (-5.0 + 0.1) / (0.1 - 10.0);
  int covered = 0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const bool inside = x + 0.5 > 8.25 && x + 0.5 < 40.25 && y + 0.5 > 8.25 && y + 0.5 < 24.25;
      if (!inside) {
        EXPECT_EQ(id.read(x, y).x, -1.0f);
        EXPECT_EQ(depth.read(x, y).x, 1.0f);
        EXPECT_EQ(glm::vec3(normal.read(x, y)), glm::vec3(0.0f));
        continue;
      }
      ++covered;
      // Below the diagonal y = x / 2 + 4.125 is triangle 0, above it triangle 1.
      EXPECT_EQ(id.read(x, y).x, (y + 0.5 > (x + 0.5) / 2 + 4.125) ? 0.0f : 1.0f) << x << "," << y;
      EXPECT_NEAR(depth.read(x, y).x, plane_depth, 1e-6);
      EXPECT_NEAR(glm::length(glm::vec3(normal.read(x, y))), 1.0f, 1e-6f);
    }
  }
  EXPECT_EQ(covered, 32 * 16);
}

TEST(AovPass, NamesAndChannels) {
  for (AovKind k : {AovKind::Depth, AovKind::PrimitiveId, AovKind::Normal}) EXPECT_EQ(parse_aov_kind(aov_name(k)), k);
  EXPECT_FALSE(parse_aov_kind("albedo").has_value());
  EXPECT_EQ(aov_channel_names(AovKind::Depth), std::vector<std::string>{"Z"});
  EXPECT_EQ(aov_channel_names(AovKind::PrimitiveId), std::vector<std::string>{"primid"});
  EXPECT_EQ(aov_channel_names(AovKind::Normal), (std::vector<std::string>{"N.x", "N.y", "N.z"}));
}

TEST(AovPass, RejectsOtherPipelinesAndBadKindLists) {
  const Scene scene = test::textured_quad_scene();
  RenderSettings settings;
  settings.width_px = settings.height_px = 8;
  settings.pipeline = "cartoon";
  EXPECT_THROW(render_aov_frame(scene, settings, {AovKind::Depth}), Error);
  settings.pipeline = "lambert";
  EXPECT_THROW(render_aov_frame(scene, settings, {}), Error);
}

}  // namespace
}  // namespace ontile
