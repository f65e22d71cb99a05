// Scene-wide helpers: the drawn triangle total and the default camera that frames the
// scene's bounds when the file brings no camera.
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ontile {

uint64_t Scene::drawn_triangle_count() const {
  uint64_t triangles = 0;
  for (const MeshInstance& instance : instances) {
    if (instance.mesh < 0 || static_cast<size_t>(instance.mesh) >= meshes.size()) continue;
    for (const MeshPrimitive& primitive : meshes[static_cast<size_t>(instance.mesh)].primitives) {
      triangles += primitive.triangle_count();
    }
  }
  return triangles;
}

// Perspective, 45 degree vertical FOV, on the +Z side of the bounds' centre raised by 15
// degrees, looking at the centre with +Y up. The distance makes the bounding sphere (radius r)
// touch the narrower of the vertical FOV and the horizontal FOV at 16:9: d = r / sin(half
// angle). The depth range hugs the sphere with 10% slack: znear = max(d - 1.1 r, d / 1000)
// (the floor keeps depth precision when the camera is close), zfar = d + 1.1 r. An empty
// scene, or one that is a single point, is framed as a unit sphere.
Camera default_camera(const Scene& scene) {
  constexpr double kYfovRad = 45.0 * std::numbers::pi / 180.0;
  constexpr double kElevationRad = 15.0 * std::numbers::pi / 180.0;
  constexpr double kFramingAspect = 16.0 / 9.0;

  glm::dvec3 center(0.0);
  double radius = 1.0;
  if (!scene.world_bounds.empty()) {
    center = glm::dvec3(scene.world_bounds.center());
    const double half_diagonal =
        0.5 * glm::length(glm::dvec3(scene.world_bounds.max) - glm::dvec3(scene.world_bounds.min));
    if (half_diagonal > 0.0 && std::isfinite(half_diagonal)) radius = half_diagonal;
  }
  const double half_vertical = kYfovRad / 2.0;
  const double half_horizontal = std::atan(std::tan(half_vertical) * kFramingAspect);
  const double distance = radius / std::sin(std::min(half_vertical, half_horizontal));

  const glm::dvec3 back(0.0, std::sin(kElevationRad), std::cos(kElevationRad));  // eye - center
  const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0.0, 1.0, 0.0), back));
  const glm::dvec3 up = glm::cross(back, right);
  const glm::dvec3 eye = center + distance * back;

  Camera camera;
  camera.type = Camera::Type::Perspective;
  camera.name = "default";
  camera.yfov_rad = static_cast<float>(kYfovRad);
  camera.aspect_ratio = 0.0f;  // follow the image
  camera.znear = static_cast<float>(std::max(distance - 1.1 * radius, distance * 1e-3));
  camera.zfar = static_cast<float>(distance + 1.1 * radius);
  glm::dmat4 world(1.0);
  world[0] = glm::dvec4(right, 0.0);
  world[1] = glm::dvec4(up, 0.0);
  world[2] = glm::dvec4(back, 0.0);
  world[3] = glm::dvec4(eye, 1.0);
  camera.world = world;
  return camera;
}

}  // namespace ontile
