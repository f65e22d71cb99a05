// The ray-traced reference against the rasterizer: exact coverage and colour within one 8-bit
// step on a quad without fill-rule ties, ties only on a perspective triangle and on the demo
// scene, the primitive-id/normal AOVs, sample counts, determinism, the edge distance and the
// depth-tie classification.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "aov/aov_pass.h"
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
  EXPECT_EQ(m.mismatch_edge_ties + m.mismatch_depth_ties + m.mismatch_real, 0u);
  EXPECT_EQ(m.pixels_near_edges, 0u);
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

TEST(AccuracyMetrics, TriangleAtPixelGivesExactDepthAndItsErrorBound) {
  const Scene scene = test::textured_quad_scene();
  const LambertReferenceScene ref = make_lambert_reference_scene(scene, scene.cameras[0], 64, 64);
  const std::vector<Renderer>& renderers = ref.renderers.renderers;
  const double plane_depth = (-5.0 + 0.1) / (0.1 - 10.0);  // orthographic, as in aov_pass_test
  const TriangleAtPixel inside = triangle_at_pixel(*ref.geometry, renderers, ref.camera, 64, 64, 0, 9.5, 20.5);
  ASSERT_TRUE(inside.covered);
  EXPECT_NEAR(inside.depth, plane_depth, 1e-9);  // the camera's near plane is the float 0.1f
  // The plane faces the camera: no snapping term, only the float transform and D32F terms,
  // 6u (|z row| |p| + |w row| |p|) / w + 2^-24 with |p| = (|x|, |y|, 0, 1) at the far corner.
  EXPECT_GE(inside.depth_error_bound, 1.0 / 16777216.0);
  EXPECT_LT(inside.depth_error_bound, 1e-6);
  // (38.5, 9.5) is triangle 1's, outside triangle 0; an unknown id covers nothing.
  EXPECT_FALSE(triangle_at_pixel(*ref.geometry, renderers, ref.camera, 64, 64, 0, 38.5, 9.5).covered);
  EXPECT_TRUE(triangle_at_pixel(*ref.geometry, renderers, ref.camera, 64, 64, 1, 38.5, 9.5).covered);
  EXPECT_FALSE(triangle_at_pixel(*ref.geometry, renderers, ref.camera, 64, 64, 2, 9.5, 20.5).covered);
}

// Two overlapping quads dz apart in world z (orthographic camera): at a pixel far from every
// edge the reference is made to name the surface the rasterizer does not show.
AccuracyMetrics swapped_surface_metrics(float dz) {
  Scene scene = test::textured_quad_scene();
  MeshPrimitive& prim = scene.meshes[0].primitives[0];
  for (uint32_t v = 0; v < 4; ++v) prim.positions.push_back(prim.positions[v] + glm::vec3(0.0f, 0.0f, dz));
  prim.normals.insert(prim.normals.end(), prim.normals.begin(), prim.normals.end());
  prim.uv0.insert(prim.uv0.end(), prim.uv0.begin(), prim.uv0.end());
  prim.indices.insert(prim.indices.end(), {4, 7, 6, 4, 6, 5});
  RenderSettings settings = settings_for(64, 64);
  const RenderedFrame frame = render_frame(scene, settings);
  const AovFrame aovs = render_aov_frame(scene, settings, {AovKind::Depth, AovKind::PrimitiveId});
  const LambertReferenceScene ref = make_lambert_reference_scene(scene, frame.camera, 64, 64);
  ReferenceImage image = render_reference(ref, 64, 64, 1);
  // Pixel (12, 20): triangle 0 or 2 (its copy), 0.25 px or more from every edge.
  const size_t i = 20 * 64 + 12;
  const float raster_id = aovs.surfaces[1]->read(12, 20).x;
  EXPECT_TRUE(raster_id == 0.0f || raster_id == 2.0f) << raster_id;
  image.primitive_id[i] = raster_id == 0.0f ? 2.0f : 0.0f;
  AccuracyInputs in;
  in.reference = &image;
  in.geometry = ref.geometry.get();
  in.renderers = &ref.renderers.renderers;
  in.camera = ref.camera;
  in.raster_color = frame.outputs.color;
  in.raster_depth = aovs.surfaces[0];
  in.raster_primitive_id = aovs.surfaces[1];
  return compare_with_reference(in);
}

TEST(AccuracyMetrics, CloseSurfacesAreDepthTiesAndDistantOnesReal) {
  // Depth gap dz / (f - n) = 1e-6 / 9.9, below the two bounds (about 2 * 6e-7); 1e-3 / 9.9 is not.
  const AccuracyMetrics tie = swapped_surface_metrics(1e-6f);
  EXPECT_EQ(tie.mismatch_depth_ties, 1u);
  EXPECT_EQ(tie.mismatch_real, 0u);
  EXPECT_NEAR(tie.max_depth_tie_gap, 1e-6 / 9.9, 1e-9);
  EXPECT_GT(tie.max_depth_tie_bound, tie.max_depth_tie_gap);
  const AccuracyMetrics real = swapped_surface_metrics(1e-3f);
  EXPECT_EQ(real.mismatch_depth_ties, 0u);
  EXPECT_EQ(real.mismatch_real, 1u);
  EXPECT_EQ(real.mismatch_edge_ties, 0u);
}

TEST(AccuracyMetrics, MissingRenderersAreAnError) {
  AccuracyInputs in;
  EXPECT_THROW(compare_with_reference(in), Error);
}

TEST(AccuracyRun, RejectsPipelinesWithoutAReference) {
  const Scene scene = test::textured_quad_scene();
  RenderSettings settings = settings_for(16, 16);
  settings.pipeline = "cartoon";
  EXPECT_THROW(measure_accuracy(scene, settings), Error);
}

}  // namespace
}  // namespace ontile
