// Screen-space edges for the cartoon look: a full-screen pass that runs 3x3 Sobel filters over
// linear depth and view-space normals and draws the border colour of the nearest surface where
// either gradient is large. Reads the G-buffer as textures (nearest, clamp): a separate pass.
#pragma once
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
#include "shaders_cpp/full_screen.h"
#include "shaders_cpp/toon/sobel_edge_kernel.h"
#include "shaders_cpp/toon/sobel_trace_kernel.h"
#include "shaders_cpp/toon/toon_outputs.h"

namespace ontile {
namespace sobel {
class TapTrace;
}  // namespace sobel

// How D32F depth maps back to view distance, for the Vulkan [0, 1] projections of
// context/camera_matrices (glTF 2.0 section 3.10 with depth in [0, 1]).
struct DepthLinearization {
  bool orthographic = false;
  float near_plane = 0.1f;  // > 0 for perspective
  float far_plane = 0.0f;   // > near; 0 = infinite far plane (perspective only)
  // Recovers near and far from a projection matrix (column-major, m[col][row]): orthographic
  // when m[2][3] == 0; perspective near = m32 / m22, far = m32 / (m22 + 1) (m22 = -1: infinite);
  // orthographic near = m32 / m22, far = near - 1 / m22.
  static DepthLinearization from_projection(const glm::dmat4& projection);
};

// Positive view distance of depth d (clamped to [0, 1]):
//   perspective:         z = f n / (f - d (f - n)), evaluated as f n / (n + (1 - d)(f - n))
//   infinite perspective: z = n / max(1 - d, 2^-24), so d = 1 (cleared background) lands at a
//                          finite n * 2^24 instead of infinity (2^-24 is D32F's step below 1)
//   orthographic:        z = n + d (f - n)
float linearize_depth(float d, const DepthLinearization& linearization);

// 3x3 Sobel on samples v[row * 3 + col], rows top to bottom, columns left to right:
// Sx = [-1 0 1; -2 0 2; -1 0 1], Sy = its transpose; returns length(Gx, Gy). Differences are
// taken first and summed as ((r0 + r2) + 2 r1), so a step of height h is exactly 4h.
float sobel_magnitude(const float v[9]);
// For vector samples (normals): the Sobel kernels per component, combined as
// sqrt(sum over components of Gx^2 + Gy^2), the Frobenius norm of the normal field's gradient:
// invariant to rotations, and 4 |n1 - n2| = 8 sin(angle / 2) across a straight crease.
float sobel_vector_magnitude(const glm::vec3 v[9]);

// Defaults keep a clean toon scene clean: silhouettes and depth gaps of more than 5% of the view
// distance (4 dz > 0.2 z) and creases sharper than about 29 degrees (8 sin(a/2) > 2) are drawn;
// smooth curvature and flat-shaded facets of 32-sided spheres (11.25 degrees) are not, and a
// plane only produces depth edges beyond about 86 degrees from the view at 512 px height
// (its depth gradient is 8 t z tan(angle) per pixel angle).
struct SobelEdgeParams {
  const Texture2D* color = nullptr;   // required: the shaded scene, sampled at the pixel
  const Texture2D* depth = nullptr;   // required: D32F depth in .x; defines the pixel grid
  const Texture2D* normal = nullptr;  // optional: view normals as toon_outputs.h encodes them
  const Texture2D* border = nullptr;  // optional: border colour RGBA per pixel, alpha 0 = none
  DepthLinearization depth_linearization;
  NormalEncoding normal_encoding = NormalEncoding::Unorm;
  glm::vec4 default_border_color{0.0f, 0.0f, 0.0f, 1.0f};  // used when border is null
  float thickness_px = 1.0f;       // Sobel tap spacing in pixels (lines are ~1-2 taps wide)
  float depth_threshold = 0.2f;    // relative: scaled by the centre's view distance
  float depth_sensitivity = 1.0f;  // multiplies the depth threshold
  float normal_threshold = 2.0f;   // on sobel_vector_magnitude of unit normals
  // Grazing-angle compensation (needs the normal buffer): the depth limit is divided by
  // max(|cos|, min_grazing_cosine), cos = the angle between the centre's normal and its view
  // ray. A plane seen at angle a from its normal has a relative depth gradient proportional to
  // tan(a), so without this, floors towards the horizon turn black.
  glm::vec2 view_ray_scale{0.0f};  // view_ray_scale(projection); (0, 0) = rays along -Z
  float min_grazing_cosine = 0.1f;
};

// (1 / P00, 1 / P11) of a perspective projection: the view ray through NDC (x, y) is
// (x / P00, y / P11, -1). Orthographic projections give (0, 0): every ray is -Z.
glm::vec2 view_ray_scale(const glm::dmat4& projection);

// Per pixel (uv from FullScreenVertexShader::kUv, taps uv + (i, j) * thickness_px / depth size):
//   depth edge  = sobel_magnitude(linear z) > depth_threshold * depth_sensitivity * z_centre
//                 (/ max(|cos|, min_grazing_cosine) when there is a normal buffer, see above)
//   normal edge = sobel_vector_magnitude(decoded normals) > normal_threshold
//   edge        = max of the two, a hard 0 or 1 (crisp lines, no soft band around the threshold)
//   colour      = mix(scene, border.rgb, edge * border.a), alpha = scene alpha
// where border is the border texel of the tap with the smallest depth (the centre on ties with
// it, else the first in row-major order): a silhouette, drawn on the pixels of both sides, takes
// the border colour of the object in front, and a front object whose border alpha is 0 draws no
// line even against a bordered background. Outputs colour only, to colour target 0.
//
// Every tap is a nearest, clamp-to-edge read of level 0 (Texture2D::sample_lod with lod 0):
// the texel is floor(tap uv * size) clamped to the texture, computed with exactly sample_lod's
// float arithmetic. The texel trace (raster/texel_trace.h) receives, per active fragment in
// batch order (quad by quad, lane by lane), the texels of that per-tap sampling: the 9 depth
// taps in row-major order; the normal centre tap; the other 8 normal taps only when depth found
// no edge; the colour at uv; the border at the nearest tap only on an edge. So the simulated
// texture traffic is that of a GPU shader sampling each tap, while the C++ code decodes each
// texel of a batch's neighbourhood once (linear depth, decoded normal) and runs the tests on
// SIMD lanes (sobel_edge_kernel.h); batches whose taps spread wider than the neighbourhood
// grid (scattered uvs, very thick lines) read each tap instead.
class SobelEdgeShader final : public FragmentShader {
 public:
  // Throws Error for missing colour/depth textures, a normal or border texture whose size
  // differs from the depth texture's, or an invalid depth linearization.
  explicit SobelEdgeShader(const SobelEdgeParams& params);
  void shade_batch(const FragmentBatch& batch, BatchOutput& out) const override;
  uint32_t varyings_read() const override { return 3u << FullScreenVertexShader::kUv; }  // uv
  int outputs_always_written() const override { return 1; }  // colour, every path

