// Loads the Khronos sample models in ../shared/assets and checks counts and values against
// the assets README and the files' own bytes.
#include "scene/gltf_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#ifndef ONTILE_SHARED_ASSETS
#define ONTILE_SHARED_ASSETS "/work/shared/assets"
#endif

namespace ontile {
namespace {

std::filesystem::path asset(const std::string& relative) {
  return std::filesystem::path(ONTILE_SHARED_ASSETS) / relative;
}

#define REQUIRE_ASSETS()                                    \
  if (!std::filesystem::is_directory(ONTILE_SHARED_ASSETS)) \
  GTEST_SKIP() << "shared assets not found at " << ONTILE_SHARED_ASSETS

bool all_finite(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

// Camera frames must be rigid: unit, mutually orthogonal axes.
void expect_rigid(const glm::dmat4& m) {
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(glm::length(glm::dvec3(m[axis])), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(glm::dvec3(m[0]), glm::dvec3(m[1])), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(glm::dvec3(m[1]), glm::dvec3(m[2])), 0.0, 1e-12);
  EXPECT_NEAR(glm::determinant(glm::dmat3(m)), 1.0, 1e-12);
}

TEST(GltfAssets, EveryModelLoadsWithReadmeDrawnTriangleCount) {
  REQUIRE_ASSETS();
  const std::vector<std::pair<std::string, uint64_t>> models = {
      {"DamagedHelmet/DamagedHelmet.glb", 15452},
      {"Suzanne/Suzanne.gltf", 3936},
      {"Duck/Duck.gltf", 4212},
      {"BoxTextured/BoxTextured.gltf", 12},
      {"Fox/Fox.glb", 576},
      {"LightsPunctualLamp/LightsPunctualLamp.gltf", 6000},
      {"ToyCar/ToyCar.gltf", 108936},
      {"CesiumMilkTruck/CesiumMilkTruck.gltf", 3624},
      {"TextureCoordinateTest/TextureCoordinateTest.gltf", 10},
      {"OrientationTest/OrientationTest.gltf", 524},
      {"SimpleSparseAccessor/SimpleSparseAccessor.gltf", 12},
  };
  for (const auto& [relative, drawn] : models) {
    SCOPED_TRACE(relative);
    GltfLoadStats stats;
    const Scene scene = load_gltf(asset(relative), {}, &stats);
    EXPECT_EQ(scene.drawn_triangle_count(), drawn);
    EXPECT_EQ(scene.source_path, asset(relative).string());
    EXPECT_TRUE(stats.warnings.empty()) << stats.warnings.front();
    EXPECT_EQ(stats.non_finite_positions, 0u);
    EXPECT_FALSE(scene.world_bounds.empty());
    for (const MeshInstance& instance : scene.instances) {
      EXPECT_TRUE(all_finite(instance.world));
      EXPECT_LE(instance.world_bounds.min.x, instance.world_bounds.max.x);
    }
    for (const Mesh& mesh : scene.meshes) {
      for (const MeshPrimitive& p : mesh.primitives) {
        EXPECT_EQ(p.normals.size(), p.positions.size());
        EXPECT_EQ(p.indices.size() % 3, 0u);
      }
    }
  }
}

TEST(GltfAssets, LightsPunctualLampHasFivePointLights) {
  REQUIRE_ASSETS();
  const Scene scene = load_gltf(asset("LightsPunctualLamp/LightsPunctualLamp.gltf"));
  ASSERT_EQ(scene.lights.size(), 5u);
  for (const Light& light : scene.lights) {
    EXPECT_EQ(light.type, Light::Type::Point);
    EXPECT_TRUE(std::isfinite(light.position.x) && std::isfinite(light.position.y) &&
                std::isfinite(light.position.z));
    EXPECT_NEAR(glm::length(light.direction), 1.0f, 1e-5f);
  }
  // Node 3 carries light 0: colour [1, 0.63187498, 0.23909976], intensity 15.
  EXPECT_EQ(scene.lights[0].name, "Point");
  EXPECT_FLOAT_EQ(scene.lights[0].intensity, 15.0f);
  EXPECT_FLOAT_EQ(scene.lights[0].color.y, 0.6318749785423279f);
  // Light 1 has no colour in the file: white (KHR_lights_punctual default).
  EXPECT_EQ(scene.lights[1].color, glm::vec3(1.0f));
}

TEST(GltfAssets, CameraCountsAndRigidFrames) {
  REQUIRE_ASSETS();
  const Scene duck = load_gltf(asset("Duck/Duck.gltf"));
  ASSERT_EQ(duck.cameras.size(), 1u);
  EXPECT_EQ(duck.cameras[0].type, Camera::Type::Perspective);
  expect_rigid(duck.cameras[0].world);
  const Scene car = load_gltf(asset("ToyCar/ToyCar.gltf"));
  ASSERT_EQ(car.cameras.size(), 8u);
  for (const Camera& camera : car.cameras) expect_rigid(camera.world);
}

TEST(GltfAssets, SimpleSparseAccessorSubstitutesThreePositions) {
  REQUIRE_ASSETS();
  const auto path = asset("SimpleSparseAccessor/SimpleSparseAccessor.gltf");
  // Layout from the .gltf: indices ushort[36] at 0, positions float[14][3] at 72, sparse
  // indices ushort[3] at 240, sparse values float[3][3] at 248.
  std::ifstream file(asset("SimpleSparseAccessor/SimpleSparseAccessor.bin"), std::ios::binary);
  const std::vector<char> bin((std::istreambuf_iterator<char>(file)), {});
  ASSERT_EQ(bin.size(), 284u);
  uint16_t indices[36], sparse_indices[3];
  float positions[14][3], sparse_values[3][3];
  std::memcpy(indices, bin.data(), sizeof indices);
  std::memcpy(positions, bin.data() + 72, sizeof positions);
  std::memcpy(sparse_indices, bin.data() + 240, sizeof sparse_indices);
  std::memcpy(sparse_values, bin.data() + 248, sizeof sparse_values);
  for (int s = 0; s < 3; ++s) {
    ASSERT_LT(sparse_indices[s], 14);
    // The substitution must change something, or the test could not tell it happened.
    EXPECT_NE(positions[sparse_indices[s]][1], sparse_values[s][1]);
    std::memcpy(positions[sparse_indices[s]], sparse_values[s], sizeof sparse_values[s]);
  }
  const Scene scene = load_gltf(path);
  ASSERT_EQ(scene.meshes.size(), 1u);
  const MeshPrimitive& primitive = scene.meshes[0].primitives.at(0);
  // No NORMAL in the file: flat normals, so the primitive is de-indexed in index order.
  ASSERT_EQ(primitive.indices.size(), 36u);
  for (size_t corner = 0; corner < 36; ++corner) {
    const float* expected = positions[indices[corner]];
    EXPECT_EQ(primitive.indices[corner], corner);
    EXPECT_EQ(primitive.positions[corner], glm::vec3(expected[0], expected[1], expected[2]))
        << "corner " << corner;
  }
}

TEST(GltfAssets, OrientationTestMatrixNodesKeepTheirMatrix) {
  REQUIRE_ASSETS();
  const auto path = asset("OrientationTest/OrientationTest.gltf");
  std::ifstream file(path);
  const nlohmann::json json = nlohmann::json::parse(file);
  const Scene scene = load_gltf(path);
  int matrix_nodes = 0;
  for (const auto& node : json["nodes"]) {
    if (!node.contains("matrix")) continue;
    ++matrix_nodes;
    const MeshInstance* instance = nullptr;
    for (const MeshInstance& i : scene.instances)
      if (i.node_name == node["name"].get<std::string>()) instance = &i;
    ASSERT_NE(instance, nullptr) << node["name"];
    // These nodes are scene roots, so the world matrix is the node's matrix.
    for (int k = 0; k < 16; ++k) {
      EXPECT_EQ(instance->world[k / 4][k % 4], node["matrix"][k].get<double>());
    }
  }
  EXPECT_EQ(matrix_nodes, 3);
  for (const MeshInstance& instance : scene.instances) EXPECT_TRUE(all_finite(instance.world));
}

TEST(GltfAssets, TexturesColourSpacesSamplersAndCache) {
  REQUIRE_ASSETS();
  const Scene box = load_gltf(asset("BoxTextured/BoxTextured.gltf"));
  ASSERT_EQ(box.materials.size(), 1u);
  const TextureSlot& base = box.materials[0].base_color_texture;
  ASSERT_NE(base.texture, nullptr);
  EXPECT_EQ(base.texture->encoding(), TexelEncoding::Srgb8);
  EXPECT_EQ(base.texture->width(), 256);
  // Sampler: magFilter LINEAR, minFilter NEAREST_MIPMAP_LINEAR, REPEAT.
  EXPECT_EQ(base.sampler.mag_filter, FilterMode::Linear);
  EXPECT_EQ(base.sampler.min_filter, FilterMode::Nearest);
  EXPECT_EQ(base.sampler.mipmap_mode, MipmapMode::Linear);
  EXPECT_EQ(base.sampler.wrap_u, WrapMode::Repeat);

  // The milk truck's two textures share one image: one Texture2D.
  const Scene truck = load_gltf(asset("CesiumMilkTruck/CesiumMilkTruck.gltf"));
  std::vector<const Texture2D*> textures;
  for (const Material& m : truck.materials)
    if (m.base_color_texture.texture) textures.push_back(m.base_color_texture.texture.get());
  ASSERT_EQ(textures.size(), 2u);
  EXPECT_EQ(textures[0], textures[1]);

  const Scene helmet = load_gltf(asset("DamagedHelmet/DamagedHelmet.glb"));
  const Material& h = helmet.materials.at(0);
  ASSERT_TRUE(h.normal_texture.texture && h.emissive_texture.texture &&
              h.metallic_roughness_texture.texture);
  EXPECT_EQ(h.normal_texture.texture->encoding(), TexelEncoding::Unorm8);
  EXPECT_EQ(h.metallic_roughness_texture.texture->encoding(), TexelEncoding::Unorm8);
  EXPECT_EQ(h.emissive_texture.texture->encoding(), TexelEncoding::Srgb8);
  EXPECT_EQ(h.normal_texture.texture->width(), 2048);
}

TEST(GltfAssets, DefaultCameraFramesTheBoundingSphere) {
  REQUIRE_ASSETS();
  const Scene duck = load_gltf(asset("Duck/Duck.gltf"));
  const Camera camera = default_camera(duck);
  const glm::vec3 center = duck.world_bounds.center();
  const float radius = 0.5f * glm::length(duck.world_bounds.max - duck.world_bounds.min);
  const glm::vec3 eye(camera.world[3]);
  const float distance = glm::length(eye - center);
  // The sphere touches the 45 degree vertical FOV: distance * sin(22.5 deg) = radius.
  EXPECT_NEAR(distance * std::sin(camera.yfov_rad / 2), radius, radius * 1e-5f);
  EXPECT_NEAR(camera.yfov_rad, 0.785398163f, 1e-7f);
  // Looks at the centre from +Z, 15 degrees up.
  const glm::vec3 forward = -glm::vec3(camera.world[2]);
  EXPECT_NEAR(glm::dot(forward, glm::normalize(center - eye)), 1.0f, 1e-6f);
  EXPECT_NEAR(std::asin((eye - center).y / distance), 0.261799388f, 1e-5f);
  EXPECT_GT(eye.z, center.z);
  expect_rigid(camera.world);
  EXPECT_NEAR(camera.znear, distance - 1.1f * radius, distance * 1e-5f);
  EXPECT_NEAR(camera.zfar, distance + 1.1f * radius, distance * 1e-5f);
}

}  // namespace
}  // namespace ontile
