// Columns, balustrades and vases of the "atrium" courtyard (see atrium_parts.h). Proportions
// loosely follow a Tuscan/Doric order: base and capital take about 1 m at scale 1.
#include "scene/gen/atrium_parts.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace ontile::gen {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kHalfPi = static_cast<float>(kPi / 2);
constexpr float kMarbleMetresPerRepeat = 1.0f;

// Heights of the parts of a column at scale 1, bottom to top.
constexpr float kPlinthHeight = 0.25f, kBaseHeight = 0.28f, kCapitalHeight = 0.5f;
constexpr float kEchinusTop = 0.30f;  // above the shaft top; the abacus fills the rest

// Balustrade dimensions.
constexpr float kBaseCourseHeight = 0.12f, kBalusterHeight = 0.72f, kRailHeight = 0.14f;
constexpr float kBalusterSpacing = 0.36f;

double gaussian(double x, double centre, double width) {
  const double t = (x - centre) / width;
  return std::exp(-t * t);
}

int count(double base, double detail, int minimum) { return scaled_segments(base, detail, minimum); }

}  // namespace

float column_height_m(float shaft_height_m, float scale) {
  return shaft_height_m + (kPlinthHeight + kBaseHeight + kCapitalHeight) * scale;
}

MeshData column_mesh(float shaft_height_m, float s, double detail) {
  MeshData mesh;
  const float base_y = kPlinthHeight * s;
  const float shaft_bottom = base_y + kBaseHeight * s;
  const float shaft_top = shaft_bottom + shaft_height_m;
  const float shaft_radius = 0.30f * s;
  const float top_radius = shaft_radius * 0.88f;  // entasis: 12 % narrower at the top
  const int torus_rows = count(5, detail, 2);
  std::vector<ProfileRun> runs;
  runs.push_back(profile_arc({0.36f * s, base_y + 0.08f * s}, 0.08f * s, -kHalfPi, kHalfPi, torus_rows));
  runs.push_back(profile_line({0.36f * s, base_y + 0.16f * s}, {0.32f * s, base_y + 0.18f * s}, 1));
  runs.push_back(profile_arc({0.32f * s, base_y + 0.23f * s}, 0.05f * s, -kHalfPi, kHalfPi, torus_rows));
  runs.push_back(profile_curve(
      [&](double t) {
        return glm::dvec2(shaft_radius * (1.0 - 0.12 * t * t), shaft_bottom + t * shaft_height_m);
      },
      count(16, detail, 1)));
  runs.push_back(profile_arc({top_radius, shaft_top + 0.03f * s}, 0.03f * s, -kHalfPi, kHalfPi,
                             count(3, detail, 2)));
  runs.push_back(profile_line({top_radius, shaft_top + 0.06f * s}, {top_radius, shaft_top + 0.10f * s}, 1));
  runs.push_back(profile_arc({top_radius, shaft_top + kEchinusTop * s}, 0.2f * s, -kHalfPi, 0.0f,
                             count(6, detail, 2)));
  const float circumference = 2.0f * static_cast<float>(kPi) * shaft_radius;
  add_lathe(mesh, runs, count(28, detail, 8), std::max(1.0f, std::round(circumference)),
            kMarbleMetresPerRepeat);

  const float cells_per_metre = static_cast<float>(4.0 * detail);
  add_box(mesh, {-0.45f * s, 0.0f, -0.45f * s}, {0.45f * s, base_y, 0.45f * s}, cells_per_metre,
          kMarbleMetresPerRepeat, kBoxAllFaces & ~kBoxNegY);
  add_box(mesh, {-0.5f * s, shaft_top + kEchinusTop * s, -0.5f * s},
          {0.5f * s, column_height_m(shaft_height_m, s), 0.5f * s}, cells_per_metre,
          kMarbleMetresPerRepeat);
  return mesh;
}

float balustrade_height_m() { return kBaseCourseHeight + kBalusterHeight + kRailHeight; }

MeshData balustrade_bay_mesh(float width_m, double detail) {
  MeshData mesh;
  const float half = width_m * 0.5f;
  const float cells_per_metre = static_cast<float>(2.0 * detail);
  add_box(mesh, {-half, 0.0f, -0.15f}, {half, kBaseCourseHeight, 0.15f}, cells_per_metre,
          kMarbleMetresPerRepeat, kBoxAllFaces & ~kBoxNegY);
  const float rail_bottom = kBaseCourseHeight + kBalusterHeight;
  add_box(mesh, {-half, rail_bottom, -0.18f}, {half, rail_bottom + kRailHeight, 0.18f},
          cells_per_metre, kMarbleMetresPerRepeat);
  // Turned baluster: foot ring, pear-shaped belly, slender neck, collar under the rail.
  const std::vector<ProfileRun> baluster = {profile_curve(
      [](double t) {
        const double y = t * kBalusterHeight;
        return glm::dvec2(0.045 + 0.06 * gaussian(y, 0.25, 0.12) + 0.035 * gaussian(y, 0.66, 0.05) +
                              0.03 * gaussian(y, 0.04, 0.04),
                          y);
      },
      count(16, detail, 4))};
  const int balusters = std::max(1, static_cast<int>(width_m / kBalusterSpacing));
  const float spacing = width_m / static_cast<float>(balusters);
  const int radial = count(12, detail, 6);
  for (int i = 0; i < balusters; ++i) {
    const float x = -half + spacing * (static_cast<float>(i) + 0.5f);
    add_lathe(mesh, baluster, radial, 1.0f, kMarbleMetresPerRepeat,
              glm::translate(glm::mat4(1.0f), glm::vec3(x, kBaseCourseHeight, 0.0f)));
  }
  return mesh;
}

MeshData vase_mesh(double detail) {
  MeshData mesh;
  constexpr double kTop = 1.02;
  const auto radius = [](double y) {
    return 0.17 + 0.25 * gaussian(y, 0.42, 0.26) + 0.09 * gaussian(y, 1.0, 0.06);
  };
  const std::vector<ProfileRun> runs = {
      profile_line({0.0f, 0.0f}, {static_cast<float>(radius(0.0)), 0.0f}, 1),
      profile_curve([&](double t) { return glm::dvec2(radius(t * kTop), t * kTop); },
                    count(36, detail, 4)),
      // Soil surface, slightly sunk below the lip.
      profile_line({static_cast<float>(radius(kTop)), static_cast<float>(kTop)}, {0.0f, 0.97f}, 1)};
  add_lathe(mesh, runs, count(40, detail, 8), 2.0f, 1.0f);
  return mesh;
}

}  // namespace ontile::gen
