// Accuracy metrics (see accuracy_metrics.h).
#include "reference/accuracy_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "raster/pixel_format.h"
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

}  // namespace

double distance_to_triangle_edges_px(const ReferenceGeometry& geometry, const CameraMatrices& camera,
                                     int width_px, int height_px, uint32_t primitive_id,
                                     double x_px, double y_px) {
  uint32_t renderer = 0, triangle = 0;
  if (!geometry.locate(primitive_id, renderer, triangle)) return std::numeric_limits<double>::infinity();
  const std::array<glm::dvec3, 3> p = geometry.triangle_world(renderer, triangle);
  // Sutherland-Hodgman against the near plane z >= 0 (clip space, Vulkan depth range).
  glm::dvec4 clip[3];
  for (int i = 0; i < 3; ++i) clip[i] = camera.view_projection * glm::dvec4(p[i], 1.0);
  glm::dvec4 polygon[4];
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec4& a = clip[i];
    const glm::dvec4& b = clip[(i + 1) % 3];
    if (a.z >= 0.0) polygon[count++] = a;
    if ((a.z >= 0.0) != (b.z >= 0.0)) polygon[count++] = a + (b - a) * (a.z / (a.z - b.z));
  }
  double best = std::numeric_limits<double>::infinity();
  glm::dvec2 screen[4];
  for (int i = 0; i < count; ++i) {
    if (!(polygon[i].w > 0.0)) return best;
    // The viewport transform of triangle_setup.cpp.
    screen[i] = {(polygon[i].x / polygon[i].w * 0.5 + 0.5) * width_px,
                 (0.5 - polygon[i].y / polygon[i].w * 0.5) * height_px};
  }
  for (int i = 0; i < count; ++i) {
    best = std::min(best, distance_to_segment({x_px, y_px}, screen[i], screen[(i + 1) % count]));
  }
  return best;
}

AccuracyMetrics compare_with_reference(const AccuracyInputs& in) {
  if (!in.reference || !in.geometry) throw Error("accuracy: missing reference image or geometry");
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
      if (ref_id >= 0.0f && distance_to_triangle_edges_px(*in.geometry, in.camera, w, h, static_cast<uint32_t>(ref_id),
                                                          x + 0.5, y + 0.5) <= kEdgeTieDistancePx) {
        ++m.reference_pixels_near_edges;
      }
      if (same) {
        ++m.coverage_matches;
      } else {
        double d = std::numeric_limits<double>::infinity();
        for (float id : {raster_id, ref_id}) {
          if (id >= 0.0f) {
            d = std::min(d, distance_to_triangle_edges_px(*in.geometry, in.camera, w, h,
                                                          static_cast<uint32_t>(id), x + 0.5, y + 0.5));
          }
        }
        if (d <= kEdgeTieDistancePx) {
          ++m.mismatch_edge_ties;
        } else {
          ++m.mismatch_real;
          m.max_real_mismatch_edge_distance_px = std::max(m.max_real_mismatch_edge_distance_px, d);
        }
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
  j["mismatch_real"] = m.mismatch_real;
  j["edge_tie_distance_px"] = kEdgeTieDistancePx;
  j["max_real_mismatch_edge_distance_px"] =
      std::isfinite(m.max_real_mismatch_edge_distance_px) ? nlohmann::json(m.max_real_mismatch_edge_distance_px) : nullptr;
  j["reference_pixels_near_edges"] = m.reference_pixels_near_edges;
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
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "coverage agreement   %.6f%% (%llu of %llu pixels)\n"
                "coverage mismatches  %llu edge ties (<= 1/256 px from an edge; %llu reference pixels are), %llu real\n"
                "depth error          max %.3g relative (%.3g absolute), mean %.3g relative, over %llu pixels\n"
                "colour error (sRGB8) PSNR %.2f dB, mean %.4f, max %d codes; %llu pixels off by > 1 code\n",
                100.0 * m.coverage_agreement, static_cast<unsigned long long>(m.coverage_matches),
                static_cast<unsigned long long>(m.pixels), static_cast<unsigned long long>(m.mismatch_edge_ties),
                static_cast<unsigned long long>(m.reference_pixels_near_edges),
                static_cast<unsigned long long>(m.mismatch_real), m.depth_max_relative_error,
                m.depth_max_abs_error, m.depth_mean_relative_error,
                static_cast<unsigned long long>(m.depth_pixels), m.color_psnr_db, m.color_mean_abs_error,
                m.color_max_abs_error, static_cast<unsigned long long>(m.color_pixels_over_one_step));
  return buf;
}

}  // namespace ontile
