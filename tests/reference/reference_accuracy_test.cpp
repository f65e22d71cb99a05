// The ray-traced reference against the rasterizer: exact coverage and colour within one 8-bit
// step on a quad without fill-rule ties, ties only on a perspective triangle and on the demo
// scene, the primitive-id/normal AOVs, sample counts, determinism and the edge distance.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pipelines/aov/aov_pass.h"
#include "reference/accuracy_run.h"
#include "reference/reference_test_scenes.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile {
namespace {

RenderSettings settings_for(int width_px, int height_px) {
  RenderSettings s;
  s.width_px = width_px;
  s.height_px = height_px;
  s.context.threads = 2;
  return s;
}

TEST(ReferenceAccuracy, QuadWithoutTiesMatchesExactlyAndWithinOneStep) {
  const Scene scene = test::textured_quad_scene();
  const AccuracyRun run = measure_accuracy(scene, settings_for(test::kQuadTargetPx, test::kQuadTargetPx));
  const AccuracyMetrics& m = run.metrics;
  EXPECT_EQ(m.coverage_matches, uint64_t(64 * 64));
  EXPECT_EQ(m.coverage_agreement, 1.0);
  EXPECT_EQ(m.mismatch_edge_ties + m.mismatch_real, 0u);
  // Pixel centres (x + 0.5) inside [8.25, 40.25) x [8.25, 24.25): 32 x 16 pixels.
  EXPECT_EQ(m.depth_pixels, uint64_t(32 * 16));
  EXPECT_LE(m.color_max_abs_error, 1);
  EXPECT_LT(m.depth_max_abs_error, 1e-6);
  // The quad really is textured and shaded: its pixels differ from each other.
  const ReferenceImage& ref = run.reference;
  EXPECT_NE(ref.color[10 * 64 + 10], ref.color[10 * 64 + 11]);
  EXPECT_EQ(ref.primitive_id[0], kNoPrimitiveId);
  // Pixel (9, 20) lies below the diagonal (triangle 0), pixel (38, 9) above it (triangle 1).
  EXPECT_EQ(ref.primitive_id[20 * 64 + 9], 0.0f);
  EXPECT_EQ(ref.primitive_id[9 * 64 + 38], 1.0f);
}

TEST(ReferenceAccuracy, PerspectiveTriangleMismatchesAreEdgeTiesOnly) {
  const Scene scene = test::tilted_triangle_scene();
  const AccuracyRun run = measure_accuracy(scene, settings_for(160, 120));
  const AccuracyMetrics& m = run.metrics;
  EXPECT_EQ(m.mismatch_real, 0u);
  EXPECT_GT(m.depth_pixels, 2000u);  // the triangle covers about an eighth of the image
  EXPECT_LE(m.color_max_abs_error_where_coverage_matches, 1);
  EXPECT_LT(m.depth_max_relative_error, 1e-4);
}

TEST(ReferenceAccuracy, DemoPrimitiveIdsAgreeAndEveryMismatchIsATie) {
  const Scene scene = load_gltf(std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb");
  const RenderSettings settings = settings_for(640, 360);
  const AccuracyRun run = measure_accuracy(scene, settings);
  const AccuracyMetrics& m = run.metrics;
  EXPECT_GE(m.coverage_agreement, 0.9999);
  EXPECT_EQ(m.mismatch_real, 0u);
  EXPECT_EQ(m.mismatch_edge_ties, m.pixels - m.coverage_matches);

  // The normal AOV agrees with the reference's normal where the primitive ids agree.
  const AovFrame aovs = render_aov_frame(scene, settings, {AovKind::PrimitiveId, AovKind::Normal});
  uint64_t compared = 0;
  float min_dot = 1.0f;
  for (int y = 0; y < 360; ++y) {
    for (int x = 0; x < 640; ++x) {
      const size_t i = size_t(y) * 640 + x;
      if (aovs.surfaces[0]->read(x, y).x != run.reference.primitive_id[i] || run.reference.primitive_id[i] < 0) continue;
      ++compared;
      min_dot = std::min(min_dot, glm::dot(glm::vec3(aovs.surfaces[1]->read(x, y)), run.reference.normal[i]));
    }
  }
  EXPECT_EQ(compared, m.depth_pixels);
  EXPECT_GT(min_dot, 0.9999f);
}

TEST(ReferenceRenderer, IsDeterministicAndAveragesSamples) {
  const Scene scene = test::textured_quad_scene();
  const LambertReferenceScene ref = make_lambert_reference_scene(scene, scene.cameras[0], 64, 64);
  const ReferenceImage a = render_reference(ref, 64, 64, 1);
  const ReferenceImage b = render_reference(ref, 64, 64, 1);
  EXPECT_EQ(a.color, b.color);
  EXPECT_EQ(a.depth, b.depth);
  // 16 samples at (i + 0.5) / 4: pixel 7's samples (x <= 7.875) all miss the quad, which starts
  // at x = 8.25; pixel 8's x = 8.125 column misses and the other three columns hit.
  const glm::vec4 clear(0.05f, 0.05f, 0.08f, 1.0f);
  const ReferenceImage s16 = render_reference(ref, 64, 64, 16);
  EXPECT_EQ(s16.color[12 * 64 + 7], clear);
  EXPECT_NE(s16.color[12 * 64 + 8], clear);
  EXPECT_NE(s16.color[12 * 64 + 8], a.color[12 * 64 + 8]);
  // AOVs always come from the pixel-centre ray (an extra ray for even grids, the middle sample
  // for odd ones).
  EXPECT_EQ(s16.primitive_id, a.primitive_id);
  EXPECT_EQ(s16.depth, a.depth);
  const ReferenceImage s9 = render_reference(ref, 64, 64, 9);
  EXPECT_EQ(s9.primitive_id, a.primitive_id);
  EXPECT_EQ(s9.normal, a.normal);
}

TEST(ReferenceRenderer, RejectsSampleCountsThatAreNotSquares) {
  const Scene scene = test::textured_quad_scene();
  const LambertReferenceScene ref = make_lambert_reference_scene(scene, scene.cameras[0], 8, 8);
  for (int spp : {0, 2, 3, 8, 257, 289}) EXPECT_THROW(render_reference(ref, 8, 8, spp), Error) << spp;
  EXPECT_NO_THROW(render_reference(ref, 8, 8, 9));
}

TEST(AccuracyMetrics, EdgeDistanceIsThePixelDistanceToTheNearestEdge) {
  const Scene scene = test::textured_quad_scene();
  const LambertReferenceScene ref = make_lambert_reference_scene(scene, scene.cameras[0], 64, 64);
  // Triangle 0 = (8.25, 8.25), (8.25, 24.25), (40.25, 24.25) in pixels.
  EXPECT_NEAR(distance_to_triangle_edges_px(*ref.geometry, ref.camera, 64, 64, 0, 8.5, 20.5), 0.25, 1e-9);
  EXPECT_NEAR(distance_to_triangle_edges_px(*ref.geometry, ref.camera, 64, 64, 0, 12.5, 22.0), 2.25, 1e-9);
  // The diagonal y = x / 2 + 4.125: from (30.5, 19.5) the distance is |30.5/2 + 4.125 - 19.5| / sqrt(1.25).
  EXPECT_NEAR(distance_to_triangle_edges_px(*ref.geometry, ref.camera, 64, 64, 0, 30.5, 19.5),
              std::abs(30.5 / 2 + 4.125 - 19.5) / std::sqrt(1.25), 1e-9);
  EXPECT_TRUE(std::isinf(distance_to_triangle_edges_px(*ref.geometry, ref.camera, 64, 64, 2, 1.0, 1.0)));
}

TEST(AccuracyRun, RejectsPipelinesWithoutAReference) {
  const Scene scene = test::textured_quad_scene();
  RenderSettings settings = settings_for(16, 16);
  settings.pipeline = "cartoon";
  EXPECT_THROW(measure_accuracy(scene, settings), Error);
}

}  // namespace
}  // namespace ontile
