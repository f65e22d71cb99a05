// Accuracy of the rasterizer against the ray-traced reference: coverage agreement (primitive
// ids), depth error, colour error on the final 8-bit sRGB image, and whether each coverage
// mismatch is a fill-rule tie (pixel centre within 1/256 px of a triangle edge), a depth tie
// (two surfaces closer in depth than the rasterizer can resolve) or a real error.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reference/reference_renderer.h"
#include "tiler/surface.h"

namespace ontile {

// A mismatch whose pixel centre lies this close to an edge is decided by snapping to 1/256 px
// and the top-left rule (D3D11 3.4.2.1), not by an error.
constexpr double kEdgeTieDistancePx = 1.0 / 256.0;
// Largest distance, per axis, that snapping to the nearest 1/256 px (D3D11 3.2.4.1) moves a
// vertex: half a 16.8 fixed-point step.
constexpr double kVertexSnapErrorPx = 0.5 / 256.0;

struct AccuracyInputs {
  const ReferenceImage* reference = nullptr;          // 1 sample per pixel
  const ReferenceGeometry* geometry = nullptr;        // the reference's triangles
  const std::vector<Renderer>* renderers = nullptr;   // those the geometry was built from
  CameraMatrices camera;                              // the frame's camera
  const Surface* raster_color = nullptr;              // lambert's RGBA8_SRGB image
  const Surface* raster_depth = nullptr;              // AOV depth (RGBA32F)
  const Surface* raster_primitive_id = nullptr;       // AOV primitive id (RGBA32F)
};

struct AccuracyMetrics {
  int width_px = 0, height_px = 0;
  uint64_t pixels = 0;
  // Coverage: pixels whose primitive id (or "nothing") is the same in both.
  uint64_t coverage_matches = 0;
  double coverage_agreement = 0.0;  // coverage_matches / pixels
  uint64_t mismatch_edge_ties = 0;  // within kEdgeTieDistancePx of an edge of either triangle
  // Not edge ties; the pixel-centre ray crosses both triangles and their depths differ by no
  // more than the sum of their depth_error_bound (see TriangleAtPixel): the depth test, not
  // coverage, decided, and the rasterizer cannot resolve the order.
  uint64_t mismatch_depth_ties = 0;
  uint64_t mismatch_real = 0;       // neither
  double max_real_mismatch_edge_distance_px = 0.0;
  // Over depth ties: the largest depth gap and the largest bound it was compared with.
  double max_depth_tie_gap = 0.0, max_depth_tie_bound = 0.0;
  // Covered reference pixels whose centre lies within kEdgeTieDistancePx of an edge of their own
  // triangle: where ties can happen at all (many on dense meshes).
  uint64_t reference_pixels_near_edges = 0;
  // Pixels whose centre lies within kEdgeTieDistancePx of an edge of the triangle the
  // rasterizer or the reference shows there (silhouettes against the background included):
  // every edge tie is one of them.
  uint64_t pixels_near_edges = 0;
  // Largest edge distance over edge ties; snapping moves an edge by at most the largest vertex
  // move, sqrt(2) * kVertexSnapErrorPx, so ties explained by snapping stay below that.
  double max_edge_tie_distance_px = 0.0;
  // Depth over pixels where both hit the same triangle: |raster - reference| / reference.
  uint64_t depth_pixels = 0;
  double depth_max_relative_error = 0.0, depth_mean_relative_error = 0.0;
  double depth_max_abs_error = 0.0;
  // Colour on the final 8-bit sRGB codes (R, G, B; the reference's linear colour encoded as the
  // RGBA8_SRGB attachment encodes), over all pixels. PSNR is +inf for identical images.
  double color_psnr_db = 0.0;
  double color_mean_abs_error = 0.0;  // in codes (1 = one 8-bit step)
  int color_max_abs_error = 0;
  uint64_t color_pixels_over_one_step = 0;  // pixels with a channel off by more than 1 code
  int color_max_abs_error_where_coverage_matches = 0;
};

// Throws Error when the inputs are missing or their sizes differ.
AccuracyMetrics compare_with_reference(const AccuracyInputs& inputs);

// Distance in pixels from screen point (x_px, y_px) (y down) to the nearest edge of the
// triangle with this primitive id, projected with the camera (after clipping at the near plane,
// as the rasterizer clips). Infinity when the id is unknown or the triangle is behind the camera.
double distance_to_triangle_edges_px(const ReferenceGeometry& geometry, const CameraMatrices& camera,
                                     int width_px, int height_px, uint32_t primitive_id,
                                     double x_px, double y_px);

// A triangle as the reference sees it at one screen position, and how far the rasterizer's
// D32F depth for it may be off there.
struct TriangleAtPixel {
  bool covered = false;            // the ray through the position crosses the triangle
  double depth = 1.0;              // clip z / w where the ray meets the triangle's plane
  double depth_error_bound = 0.0;  // |rasterized depth - depth| <= this where covered
};

// Exact (double) test of the ray through (x_px, y_px) against triangle primitive_id, after
// near-plane clipping, and its depth error bound (derivation in accuracy_metrics.cpp).
// renderers are those the geometry was built from. Not covered when the id is unknown.
TriangleAtPixel triangle_at_pixel(const ReferenceGeometry& geometry, const std::vector<Renderer>& renderers,
                                  const CameraMatrices& camera, int width_px, int height_px,
                                  uint32_t primitive_id, double x_px, double y_px);

nlohmann::json accuracy_json(const AccuracyMetrics& metrics);
// Human-readable summary, one metric per line.
std::string accuracy_text(const AccuracyMetrics& metrics);

}  // namespace ontile