  // The output colour at one uv (what shade_batch() writes for a fragment), with the same texel
  // trace.
  glm::vec4 shade_pixel(glm::vec2 uv) const;

 private:
  // Shades fragments [0, count) (count a multiple of 16, at most kBatchFragments) at
  // (u[f], v[f]) whose bit is set in `active`, into colour[channel][f], recording the trace.
  // Returns true when no such fragment is on an edge (each got its scene texel as loaded),
  // false when one may be.
  bool shade_fragments(const float* u, const float* v, int count, uint64_t active,
                       float (&colour)[4][kBatchFragments]) const;
  // One fragment's taps read one by one (batches whose neighbourhood exceeds the grid).
  glm::vec4 shade_one(glm::vec2 uv, sobel::TapTrace& trace) const;
  // A fragment's colour from its scene texel and edge test; on an edge, the border texel of its
  // nearest tap (recorded in the trace) or the default border colour.
  glm::vec4 compose(const int tx[sobel::kTapsPerAxis], const int ty[sobel::kTapsPerAxis],
                    int color_x, int color_y, bool edge, int nearest_tap,
                    sobel::TapTrace& trace) const;

  // On an edge: the scene colour mixed towards the border colour of the nearest tap (read, and
  // recorded when trace is not null) or the default border colour.
  glm::vec4 edge_colour(glm::vec4 scene, int border_x, int border_y, sobel::TapTrace* trace) const;

  // |cos| of the angle between the centre's normal and the view ray at uv, at least
  // min_grazing_cosine (also for a zero normal: an uncovered background pixel).
  float grazing_cosine(glm::vec3 view_normal, glm::vec2 uv) const;

  SobelEdgeParams p_;
  Texture2D::TexelView color_, depth_, normal_, border_;  // level 0 of each (empty if absent)
  sobel::TapLayout layout_;
  sobel::DepthDecode depth_decode_;
  sobel::EdgeTest edge_test_;
  sobel::BatchTracePlanes trace_planes_;
  bool batch_lanes_ = false;  // trace and colour reads of grid batches on SIMD lanes
  // The RGBA8 format whose decoded codes the scene texels are, if any: a batch with no edge
  // writes only such values, which the batcher then need not quantise into that format.
  std::optional<PixelFormat> color_codes_;
};

}  // namespace ontile
