// Reference rendering (see reference_renderer.h): rays in 2x2 quads, every crossing collected,
// opaque surfaces resolved front to back through alpha test, blended ones composited back to
// front with the material's blend state, as lambert's two draw_renderers calls order them.
#include "reference/reference_renderer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>

#include "io/image_io.h"
#include "util/error.h"
#include "util/parallel_for.h"

namespace ontile {
namespace {

struct LaneResult {
  glm::vec4 color{0.0f};
  float depth = 1.0f;
  float primitive_id = kNoPrimitiveId;
  glm::vec3 normal{0.0f};
};

constexpr size_t kNone = std::numeric_limits<size_t>::max();

// Index of the first candidate at or after `from` that an opaque-queue draw renders.
size_t next_opaque(const LambertReferenceScene& ref, const std::vector<RayCandidate>& c, size_t from) {
  for (size_t i = from; i < c.size(); ++i) {
    if (ref.draws[c[i].renderer].surface_class != SurfaceClass::Blended) return i;
  }
  return kNone;
}

glm::vec4 write_attachment(const BlendState& blend, const glm::vec4& src, const glm::vec4& dst) {
  return glm::clamp(blend_color(blend, src, dst), glm::vec4(0.0f), glm::vec4(1.0f));
}

// Traces and shades one quad with every lane's ray offset (off_x, off_y) pixels from its
// pixel's top-left corner. Lanes outside the image are traced (helper lanes need them) but
// never active.
void render_quad(const LambertReferenceScene& ref, const glm::dmat4& inverse_vp, int width_px,
                 int height_px, int qx, int qy, double off_x, double off_y,
                 std::vector<RayCandidate> (&hits)[kQuadLanes], LaneResult (&result)[kQuadLanes]) {
  QuadRays rays;
  double t_max[kQuadLanes];
  uint8_t inside = 0;
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    const int x = qx + (lane & 1), y = qy + (lane >> 1);
    if (x < width_px && y < height_px) inside |= static_cast<uint8_t>(1u << lane);
    camera_ray(inverse_vp, width_px, height_px, x + off_x, y + off_y, rays.origin[lane],
               rays.direction[lane], t_max[lane]);
    ref.geometry->intersect_all(rays.origin[lane], rays.direction[lane], t_max[lane], hits[lane]);
    result[lane] = LaneResult{};
    result[lane].color = ref.clear_color;
  }

  // Opaque queue: each lane's current candidate is its nearest opaque-queue crossing not yet
  // discarded. Lanes on the same triangle are shaded together, as one rasterized quad.
  size_t cursor[kQuadLanes];
  double opaque_t[kQuadLanes];
  uint8_t pending = 0;
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    opaque_t[lane] = std::numeric_limits<double>::infinity();
    cursor[lane] = next_opaque(ref, hits[lane], 0);
    if (((inside >> lane) & 1u) && cursor[lane] != kNone) pending |= static_cast<uint8_t>(1u << lane);
  }
  QuadShading shading;
  while (pending) {
    int first = 0;
    while (!((pending >> first) & 1u)) ++first;
    const RayCandidate hit = hits[first][cursor[first]];
    uint8_t group = 0;
    for (int lane = first; lane < kQuadLanes; ++lane) {
      if (((pending >> lane) & 1u) && hits[lane][cursor[lane]].primitive_id == hit.primitive_id) {
        group |= static_cast<uint8_t>(1u << lane);
      }
    }
    shade_hit_quad(ref, hit, rays, qx, qy, group, shading);
    const ReferenceDraw& draw = ref.draws[hit.renderer];
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (!((group >> lane) & 1u)) continue;
      if ((shading.output.discard_mask >> lane) & 1u) {
        cursor[lane] = next_opaque(ref, hits[lane], cursor[lane] + 1);
        if (cursor[lane] == kNone) pending &= static_cast<uint8_t>(~(1u << lane));
        continue;
      }
      pending &= static_cast<uint8_t>(~(1u << lane));
      LaneResult& r = result[lane];
      r.color = write_attachment(draw.state.blend, shading.output.color[0][lane], ref.clear_color);
      r.depth = shading.depth[lane];
      r.primitive_id = static_cast<float>(hit.primitive_id);
      r.normal = shading.normal[lane];
      opaque_t[lane] = hits[lane][cursor[lane]].t;
    }
  }

  // Transparent queue: blended crossings up to the opaque surface (depth test LessEqual, no
  // depth write), composited far to near.
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    if (!((inside >> lane) & 1u)) continue;
    const std::vector<RayCandidate>& c = hits[lane];
    for (size_t i = c.size(); i-- > 0;) {
      if (ref.draws[c[i].renderer].surface_class != SurfaceClass::Blended || c[i].t > opaque_t[lane]) continue;
      shade_hit_quad(ref, c[i], rays, qx, qy, static_cast<uint8_t>(1u << lane), shading);
      if ((shading.output.discard_mask >> lane) & 1u) continue;
      result[lane].color = write_attachment(ref.draws[c[i].renderer].state.blend,
                                            shading.output.color[0][lane], result[lane].color);
    }
  }
}

}  // namespace

