// Accuracy metrics (see accuracy_metrics.h).
#include "reference/accuracy_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "raster/pixel_format.h"
#include "reference/reference_renderer.h"
#include "util/error.h"

namespace ontile {
namespace {

double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double s = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + s * ab));
}

void check_surface(const Surface* s, const char* what, int width_px, int height_px) {
  if (!s) throw Error(std::string("accuracy: missing ") + what);
  if (s->width() != width_px || s->height() != height_px) {
    throw Error(std::string("accuracy: ") + what + " is " + std::to_string(s->width()) + "x" +
                std::to_string(s->height()) + ", the reference " + std::to_string(width_px) + "x" +
                std::to_string(height_px));
  }
}

// A triangle clipped at the near plane z >= 0 (clip space, Vulkan depth range) as the
// rasterizer clips it, in double: clip-space corners and their screen positions.
struct ClippedPolygon {
  int count = 0;
  glm::dvec4 clip[4];
  glm::dvec2 screen[4];
};

// False when a clipped corner has w <= 0 (nothing of the triangle is in front of the camera).
bool clip_and_project(const std::array<glm::dvec3, 3>& world, const CameraMatrices& camera, int width_px,
                      int height_px, ClippedPolygon& out) {
  glm::dvec4 corner[3];
  for (int i = 0; i < 3; ++i) corner[i] = camera.view_projection * glm::dvec4(world[i], 1.0);
  out.count = 0;
  for (int i = 0; i < 3; ++i) {  // Sutherland-Hodgman against one plane
    const glm::dvec4& a = corner[i];
    const glm::dvec4& b = corner[(i + 1) % 3];
    if (a.z >= 0.0) out.clip[out.count++] = a;
    if ((a.z >= 0.0) != (b.z >= 0.0)) out.clip[out.count++] = a + (b - a) * (a.z / (a.z - b.z));
  }
  for (int i = 0; i < out.count; ++i) {
    const glm::dvec4& c = out.clip[i];
    if (!(c.w > 0.0)) return false;
    // The viewport transform of triangle_setup.cpp.
    out.screen[i] = {(c.x / c.w * 0.5 + 0.5) * width_px, (0.5 - c.y / c.w * 0.5) * height_px};
  }
  return out.count >= 3;
}

// Inside (boundary included) the convex polygon, either winding.
bool polygon_contains(const ClippedPolygon& poly, const glm::dvec2& p) {
  bool any_positive = false, any_negative = false;
  for (int i = 0; i < poly.count; ++i) {
    const glm::dvec2 a = poly.screen[i], b = poly.screen[(i + 1) % poly.count];
    const double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    any_positive |= cross > 0.0;
    any_negative |= cross < 0.0;
  }
  return !(any_positive && any_negative) && (any_positive || any_negative);
}

// Clip z / w where the ray through screen position (x_px, y_px) meets the plane through
// `world` (as the reference computes its depth); NaN when the ray is parallel to the plane.
double plane_depth_at(const std::array<glm::dvec3, 3>& world, const CameraMatrices& camera,
                      const glm::dmat4& inverse_vp, int width_px, int height_px, double x_px, double y_px) {
  glm::dvec3 origin, direction;
  double t_max = 0.0;
  camera_ray(inverse_vp, width_px, height_px, x_px, y_px, origin, direction, t_max);
  const glm::dvec3 n = glm::cross(world[1] - world[0], world[2] - world[0]);
  const double n_dot_d = glm::dot(n, direction);
  if (n_dot_d == 0.0) return std::numeric_limits<double>::quiet_NaN();
  const double t = glm::dot(n, world[0] - origin) / n_dot_d;
  const glm::dvec4 hit = camera.view_projection * glm::dvec4(origin + t * direction, 1.0);
  return hit.z / hit.w;
}

}  // namespace

double distance_to_triangle_edges_px(const ReferenceGeometry& geometry, const CameraMatrices& camera,
                                     int width_px, int height_px, uint32_t primitive_id,
                                     double x_px, double y_px) {
  uint32_t renderer = 0, triangle = 0;
  double best = std::numeric_limits<double>::infinity();
  if (!geometry.locate(primitive_id, renderer, triangle)) return best;
  ClippedPolygon poly;
  if (!clip_and_project(geometry.triangle_world(renderer, triangle), camera, width_px, height_px, poly)) return best;
  for (int i = 0; i < poly.count; ++i) {
    best = std::min(best, distance_to_segment({x_px, y_px}, poly.screen[i], poly.screen[(i + 1) % poly.count]));
  }
  return best;
}

