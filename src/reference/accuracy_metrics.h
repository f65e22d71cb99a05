// Accuracy of the rasterizer against the ray-traced reference: coverage agreement (primitive
// ids), depth error, colour error on the final 8-bit sRGB image, and whether each coverage
// mismatch is a fill-rule tie (pixel centre within 1/256 px of a triangle edge) or a real error.
#pragma once
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "reference/reference_renderer.h"
#include "tiler/surface.h"

namespace ontile {

// A mismatch whose pixel centre lies this close to an edge is decided by snapping to 1/256 px
// and the top-left rule (D3D11 3.4.2.1), not by an error.
constexpr double kEdgeTieDistancePx = 1.0 / 256.0;

struct AccuracyInputs {
  const ReferenceImage* reference = nullptr;          // 1 sample per pixel
  const ReferenceGeometry* geometry = nullptr;        // the reference's triangles
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
  uint64_t mismatch_real = 0;       // farther
  double max_real_mismatch_edge_distance_px = 0.0;
  // Covered reference pixels whose centre lies within kEdgeTieDistancePx of an edge of their own
  // triangle: where ties can happen at all (many on dense meshes).
  uint64_t reference_pixels_near_edges = 0;
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

nlohmann::json accuracy_json(const AccuracyMetrics& metrics);
// Human-readable summary, one metric per line.
std::string accuracy_text(const AccuracyMetrics& metrics);

}  // namespace ontile
