// Triangle setup (see triangle_setup.h).
#include "raster/triangle_setup.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ontile {
namespace {

// Floor division for possibly negative numerators.
int64_t floor_div(int64_t n, int64_t d) { return n >= 0 ? n / d : -((-n + d - 1) / d); }

EdgeFunction make_edge(int32_t xj, int32_t yj, int32_t xk, int32_t yk) {
  const int64_t dx = int64_t{xk} - xj;
  const int64_t dy = int64_t{yk} - yj;
  EdgeFunction e;
  e.a = -dy;
  e.b = dx;
  e.c = dy * xj - dx * yj;
  // With positive area in y-down screen space the vertices run clockwise on screen: a top
  // edge runs left to right (dy == 0, dx > 0) and a left edge runs upwards (dy < 0).
  const bool top_left = (dy == 0 && dx > 0) || dy < 0;
  e.bias = top_left ? 0 : -1;
  return e;
}

}  // namespace

SetupResult setup_triangle(const glm::vec4 clip[3], int width_px, int height_px, CullMode cull,
                           FrontFace front_face, TriangleSetup& t, int subpixel_bits) {
  // Snapping grid: 2^subpixel_bits steps per pixel, each `grid_step` units of 1/256 px.
  const double snap_scale = static_cast<double>(int64_t{1} << subpixel_bits);
  const int64_t grid_step = kSubpixelScale >> subpixel_bits;
  for (int i = 0; i < 3; ++i) {
    // Viewport transform in double so snapping sees the exact rounding of the divide.
    const double inv_w = 1.0 / static_cast<double>(clip[i].w);
    const double ndc_x = clip[i].x * inv_w;
    const double ndc_y = clip[i].y * inv_w;
    const double sx = (ndc_x * 0.5 + 0.5) * width_px;
    const double sy = (0.5 - ndc_y * 0.5) * height_px;  // +Y up in NDC, rows go down
    // Round to the nearest point of the snapping grid (D3D11 3.2.4.1 snapping); scaling by a
    // power of two is exact, so at 8 bits this is llround(sx * 256) as before.
    t.x_fp[i] = static_cast<int32_t>(std::llround(sx * snap_scale) * grid_step);
    t.y_fp[i] = static_cast<int32_t>(std::llround(sy * snap_scale) * grid_step);
    t.depth[i] = static_cast<float>(clip[i].z * inv_w);
    t.inv_w[i] = static_cast<float>(inv_w);
    t.vertex_order[i] = static_cast<uint8_t>(i);
  }
  int64_t area2 = (int64_t{t.x_fp[1]} - t.x_fp[0]) * (int64_t{t.y_fp[2]} - t.y_fp[0]) -
                  (int64_t{t.x_fp[2]} - t.x_fp[0]) * (int64_t{t.y_fp[1]} - t.y_fp[0]);
  if (area2 == 0) return SetupResult::ZeroArea;
  // Negative area in y-down screen space = counter-clockwise in +Y-up NDC.
  const bool ccw = area2 < 0;
  t.front_facing = (front_face == FrontFace::CounterClockwise) == ccw;
  if ((cull == CullMode::Back && !t.front_facing) || (cull == CullMode::Front && t.front_facing)) {
    return SetupResult::Culled;
  }
  if (area2 < 0) {
    std::swap(t.x_fp[1], t.x_fp[2]);
    std::swap(t.y_fp[1], t.y_fp[2]);
    std::swap(t.depth[1], t.depth[2]);
    std::swap(t.inv_w[1], t.inv_w[2]);
    std::swap(t.vertex_order[1], t.vertex_order[2]);
    area2 = -area2;
  }
  t.area2 = area2;
  t.inv_area2 = 1.0 / static_cast<double>(area2);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    t.edge[i] = make_edge(t.x_fp[j], t.y_fp[j], t.x_fp[k], t.y_fp[k]);
  }
  // Conservative pixel range: any sample inside a pixel may be covered.
  const int32_t min_xf = std::min({t.x_fp[0], t.x_fp[1], t.x_fp[2]});
  const int32_t max_xf = std::max({t.x_fp[0], t.x_fp[1], t.x_fp[2]});
  const int32_t min_yf = std::min({t.y_fp[0], t.y_fp[1], t.y_fp[2]});
  const int32_t max_yf = std::max({t.y_fp[0], t.y_fp[1], t.y_fp[2]});
  t.min_x = static_cast<int>(std::max<int64_t>(floor_div(min_xf, kSubpixelScale), 0));
  t.min_y = static_cast<int>(std::max<int64_t>(floor_div(min_yf, kSubpixelScale), 0));
  t.max_x = static_cast<int>(std::min<int64_t>(floor_div(max_xf, kSubpixelScale), width_px - 1));
  t.max_y = static_cast<int>(std::min<int64_t>(floor_div(max_yf, kSubpixelScale), height_px - 1));
  if (t.min_x > t.max_x || t.min_y > t.max_y) return SetupResult::OutsideViewport;
  return SetupResult::Ok;
}

}  // namespace ontile