// Depth error bound of the rasterizer for one triangle, |z_raster - z_exact| <= sum of:
//  1. Snapping. Setup keeps each vertex's z/w but moves it by d_i, |d_i| <= s per axis, with
//     s = kVertexSnapErrorPx (+ the float transform's screen error below). z/w is affine in
//     screen space with gradient g, so the exact plane takes z_i + g.d_i at the snapped vertex
//     and, at a point inside the snapped triangle (barycentrics l_i in [0, 1]), the snapped
//     plane differs from it by sum l_i g.d_i: at most (|g_x| + |g_y|) * s.
//  2. Float vertex transform. clip = float(MVP) * p in float: per row an n = 4 term dot product
//     with error <= gamma_4 |row| |p| (Higham, Accuracy and Stability of Numerical Algorithms,
//     3.1), 4u, plus u for rounding MVP to float and u for storing a clipped corner back to
//     float: dz, dw <= 6u (|MVP| |p|) with u = 2^-24. Then d(z/w) <= (dz + (z/w) dw) / w and
//     z/w <= 1; clipped corners are convex combinations of the original ones, so the largest
//     corner error over the smallest polygon w bounds every corner (and, being affine, every
//     interior point). The same error in x and y moves the screen position by
//     (viewport / 2) (dx + |x/w| dw) / w before snapping; it is added to s.
//  3. D32F. The corner depths are rounded to float (TriangleSetup::depth) and so is the
//     interpolated depth: two half-ulps, each <= 2^-25 on [0, 1] (ulp 2^-24 on [0.5, 1)).
// The rasterizer's order of two surfaces A, B can differ from the exact one only when
// |z_A - z_B| <= bound_A + bound_B.
TriangleAtPixel triangle_at_pixel(const ReferenceGeometry& geometry, const std::vector<Renderer>& renderers,
                                  const CameraMatrices& camera, int width_px, int height_px,
                                  uint32_t primitive_id, double x_px, double y_px) {
  TriangleAtPixel out;
  uint32_t renderer = 0, triangle = 0;
  if (!geometry.locate(primitive_id, renderer, triangle) || renderer >= renderers.size()) return out;
  const std::array<glm::dvec3, 3> world = geometry.triangle_world(renderer, triangle);
  ClippedPolygon poly;
  if (!clip_and_project(world, camera, width_px, height_px, poly) || !polygon_contains(poly, {x_px, y_px})) {
    return out;
  }
  const glm::dmat4 inverse_vp = glm::inverse(camera.view_projection);
  const double z = plane_depth_at(world, camera, inverse_vp, width_px, height_px, x_px, y_px);
  const double gx = plane_depth_at(world, camera, inverse_vp, width_px, height_px, x_px + 1.0, y_px) - z;
  const double gy = plane_depth_at(world, camera, inverse_vp, width_px, height_px, x_px, y_px + 1.0) - z;
  if (!std::isfinite(z) || !std::isfinite(gx) || !std::isfinite(gy)) return out;

  constexpr double u = 1.0 / 16777216.0;  // 2^-24, float unit roundoff
  const Renderer& r = renderers[renderer];
  const glm::dmat4 mvp = camera.view_projection * r.world;
  const std::array<uint32_t, 3> idx = geometry.triangle_indices(renderer, triangle);
  double abs_xy = 0.0, abs_z = 0.0, abs_w = 0.0;  // max over corners of (|MVP| |p|) per row
  for (uint32_t v : idx) {
    const glm::dvec4 p(glm::dvec3(r.mesh->positions[v]), 1.0);
    glm::dvec4 row_abs(0.0);
    for (int col = 0; col < 4; ++col) row_abs += glm::abs(mvp[col]) * std::abs(p[col]);
    abs_xy = std::max({abs_xy, row_abs.x, row_abs.y});
    abs_z = std::max(abs_z, row_abs.z);
    abs_w = std::max(abs_w, row_abs.w);
  }
  double min_w = std::numeric_limits<double>::infinity(), max_ndc = 0.0;
  for (int i = 0; i < poly.count; ++i) {
    min_w = std::min(min_w, poly.clip[i].w);
    max_ndc = std::max({max_ndc, std::abs(poly.clip[i].x / poly.clip[i].w), std::abs(poly.clip[i].y / poly.clip[i].w)});
  }
  const double transform_depth = 6.0 * u * (abs_z + abs_w) / min_w;
  const double transform_screen_px =
      0.5 * std::max(width_px, height_px) * 6.0 * u * (abs_xy + max_ndc * abs_w) / min_w;
  const double snap = (std::abs(gx) + std::abs(gy)) * (kVertexSnapErrorPx + transform_screen_px);
  const double d32f = 2.0 / 33554432.0;  // 2 * 2^-25
  out.covered = true;
  out.depth = z;
  out.depth_error_bound = snap + transform_depth + d32f;
  return out;
}

