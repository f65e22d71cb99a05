// Arch panels and hanging cloths for the generated courtyard (see architecture_shapes.h).
#include "scene/gen/architecture_shapes.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "util/error.h"

namespace ontile::gen {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One sample of the panel face: the point on the opening and the matching point on the
// panel's outer edge (right side, top, left side) that the radial rows interpolate between.
struct ArchColumn {
  double angle_rad;
  glm::vec2 outer;
};

// Splits the opening into three angular ranges that map onto the right side, the top and the
// left side of the panel, so the panel's top corners are exact sample points (a purely radial
// mapping would cut them off).
std::vector<ArchColumn> arch_columns(const ArchPanelShape& s) {
  const double half_span = s.span_m * 0.5;
  const double corner_angle = std::atan2(static_cast<double>(s.height_m), half_span);
  const int side_columns =
      std::max(1, static_cast<int>(std::lround(s.arc_segments * corner_angle / kPi)));
  const int top_columns = std::max(1, s.arc_segments - 2 * side_columns);
  const glm::vec2 right_bottom(s.span_m * 0.5f, 0.0f), right_top(s.span_m * 0.5f, s.height_m);
  const glm::vec2 left_top(-s.span_m * 0.5f, s.height_m), left_bottom(-s.span_m * 0.5f, 0.0f);
  struct Range {
    int columns;
    double angle0, angle1;
    glm::vec2 outer0, outer1;
  };
  const Range ranges[] = {{side_columns, 0.0, corner_angle, right_bottom, right_top},
                          {top_columns, corner_angle, kPi - corner_angle, right_top, left_top},
                          {side_columns, kPi - corner_angle, kPi, left_top, left_bottom}};
  std::vector<ArchColumn> columns;
  for (const Range& range : ranges) {
    const int first = columns.empty() ? 0 : 1;  // ranges share their end columns
    for (int i = first; i <= range.columns; ++i) {
      const double t = static_cast<double>(i) / range.columns;
      columns.push_back({range.angle0 + (range.angle1 - range.angle0) * t,
                         range.outer0 + (range.outer1 - range.outer0) * static_cast<float>(t)});
    }
  }
  return columns;
}

}  // namespace

void add_arch_panel(MeshData& faces, MeshData& soffit, const ArchPanelShape& s,
                    const glm::mat4& transform) {
  if (!(s.height_m > s.inner_radius_m && s.inner_radius_m < s.span_m * 0.5f)) {
    throw Error("scene generator: arch opening does not fit inside its panel");
  }
  const std::vector<ArchColumn> columns = arch_columns(s);
  const int cols = static_cast<int>(columns.size()) - 1;
  std::vector<glm::vec2> inner(columns.size());
  for (size_t i = 0; i < columns.size(); ++i) {
    inner[i] = glm::vec2(static_cast<float>(std::cos(columns[i].angle_rad)),
                         static_cast<float>(std::sin(columns[i].angle_rad))) *
               s.inner_radius_m;
  }
  for (const float side : {1.0f, -1.0f}) {
    const float z = side * s.thickness_m * 0.5f;
    add_surface_grid(
        faces, cols, s.radial_segments,
        [&](int col, int row) {
          const float t = static_cast<float>(row) / static_cast<float>(s.radial_segments);
          const glm::vec2 p = inner[col] + (columns[col].outer - inner[col]) * t;
          // Planar mapping; the back face mirrors u so the texture is not seen reversed.
          return SurfacePoint{glm::vec3(p, z), glm::vec3(0.0f, 0.0f, side),
                              glm::vec2(side * p.x, p.y) / s.uv_metres_per_repeat};
        },
        transform);
  }
  std::vector<float> arc_length_m(columns.size(), 0.0f);
  for (size_t i = 1; i < columns.size(); ++i) {
    arc_length_m[i] = arc_length_m[i - 1] + glm::length(inner[i] - inner[i - 1]);
  }
  add_surface_grid(
      soffit, cols, s.depth_segments,
      [&](int col, int row) {
        const float t = static_cast<float>(row) / static_cast<float>(s.depth_segments);
        const float z = (t - 0.5f) * s.thickness_m;
        return SurfacePoint{glm::vec3(inner[col], z), glm::vec3(-inner[col], 0.0f),
                            glm::vec2(arc_length_m[col], z) / s.uv_metres_per_repeat};
      },
      transform);
}

void add_cloth(MeshData& mesh, const ClothShape& s, const glm::mat4& transform) {
  const double two_pi_f = 2.0 * kPi * s.fold_count;
  add_surface_grid(
      mesh, s.cols, s.rows,
      [&](int col, int row) {
        const double u = static_cast<double>(col) / s.cols;
        const double v = static_cast<double>(row) / s.rows;
        // Folds deepen towards the free bottom edge; the billow (towards -z) grows with v^2.
        const double fold_amplitude = s.fold_depth_m * (0.35 + 0.65 * v);
        const double fold_slope_v = s.fold_depth_m * 0.65;
        const double phase = two_pi_f * u + s.fold_phase_rad;
        const double bulge = std::sin(kPi * u);
        const double z = fold_amplitude * std::sin(phase) - s.billow_m * bulge * v * v;
        const double dz_du = fold_amplitude * two_pi_f * std::cos(phase) -
                             s.billow_m * kPi * std::cos(kPi * u) * v * v;
        const double dz_dv = fold_slope_v * std::sin(phase) - 2.0 * s.billow_m * bulge * v;
        const glm::dvec3 d_du(s.width_m, 0.0, dz_du), d_dv(0.0, -s.drop_m, dz_dv);
        // cross(d_du, d_dv) has z = -width * drop < 0: the front faces -z.
        const glm::dvec3 normal = glm::cross(d_du, d_dv);
        return SurfacePoint{
            glm::vec3(static_cast<float>((u - 0.5) * s.width_m),
                      static_cast<float>(-v * s.drop_m), static_cast<float>(z)),
            glm::vec3(normal),
            glm::vec2(static_cast<float>(u), static_cast<float>(v * s.drop_m / s.width_m))};
      },
      transform);
}

}  // namespace ontile::gen
