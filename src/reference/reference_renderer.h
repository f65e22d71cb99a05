// The ray-traced reference image of the lambert pipeline: same camera, same sample positions
// (pixel centres; a stratified k x k grid per pixel for k^2 samples), same fragment functors,
// plus depth, primitive-id and normal AOVs for comparing coverage with the rasterizer.
#pragma once
#include "util/progress.h"
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "reference/reference_shading.h"

namespace ontile {

// Primitive-id AOV value of a pixel no triangle covers.
constexpr float kNoPrimitiveId = -1.0f;

struct ReferenceImage {
  int width_px = 0, height_px = 0;
  int samples_per_pixel = 1;
  // Row-major, top row first. Colour: linear RGBA, averaged over the samples; each surface's
  // write is clamped to [0, 1] (the RGBA8 attachment's range) but not rounded to 8 bits.
  std::vector<glm::vec4> color;
  // AOVs of the ray through the pixel centre (whatever the sample count), of the nearest
  // opaque-queue surface not discarded by alpha test (blended surfaces write no depth):
  std::vector<float> depth;         // clip z / w in [0, 1]; 1 (the depth clear) when nothing
  std::vector<float> primitive_id;  // as float, exact below 2^24; kNoPrimitiveId when nothing
  std::vector<glm::vec3> normal;    // unit interpolated shading normal, viewer side; 0 when nothing
};

// Throws Error unless samples_per_pixel is a perfect square from 1 to 256.
void check_samples_per_pixel(int samples_per_pixel);

// Renders ref's frame (width x height from make_lambert_reference_scene). samples_per_pixel must
// be a perfect square 1, 4, 9, ... 256; others throw Error. Runs on oneTBB's threads; the result
// does not depend on the thread count.
// `progress` (optional) hears of every finished row of quads, from the worker threads.
ReferenceImage render_reference(const LambertReferenceScene& ref, int width_px, int height_px,
                                int samples_per_pixel, const ProgressCallback& progress = {});

// EXR channel layout of a reference image: R, G, B, A, Z, primid, N.x, N.y, N.z.
std::vector<std::string> reference_channel_names();
std::vector<float> reference_channels(const ReferenceImage& image);
void write_reference_exr(const std::filesystem::path& path, const ReferenceImage& image);

// The ray through pixel position (x, y) (pixels, y down, (0.5, 0.5) = centre of pixel 0): it
// starts on the near plane, where the rasterizer clips, and t_max ends it at the far plane
// (infinity for an infinite projection). direction has unit length.
void camera_ray(const glm::dmat4& inverse_view_projection, int width_px, int height_px, double x_px, double y_px,
                glm::dvec3& origin, glm::dvec3& direction, double& t_max);

}  // namespace ontile