namespace {

// Both triangles cover the pixel centre and their exact depths differ by no more than the sum
// of the rasterizer's depth error bounds; records the gap and bound of the ties in m.
bool is_depth_tie(const AccuracyInputs& in, int width_px, int height_px, float raster_id, float ref_id, int x,
                  int y, AccuracyMetrics& m) {
  if (raster_id < 0.0f || ref_id < 0.0f) return false;
  const TriangleAtPixel a = triangle_at_pixel(*in.geometry, *in.renderers, in.camera, width_px, height_px,
                                              static_cast<uint32_t>(raster_id), x + 0.5, y + 0.5);
  const TriangleAtPixel b = triangle_at_pixel(*in.geometry, *in.renderers, in.camera, width_px, height_px,
                                              static_cast<uint32_t>(ref_id), x + 0.5, y + 0.5);
  if (!a.covered || !b.covered) return false;
  const double gap = std::abs(a.depth - b.depth);
  const double bound = a.depth_error_bound + b.depth_error_bound;
  if (gap > bound) return false;
  m.max_depth_tie_gap = std::max(m.max_depth_tie_gap, gap);
  m.max_depth_tie_bound = std::max(m.max_depth_tie_bound, bound);
  return true;
}

}  // namespace

AccuracyMetrics compare_with_reference(const AccuracyInputs& in) {
  if (!in.reference || !in.geometry || !in.renderers) {
    throw Error("accuracy: missing reference image, geometry or renderers");
  }
  const ReferenceImage& ref = *in.reference;
  const int w = ref.width_px, h = ref.height_px;
  check_surface(in.raster_color, "rasterized colour", w, h);
  check_surface(in.raster_depth, "depth AOV", w, h);
  check_surface(in.raster_primitive_id, "primitive-id AOV", w, h);
  if (in.raster_color->format() != PixelFormat::RGBA8_SRGB) {
    throw Error(std::string("accuracy: the rasterized colour is ") + format_name(in.raster_color->format()) +
                ", the lambert reference needs rgba8_srgb");
  }

  AccuracyMetrics m;
  m.width_px = w;
  m.height_px = h;
  m.pixels = uint64_t(w) * h;
  double depth_sum = 0.0, color_abs_sum = 0.0, color_sq_sum = 0.0;
  const std::vector<uint8_t>& raster_bytes = in.raster_color->bytes();
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const float raster_id = in.raster_primitive_id->read(x, y).x;
      const float ref_id = ref.primitive_id[i];
      const bool same = raster_id == ref_id;
      // Distance to the edges of the reference's and of the rasterizer's triangle.
      double ref_edge_px = std::numeric_limits<double>::infinity(), raster_edge_px = ref_edge_px;
      if (ref_id >= 0.0f) {
        ref_edge_px = distance_to_triangle_edges_px(*in.geometry, in.camera, w, h, static_cast<uint32_t>(ref_id),
                                                    x + 0.5, y + 0.5);
      }
      if (same) {
        raster_edge_px = ref_edge_px;
      } else if (raster_id >= 0.0f) {
        raster_edge_px = distance_to_triangle_edges_px(*in.geometry, in.camera, w, h,
                                                       static_cast<uint32_t>(raster_id), x + 0.5, y + 0.5);
      }
      const double d = std::min(ref_edge_px, raster_edge_px);
      if (ref_edge_px <= kEdgeTieDistancePx) ++m.reference_pixels_near_edges;
      if (d <= kEdgeTieDistancePx) ++m.pixels_near_edges;
      if (same) {
        ++m.coverage_matches;
      } else if (d <= kEdgeTieDistancePx) {
        ++m.mismatch_edge_ties;
        m.max_edge_tie_distance_px = std::max(m.max_edge_tie_distance_px, d);
      } else if (is_depth_tie(in, w, h, raster_id, ref_id, x, y, m)) {
        ++m.mismatch_depth_ties;
      } else {
        ++m.mismatch_real;
        m.max_real_mismatch_edge_distance_px = std::max(m.max_real_mismatch_edge_distance_px, d);
      }
      if (same && ref_id >= 0.0f) {
        const double raster_depth = in.raster_depth->read(x, y).x;
        const double ref_depth = ref.depth[i];
        const double abs_error = std::abs(raster_depth - ref_depth);
        const double rel_error = ref_depth > 0.0 ? abs_error / ref_depth : abs_error;
        ++m.depth_pixels;
        depth_sum += rel_error;
        m.depth_max_relative_error = std::max(m.depth_max_relative_error, rel_error);
        m.depth_max_abs_error = std::max(m.depth_max_abs_error, abs_error);
      }
      int pixel_max = 0;
      for (int c = 0; c < 3; ++c) {
        const int raster_code = raster_bytes[4 * i + c];
        const int ref_code = linear_to_srgb8(ref.color[i][c]);
        const int diff = std::abs(raster_code - ref_code);
        color_abs_sum += diff;
        color_sq_sum += double(diff) * diff;
        pixel_max = std::max(pixel_max, diff);
      }
      m.color_max_abs_error = std::max(m.color_max_abs_error, pixel_max);
      if (pixel_max > 1) ++m.color_pixels_over_one_step;
      if (same) m.color_max_abs_error_where_coverage_matches = std::max(m.color_max_abs_error_where_coverage_matches, pixel_max);
    }
  }
  m.coverage_agreement = m.pixels ? double(m.coverage_matches) / double(m.pixels) : 1.0;
  m.depth_mean_relative_error = m.depth_pixels ? depth_sum / double(m.depth_pixels) : 0.0;
  const double samples = 3.0 * double(m.pixels);
  m.color_mean_abs_error = samples > 0 ? color_abs_sum / samples : 0.0;
  const double mse = samples > 0 ? color_sq_sum / samples : 0.0;
  m.color_psnr_db = mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
  return m;
}

