// Test helper: an independent double-precision expectation of how many front-facing triangles of
// a closed mesh cover each pixel centre, with the pixels whose answer snapping to 16.8 fixed
// point could change (near silhouette edges and near nearly degenerate triangles) marked.
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "raster/raster_types.h"

namespace ontile::test {

struct ProjectedCoverage {
  int width = 0, height = 0;
  std::vector<int> front;           // front-facing triangles whose interior holds the centre
  std::vector<uint8_t> uncertain;   // 1: within the snapping margin of a silhouette edge
  int uncertain_count() const { return static_cast<int>(std::count(uncertain.begin(), uncertain.end(), 1)); }
};

namespace detail {
// Screen position (y down) with the raster core's viewport transform (triangle_setup.cpp).
inline glm::dvec2 to_screen(const glm::vec4& clip, int width, int height) {
  const double inv_w = 1.0 / static_cast<double>(clip.w);
  return {(clip.x * inv_w * 0.5 + 0.5) * width, (0.5 - clip.y * inv_w * 0.5) * height};
}
inline double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}
}  // namespace detail

// Snapping moves each vertex by at most sqrt(2)/2 subpixel (round to nearest in x and y).
constexpr double kSnapDistancePx = 0.70711 / kSubpixelScale;

// `margin_px`: pixels whose centre lies within this distance of a silhouette edge are
// uncertain. A triangle whose doubled area could change sign under snapping (|area2| below
// 2 * snap * perimeter + 4 * snap^2, doubled for safety) counts as having silhouette edges.
inline ProjectedCoverage projected_front_coverage(const std::vector<glm::vec4>& clip,
                                                  const std::vector<uint32_t>& indices, int width,
                                                  int height, double margin_px) {
  ProjectedCoverage out;
  out.width = width;
  out.height = height;
  out.front.assign(static_cast<size_t>(width) * height, 0);
  out.uncertain.assign(out.front.size(), 0);
  std::vector<glm::dvec2> screen(clip.size());
  for (size_t i = 0; i < clip.size(); ++i) screen[i] = detail::to_screen(clip[i], width, height);

  const size_t triangles = indices.size() / 3;
  std::vector<int> facing(triangles);  // +1 front, -1 back, 0 ambiguous under snapping
  const double snap = kSnapDistancePx;
  for (size_t t = 0; t < triangles; ++t) {
    const glm::dvec2 a = screen[indices[3 * t]], b = screen[indices[3 * t + 1]], c = screen[indices[3 * t + 2]];
    const double area2 = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const double perimeter = glm::length(b - a) + glm::length(c - b) + glm::length(a - c);
    const double flip_bound = 2.0 * (2.0 * snap * perimeter + 4.0 * snap * snap);
    // Negative doubled area in y-down screen space = counter-clockwise in +Y-up NDC = front.
    facing[t] = std::abs(area2) <= flip_bound ? 0 : (area2 < 0.0 ? 1 : -1);
  }

  auto mark_near_segment = [&](glm::dvec2 a, glm::dvec2 b) {
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min(a.x, b.x) - margin_px - 0.5)));
    const int x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max(a.x, b.x) + margin_px - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min(a.y, b.y) - margin_px - 0.5)));
    const int y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max(a.y, b.y) + margin_px - 0.5)));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        if (detail::distance_to_segment({x + 0.5, y + 0.5}, a, b) <= margin_px) {
          out.uncertain[static_cast<size_t>(y) * width + x] = 1;
        }
      }
    }
  };

  // Silhouette edges: the two triangles sharing the edge face different ways (or may, after
  // snapping). Each undirected edge is visited from its lower-numbered triangle side only once.
  std::map<std::pair<uint32_t, uint32_t>, size_t> owner;
  for (size_t t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) owner[{indices[3 * t + k], indices[3 * t + (k + 1) % 3]}] = t;
  }
  for (const auto& [edge, t] : owner) {
    if (edge.first > edge.second) continue;
    const auto twin = owner.find({edge.second, edge.first});
    const bool silhouette = twin == owner.end() || facing[t] == 0 || facing[twin->second] == 0 ||
                            facing[t] != facing[twin->second];
    if (silhouette) mark_near_segment(screen[edge.first], screen[edge.second]);
  }

  // Front coverage of pixel centres strictly inside, in double (no snapping). A centre closer
  // than 1e-6 px to an edge is marked uncertain rather than guessed.
  for (size_t t = 0; t < triangles; ++t) {
    if (facing[t] != 1) continue;
    glm::dvec2 v[3] = {screen[indices[3 * t]], screen[indices[3 * t + 1]], screen[indices[3 * t + 2]]};
    std::swap(v[1], v[2]);  // clockwise on screen (y down): inside is where every edge is > 0
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({v[0].x, v[1].x, v[2].x}))));
    const int x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max({v[0].x, v[1].x, v[2].x}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({v[0].y, v[1].y, v[2].y}))));
    const int y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max({v[0].y, v[1].y, v[2].y}))));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const glm::dvec2 p(x + 0.5, y + 0.5);
        double min_distance = 1e300;
        for (int k = 0; k < 3; ++k) {
          const glm::dvec2 a = v[(k + 1) % 3], b = v[(k + 2) % 3];
          const double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
          min_distance = std::min(min_distance, cross / glm::length(b - a));
        }
        const size_t i = static_cast<size_t>(y) * width + x;
        if (std::abs(min_distance) < 1e-6) out.uncertain[i] = 1;
        if (min_distance > 0.0) ++out.front[i];
      }
    }
  }
  return out;
}

}  // namespace ontile::test
