// Triangle setup (see triangle_setup.h).
#include "raster/triangle_setup.h"

#include <algorithm>
#include <utility>

namespace ontile {
namespace {

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
  const SnappedVertex vertex[3] = {snap_vertex(clip[0], width_px, height_px, subpixel_bits),
                                   snap_vertex(clip[1], width_px, height_px, subpixel_bits),
                                   snap_vertex(clip[2], width_px, height_px, subpixel_bits)};
  return setup_snapped_triangle(vertex, width_px, height_px, cull, front_face, t);
}

SetupResult setup_snapped_triangle(const SnappedVertex vertex[3], int width_px, int height_px,
                                   CullMode cull, FrontFace front_face, TriangleSetup& t) {
  for (int i = 0; i < 3; ++i) {
    t.x_fp[i] = vertex[i].x_fp;
    t.y_fp[i] = vertex[i].y_fp;
    t.depth[i] = vertex[i].depth;
    t.inv_w[i] = vertex[i].inv_w;
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
  // Conservative pixel range: any sample inside a pixel may be covered. The arithmetic shift
  // is floor division by kSubpixelScale, negative positions included (C++20 [expr.shift]).
  const int32_t min_xf = std::min({t.x_fp[0], t.x_fp[1], t.x_fp[2]});
  const int32_t max_xf = std::max({t.x_fp[0], t.x_fp[1], t.x_fp[2]});
  const int32_t min_yf = std::min({t.y_fp[0], t.y_fp[1], t.y_fp[2]});
  const int32_t max_yf = std::max({t.y_fp[0], t.y_fp[1], t.y_fp[2]});
  t.min_x = std::max(min_xf >> kSubpixelBits, 0);
  t.min_y = std::max(min_yf >> kSubpixelBits, 0);
  t.max_x = std::min(max_xf >> kSubpixelBits, width_px - 1);
  t.max_y = std::min(max_yf >> kSubpixelBits, height_px - 1);
  if (t.min_x > t.max_x || t.min_y > t.max_y) return SetupResult::OutsideViewport;
  return SetupResult::Ok;
}

}  // namespace ontile