nlohmann::json accuracy_json(const AccuracyMetrics& m) {
  nlohmann::json j;
  j["width_px"] = m.width_px;
  j["height_px"] = m.height_px;
  j["pixels"] = m.pixels;
  j["coverage_matches"] = m.coverage_matches;
  j["coverage_agreement"] = m.coverage_agreement;
  j["mismatch_edge_ties"] = m.mismatch_edge_ties;
  j["mismatch_depth_ties"] = m.mismatch_depth_ties;
  j["mismatch_real"] = m.mismatch_real;
  j["max_depth_tie_gap"] = m.max_depth_tie_gap;
  j["max_depth_tie_bound"] = m.max_depth_tie_bound;
  j["edge_tie_distance_px"] = kEdgeTieDistancePx;
  j["max_real_mismatch_edge_distance_px"] =
      std::isfinite(m.max_real_mismatch_edge_distance_px) ? nlohmann::json(m.max_real_mismatch_edge_distance_px) : nullptr;
  j["reference_pixels_near_edges"] = m.reference_pixels_near_edges;
  j["pixels_near_edges"] = m.pixels_near_edges;
  j["max_edge_tie_distance_px"] = m.max_edge_tie_distance_px;
  j["depth_pixels"] = m.depth_pixels;
  j["depth_max_relative_error"] = m.depth_max_relative_error;
  j["depth_mean_relative_error"] = m.depth_mean_relative_error;
  j["depth_max_abs_error"] = m.depth_max_abs_error;
  // JSON has no infinity: identical images give null.
  j["color_psnr_db"] = std::isfinite(m.color_psnr_db) ? nlohmann::json(m.color_psnr_db) : nullptr;
  j["color_mean_abs_error_srgb8"] = m.color_mean_abs_error;
  j["color_max_abs_error_srgb8"] = m.color_max_abs_error;
  j["color_pixels_over_one_step"] = m.color_pixels_over_one_step;
  j["color_max_abs_error_where_coverage_matches"] = m.color_max_abs_error_where_coverage_matches;
  return j;
}

std::string accuracy_text(const AccuracyMetrics& m) {
  const auto n = [](uint64_t v) { return static_cast<unsigned long long>(v); };
  char buf[1400];
  std::snprintf(buf, sizeof buf,
                "coverage agreement   %.6f%% (%llu of %llu pixels)\n"
                "coverage mismatches  %llu edge ties (<= 1/256 px from an edge), %llu depth ties, %llu real\n"
                "near edges           %llu pixels within 1/256 px of an edge (%llu of the reference's triangles); "
                "ties at most %.3g px from one\n"
                "depth ties           max gap %.3g, max bound %.3g\n"
                "depth error          max %.3g relative (%.3g absolute), mean %.3g relative, over %llu pixels\n"
                "colour error (sRGB8) PSNR %.2f dB, mean %.4f, max %d codes; %llu pixels off by > 1 code\n",
                100.0 * m.coverage_agreement, n(m.coverage_matches), n(m.pixels), n(m.mismatch_edge_ties),
                n(m.mismatch_depth_ties), n(m.mismatch_real), n(m.pixels_near_edges),
                n(m.reference_pixels_near_edges), m.max_edge_tie_distance_px, m.max_depth_tie_gap,
                m.max_depth_tie_bound, m.depth_max_relative_error, m.depth_max_abs_error,
                m.depth_mean_relative_error, n(m.depth_pixels), m.color_psnr_db, m.color_mean_abs_error,
                m.color_max_abs_error, n(m.color_pixels_over_one_step));
  return buf;
}

}  // namespace ontile