void camera_ray(const glm::dmat4& inverse_vp, int width_px, int height_px, double x_px, double y_px,
                glm::dvec3& origin, glm::dvec3& direction, double& t_max) {
  // Inverse of the viewport transform in triangle_setup.cpp: +Y up in NDC, rows go down.
  const double ndc_x = x_px / width_px * 2.0 - 1.0;
  const double ndc_y = 1.0 - y_px / height_px * 2.0;
  const glm::dvec4 near_h = inverse_vp * glm::dvec4(ndc_x, ndc_y, 0.0, 1.0);
  const glm::dvec4 mid_h = inverse_vp * glm::dvec4(ndc_x, ndc_y, 0.5, 1.0);
  const glm::dvec4 far_h = inverse_vp * glm::dvec4(ndc_x, ndc_y, 1.0, 1.0);
  origin = glm::dvec3(near_h) / near_h.w;
  direction = glm::normalize(glm::dvec3(mid_h) / mid_h.w - origin);
  // An infinite far plane maps depth 1 to a point at infinity (w = 0).
  t_max = std::numeric_limits<double>::infinity();
  if (far_h.w > 0.0) {
    const double t = glm::dot(glm::dvec3(far_h) / far_h.w - origin, direction);
    if (std::isfinite(t) && t > 0.0) t_max = t;
  }
}

void check_samples_per_pixel(int samples_per_pixel) {
  const int grid = static_cast<int>(std::lround(std::sqrt(double(std::max(samples_per_pixel, 0)))));
  if (samples_per_pixel < 1 || samples_per_pixel > 256 || grid * grid != samples_per_pixel) {
    throw Error("reference: --spp " + std::to_string(samples_per_pixel) +
                " must be a perfect square from 1 to 256 (a k x k stratified grid per pixel)");
  }
}

ReferenceImage render_reference(const LambertReferenceScene& ref, int width_px, int height_px, int samples_per_pixel,
                                const ProgressCallback& progress) {
  if (width_px <= 0 || height_px <= 0 || width_px > kMaxTargetSizePx || height_px > kMaxTargetSizePx) {
    throw Error("reference: image size " + std::to_string(width_px) + "x" + std::to_string(height_px) +
                " outside 1.." + std::to_string(kMaxTargetSizePx));
  }
  check_samples_per_pixel(samples_per_pixel);
  const int grid = static_cast<int>(std::lround(std::sqrt(double(samples_per_pixel))));
  ReferenceImage image;
  image.width_px = width_px;
  image.height_px = height_px;
  image.samples_per_pixel = samples_per_pixel;
  const size_t pixels = size_t(width_px) * height_px;
  image.color.assign(pixels, glm::vec4(0.0f));
  image.depth.assign(pixels, 1.0f);
  image.primitive_id.assign(pixels, kNoPrimitiveId);
  image.normal.assign(pixels, glm::vec3(0.0f));
  const glm::dmat4 inverse_vp = glm::inverse(ref.camera.view_projection);
  const int quad_rows = (height_px + 1) / 2;
  // Sample s of the k x k grid sits at ((i + 0.5) / k, (j + 0.5) / k); for odd k the middle
  // one is the pixel centre and gives the AOVs, for even k an extra centre ray does.
  const bool centre_in_grid = grid % 2 == 1;
  std::atomic<int> rows_done{0};
  ontile::parallel_for(tbb::blocked_range<int>(0, quad_rows), [&](const tbb::blocked_range<int>& rows) {
    std::vector<RayCandidate> hits[kQuadLanes];
    LaneResult result[kQuadLanes];
    for (int row = rows.begin(); row < rows.end(); ++row) {
      const int qy = 2 * row;
      for (int qx = 0; qx < width_px; qx += 2) {
        glm::dvec4 sum[kQuadLanes] = {};  // double: the mean of equal samples is exact
        auto store_aovs = [&] {
          for (int lane = 0; lane < kQuadLanes; ++lane) {
            const int x = qx + (lane & 1), y = qy + (lane >> 1);
            if (x >= width_px || y >= height_px) continue;
            const size_t i = size_t(y) * width_px + x;
            image.depth[i] = result[lane].depth;
            image.primitive_id[i] = result[lane].primitive_id;
            image.normal[i] = result[lane].normal;
          }
        };
        for (int j = 0; j < grid; ++j) {
          for (int i = 0; i < grid; ++i) {
            render_quad(ref, inverse_vp, width_px, height_px, qx, qy, (i + 0.5) / grid, (j + 0.5) / grid,
                        hits, result);
            for (int lane = 0; lane < kQuadLanes; ++lane) sum[lane] += glm::dvec4(result[lane].color);
            if (centre_in_grid && i == grid / 2 && j == grid / 2) store_aovs();
          }
        }
        if (!centre_in_grid) {
          render_quad(ref, inverse_vp, width_px, height_px, qx, qy, 0.5, 0.5, hits, result);
          store_aovs();
        }
        for (int lane = 0; lane < kQuadLanes; ++lane) {
          const int x = qx + (lane & 1), y = qy + (lane >> 1);
          if (x >= width_px || y >= height_px) continue;
          image.color[size_t(y) * width_px + x] = glm::vec4(sum[lane] / double(samples_per_pixel));
        }
      }
      if (progress) progress(++rows_done, quad_rows, "rows of quads ray-cast");
    }
  });
  return image;
}

std::vector<std::string> reference_channel_names() {
  return {"R", "G", "B", "A", "Z", "primid", "N.x", "N.y", "N.z"};
}

std::vector<float> reference_channels(const ReferenceImage& image) {
  std::vector<float> out;
  out.reserve(image.color.size() * 9);
  for (size_t i = 0; i < image.color.size(); ++i) {
    const glm::vec4& c = image.color[i];
    const glm::vec3& n = image.normal[i];
    out.insert(out.end(), {c.x, c.y, c.z, c.w, image.depth[i], image.primitive_id[i], n.x, n.y, n.z});
  }
  return out;
}

void write_reference_exr(const std::filesystem::path& path, const ReferenceImage& image) {
  write_exr_channels(path, image.width_px, image.height_px, reference_channel_names(), reference_channels(image));
}

}  // namespace ontile
