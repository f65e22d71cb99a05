// Error measures of one sweep setting against the ray-traced reference: colour on the final
// 8-bit sRGB codes, visibility (primitive ids) and the angular error of a stored normal buffer.
#pragma once
#include <cstdint>
#include <vector>

#include "reference/reference_renderer.h"
#include "shaders_cpp/normal_encoding.h"
#include "tiler/surface.h"

namespace ontile {

struct ColorError {
  double psnr_db = 0.0;        // over R, G, B codes; +inf for identical images
  double mean_abs = 0.0;       // in codes (1 = one 8-bit step)
  int max_abs = 0;
};

// The raster image (RGBA8_SRGB) against the reference colour encoded as that attachment
// encodes it, exactly as compare_with_reference (accuracy_metrics.h) computes its colour terms.
// Throws Error when the format or the sizes differ.
ColorError color_error(const Surface& raster_color, const ReferenceImage& reference);

// Fraction of pixels whose primitive id (R of an R32F/RGBA32F id target, -1 = nothing) differs.
double primitive_id_mismatch(const Surface& ids, const Surface& other_ids);
double primitive_id_mismatch(const Surface& ids, const ReferenceImage& reference);

struct NormalError {
  uint64_t pixels = 0;        // pixels measured: raster and reference hit the same triangle
  double mean_deg = 0.0, max_deg = 0.0;
};

// Angle between the decoded stored normal and the reference's normal AOV, over the pixels
// where the raster's primitive id equals the reference's (both hit the same triangle).
NormalError normal_error(const Surface& stored_normals, NormalStorage storage, const Surface& ids,
                         const ReferenceImage& reference);
// The storage error alone: the decoded normal against float normals of the same geometry (an
// RGBA32F normal AOV with its primitive-id AOV), over the pixels where the ids agree.
NormalError normal_error(const Surface& stored_normals, NormalStorage storage, const Surface& ids,
                         const Surface& float_normals, const Surface& float_normal_ids);

// Angle in degrees between two unit vectors, accurate for tiny angles (atan2 of |a x b| and
// a . b, in double).
double angle_between_deg(const glm::vec3& a, const glm::vec3& b);

}  // namespace ontile
