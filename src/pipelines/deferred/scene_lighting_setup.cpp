// Scene lights, generated lights and light-grid construction (see scene_lighting_setup.h).
#include "pipelines/deferred/scene_lighting_setup.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "pipelines/kit/pipeline_api.h"
#include "pipelines/universal/universal_lights.h"

namespace ontile {
namespace {

// SplitMix64 (Steele et al., "Fast splittable pseudorandom number generators", 2014): a fixed,
// portable sequence, unlike std::uniform_real_distribution whose output is implementation-defined.
class SplitMix64 {
 public:
  explicit SplitMix64(uint64_t seed) : state_(seed) {}
  float next_unit() {  // [0, 1) with 24 random bits
    state_ += 0x9E3779B97F4A7C15ull;
    uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<float>(z >> 40) / 16777216.0f;
  }

 private:
  uint64_t state_;
};

glm::vec3 hue_to_rgb(float hue) {  // fully saturated, hue in [0, 1)
  const glm::vec3 k(0.0f, 2.0f / 3.0f, 1.0f / 3.0f);
  glm::vec3 rgb;
  for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(std::abs(std::fmod(hue + k[c], 1.0f) * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
  return rgb;
}

}  // namespace

std::vector<PunctualLight> generate_point_lights(const Bounds& b, int count) {
  std::vector<PunctualLight> lights;
  if (count <= 0 || b.empty()) return lights;
  const glm::vec3 size = b.max - b.min;
  const float diagonal = glm::length(size);
  const float range = 0.6f * diagonal / std::cbrt(static_cast<float>(count));
  SplitMix64 random(0x6F6E74696C65ull);  // "ontile"
  lights.reserve(count);
  for (int i = 0; i < count; ++i) {
    PunctualLight l;
    l.type = PunctualLight::Type::Point;
    // Inside the central 90% horizontally and between 5% and 60% of the height.
    const float u = random.next_unit(), v = random.next_unit(), w = random.next_unit();
    l.position = b.min + size * glm::vec3(0.05f + 0.9f * u, 0.05f + 0.55f * v, 0.05f + 0.9f * w);
    const glm::vec3 color = glm::mix(glm::vec3(1.0f), hue_to_rgb(random.next_unit()), 0.7f);
    l.intensity = color * (0.05f * range * range);
    l.range = range;
    lights.push_back(l);
  }
  return lights;
}

LightGrid build_light_grid(const std::vector<PunctualLight>& lights, const CameraMatrices& camera,
                           int width_px, int height_px) {
  LightGrid grid;
  grid.cells_x = (width_px + LightGrid::kCellSizePx - 1) / LightGrid::kCellSizePx;
  grid.cells_y = (height_px + LightGrid::kCellSizePx - 1) / LightGrid::kCellSizePx;
  const size_t cells = static_cast<size_t>(grid.cells_x) * grid.cells_y;
  struct CellRect { int x0, y0, x1, y1; };  // inclusive cell range
  std::vector<CellRect> rects(lights.size(), CellRect{0, 0, -1, -1});
  std::vector<uint32_t> counts(cells, 0);
  for (size_t i = 0; i < lights.size(); ++i) {
    const PunctualLight& l = lights[i];
    CellRect r{0, 0, grid.cells_x - 1, grid.cells_y - 1};
    if (l.type != PunctualLight::Type::Directional && l.range > 0.0f) {
      Bounds box;
      box.extend(l.position - glm::vec3(l.range));
      box.extend(l.position + glm::vec3(l.range));
      if (box_outside_frustum(camera.view_projection, box)) continue;
      double x_min = 1.0, x_max = -1.0, y_min = 1.0, y_max = -1.0;
      bool behind = false;
      for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                           (corner & 4) ? box.max.z : box.min.z);
        const glm::dvec4 clip = camera.view_projection * glm::dvec4(p, 1.0);
        if (!(clip.w > 1e-9)) {
          behind = true;
          break;
        }
        x_min = std::min(x_min, clip.x / clip.w);
        x_max = std::max(x_max, clip.x / clip.w);
        y_min = std::min(y_min, clip.y / clip.w);
        y_max = std::max(y_max, clip.y / clip.w);
      }
      if (!behind) {
        // NDC to pixels (+Y up in NDC, rows top down), then to cells, clamped to the screen.
        auto cell_x = [&](double ndc) {
          return std::clamp(static_cast<int>(std::floor((ndc * 0.5 + 0.5) * width_px / LightGrid::kCellSizePx)), 0, grid.cells_x - 1);
        };
        auto cell_y = [&](double ndc) {
          return std::clamp(static_cast<int>(std::floor((0.5 - ndc * 0.5) * height_px / LightGrid::kCellSizePx)), 0, grid.cells_y - 1);
        };
        if (x_max < -1.0 || x_min > 1.0 || y_max < -1.0 || y_min > 1.0) continue;
        r = {cell_x(x_min), cell_y(y_max), cell_x(x_max), cell_y(y_min)};
      }
    }
    rects[i] = r;
    for (int cy = r.y0; cy <= r.y1; ++cy) {
      for (int cx = r.x0; cx <= r.x1; ++cx) ++counts[static_cast<size_t>(cy) * grid.cells_x + cx];
    }
  }
  grid.cell_begin.assign(cells + 1, 0);
  for (size_t c = 0; c < cells; ++c) grid.cell_begin[c + 1] = grid.cell_begin[c] + counts[c];
  grid.light_indices.resize(grid.cell_begin[cells]);
  std::vector<uint32_t> fill(grid.cell_begin.begin(), grid.cell_begin.end() - 1);
  for (size_t i = 0; i < lights.size(); ++i) {  // ascending light order within every cell
    const CellRect& r = rects[i];
    for (int cy = r.y0; cy <= r.y1; ++cy) {
      for (int cx = r.x0; cx <= r.x1; ++cx) grid.light_indices[fill[static_cast<size_t>(cy) * grid.cells_x + cx]++] = static_cast<uint32_t>(i);
    }
  }
  return grid;
}

SceneLighting make_scene_lighting(const Scene& scene, int generated_lights, const CameraMatrices& camera,
                                  int width_px, int height_px) {
  const UniversalLights scene_lights = universal_lights(scene);
  SceneLighting s;
  s.ambient = scene_lights.ambient;
  s.sun_to_light = scene_lights.main.to_light;
  s.sun_radiance = scene_lights.main.radiance;
  s.lights = scene_lights.additional;
  const std::vector<PunctualLight> generated = generate_point_lights(scene.world_bounds, generated_lights);
  s.lights.insert(s.lights.end(), generated.begin(), generated.end());
  s.grid = build_light_grid(s.lights, camera, width_px, height_px);
  return s;
}

}  // namespace ontile
