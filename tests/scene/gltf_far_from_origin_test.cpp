// Far from the origin through glTF: the same scene written as a .gltf at the origin and with
// its mesh node and camera node both translated by 1e5, 1e6 and 1e7 renders the same primitive
// id at every pixel (rasterizer AOV pass and Embree reference), because node and camera
// transforms are composed and kept in double and folded into the model-view-projection before
// anything goes to float (docs/stability.md, "Far from the origin through glTF").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gltf_test_files.h"
#include "aov/aov_pass.h"
#include "reference/reference_renderer.h"
#include "reference/reference_shading.h"
#include "scene/gltf_loader.h"

namespace ontile {
namespace {

using nlohmann::json;

constexpr int kWidthPx = 160, kHeightPx = 120;
constexpr int kGridVertices = 32;  // per side: 2 * 31 * 31 = 1922 triangles

// Node positions are multiples of 2^-16: offset + position is exact in double up to 1e11, so
// the offset scenes hold exactly the origin scene's relative geometry and any difference in
// the images is the renderer's. In float they are not exact from 1e5 on (17 + 16 bits).
const glm::dvec3 kMeshTranslation(16473 / 65536.0, -24589 / 65536.0, 8195 / 65536.0);
const glm::dvec3 kCameraTranslation(98311 / 65536.0, 81929 / 65536.0, 262147 / 65536.0);
const glm::dvec3 kOffsetDirection(1.0, -0.5, 0.75);

// A bumpy, jittered grid (object space, float): many edges in view, several of them
// silhouettes, so a shift of a fraction of a pixel changes ids somewhere.
void add_grid_mesh(test::GltfBuilder& b) {
  std::vector<float> positions, normals;
  for (int j = 0; j < kGridVertices; ++j) {
    for (int i = 0; i < kGridVertices; ++i) {
      const double u = -1.0 + 2.0 * i / (kGridVertices - 1), v = -1.0 + 2.0 * j / (kGridVertices - 1);
      const double jitter = 0.013 * std::sin(12.9898 * i + 78.233 * j);
      positions.push_back(static_cast<float>(u + jitter));
      positions.push_back(static_cast<float>(v - jitter));
      positions.push_back(static_cast<float>(0.3 * std::sin(3.0 * u) * std::cos(2.0 * v)));
      normals.insert(normals.end(), {0.0f, 0.0f, 1.0f});
    }
  }
  std::vector<uint16_t> indices;
  for (int j = 0; j + 1 < kGridVertices; ++j) {
    for (int i = 0; i + 1 < kGridVertices; ++i) {
      const auto at = [](int x, int y) { return static_cast<uint16_t>(y * kGridVertices + x); };
      indices.insert(indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      indices.insert(indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  const int position = b.add_positions(positions);
  const int normal = b.add_data(normals, test::kFloat, "VEC3", normals.size() / 3);
  const int index = b.add_data(indices, test::kUnsignedShort, "SCALAR", indices.size());
  // Double sided: both faces of the bumps are drawn, so culling plays no part.
  b.json["materials"] = json::array({{{"doubleSided", true}}});
  b.add_mesh(json::array(
      {{{"attributes", {{"POSITION", position}, {"NORMAL", normal}}}, {"indices", index}, {"material", 0}}}));
}

json vec(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }
json quat(const glm::dquat& q) { return json::array({q.x, q.y, q.z, q.w}); }

// The scene with both nodes translated by `offset` (glTF JSON numbers are doubles; nlohmann
// writes them with round-trip precision).
std::filesystem::path write_scene(const std::filesystem::path& dir, const std::string& name,
                                  const glm::dvec3& offset) {
  test::GltfBuilder b;
  add_grid_mesh(b);
  const glm::dquat mesh_rotation = glm::normalize(glm::dquat(0.95, 0.2, 0.3, -0.1));  // w, x, y, z
  b.add_node({{"name", "grid"},
              {"mesh", 0},
              {"translation", vec(kMeshTranslation + offset)},
              {"rotation", quat(mesh_rotation)},
              {"scale", {1.25, 1.25, 1.25}}});
  // Camera-to-world of a camera at kCameraTranslation looking at the mesh, as a quaternion.
  const glm::dmat4 view = glm::lookAt(kCameraTranslation, kMeshTranslation, glm::dvec3(0.0, 1.0, 0.0));
  const glm::dquat camera_rotation = glm::quat_cast(glm::transpose(glm::dmat3(view)));
  b.add_node({{"name", "camera"},
              {"camera", 0},
              {"translation", vec(kCameraTranslation + offset)},
              {"rotation", quat(camera_rotation)}});
  b.json["cameras"] = json::array(
      {{{"type", "perspective"}, {"perspective", {{"yfov", 0.55}, {"znear", 0.05}, {"zfar", 50.0}}}}});
  b.json["scenes"] = json::array({{{"nodes", {0, 1}}}});
  return b.write(dir, name);
}

std::vector<float> rasterized_ids(const Scene& scene) {
  RenderSettings settings;
  settings.width_px = kWidthPx;
  settings.height_px = kHeightPx;
  settings.context.threads = 2;
  const AovFrame frame = render_aov_frame(scene, settings, {AovKind::PrimitiveId});
  return aov_channels(*frame.surfaces.at(0), AovKind::PrimitiveId);
}

std::vector<float> reference_ids(const Scene& scene) {
  const LambertReferenceScene ref = make_lambert_reference_scene(scene, scene.cameras.at(0), kWidthPx, kHeightPx);
  return render_reference(ref, kWidthPx, kHeightPx, 1).primitive_id;
}

int differing_pixels(const std::vector<float>& a, const std::vector<float>& b) {
  int differing = 0;
  for (size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i];
  return differing;
}

TEST(GltfFarFromOrigin, PrimitiveIdsAtEveryPixelMatchTheOriginUpTo1e7) {
  const auto dir = test::gltf_test_dir();
  const Scene at_origin = load_gltf(write_scene(dir, "origin", glm::dvec3(0.0)));
  const std::vector<float> expected = rasterized_ids(at_origin);
  // The scene is a real test: most pixels covered, by many different triangles.
  int covered = 0;
  std::set<float> distinct;
  for (float id : expected) {
    covered += id >= 0.0f;
    if (id >= 0.0f) distinct.insert(id);
  }
  EXPECT_GT(covered, kWidthPx * kHeightPx / 2);
  EXPECT_GT(distinct.size(), 1000u);
  for (double distance : {1e5, 1e6, 1e7}) {
    const auto path = write_scene(dir, "offset_" + std::to_string(static_cast<long long>(distance)),
                                  distance * kOffsetDirection);
    const Scene offset = load_gltf(path);
    // The node translations arrive unrounded (float would hold 1e6 only to 1/16 unit).
    EXPECT_EQ(glm::dvec3(offset.instances.at(0).world[3]), kMeshTranslation + distance * kOffsetDirection);
    EXPECT_EQ(glm::dvec3(offset.cameras.at(0).world[3]), kCameraTranslation + distance * kOffsetDirection);
    EXPECT_EQ(differing_pixels(rasterized_ids(offset), expected), 0) << distance << " units away";
  }
}

TEST(GltfFarFromOrigin, EmbreeReferenceIdsMatchTheOriginAt1e6) {
  const auto dir = test::gltf_test_dir();
  const std::vector<float> expected = reference_ids(load_gltf(write_scene(dir, "origin", glm::dvec3(0.0))));
  EXPECT_GT(std::count_if(expected.begin(), expected.end(), [](float id) { return id >= 0.0f; }),
            kWidthPx * kHeightPx / 2);
  for (double distance : {1e5, 1e6}) {
    const auto path = write_scene(dir, "offset_" + std::to_string(static_cast<long long>(distance)),
                                  distance * kOffsetDirection);
    EXPECT_EQ(differing_pixels(reference_ids(load_gltf(path)), expected), 0) << distance << " units away";
  }
}

}  // namespace
}  // namespace ontile
