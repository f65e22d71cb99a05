// glTF loader failures: each malformed input gives one ontile::Error line naming the file and
// the specific problem; NaN/Inf positions load when the caller opts in, and are counted.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gltf_test_files.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile {
namespace {

using nlohmann::json;
using test::expect_load_error;
using test::GltfBuilder;

// A triangle mesh node with the given POSITION values and optional index values.
GltfBuilder triangle_file(const std::vector<float>& positions,
                          const std::vector<uint16_t>& indices = {}) {
  GltfBuilder b;
  json primitive = {{"attributes", {{"POSITION", b.add_positions(positions)}}}};
  if (!indices.empty()) {
    primitive["indices"] = b.add_data(indices, test::kUnsignedShort, "SCALAR", indices.size());
  }
  b.add_mesh(json::array({primitive}));
  b.add_node({{"mesh", 0}});
  b.json["scenes"] = json::array({{{"nodes", {0}}}});
  return b;
}

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

TEST(GltfErrors, MissingFile) {
  expect_load_error(test::gltf_test_dir() / "absent.gltf", "file not found");
}

TEST(GltfErrors, MissingBuffer) {
  GltfBuilder b = triangle_file(kTriangle);
  expect_load_error(b.write(test::gltf_test_dir(), "model", "missing.bin", false),
                    "File not found : missing.bin");
}

TEST(GltfErrors, MissingImage) {
  GltfBuilder b = triangle_file(kTriangle);
  b.json["images"] = json::array({{{"uri", "missing.png"}}});
  b.json["textures"] = json::array({{{"source", 0}}});
  b.json["materials"] =
      json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
  expect_load_error(b.write(test::gltf_test_dir(), "model"),
                    "image 0 ('missing.png') could not be loaded: File not found : missing.png");
}

TEST(GltfErrors, IndexOutOfRange) {
  GltfBuilder b = triangle_file(kTriangle, {0, 1, 7});
  // Accessor 0 holds the positions, accessor 1 the indices.
  expect_load_error(b.write(test::gltf_test_dir(), "model"),
                    "accessor 1 index 7 out of range (vertex count 3)");
}

TEST(GltfErrors, NonFinitePositionRejectedByDefaultCountedOnRequest) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  GltfBuilder b = triangle_file({0, 0, 0, 1, 0, 0, 0, 1, 0, 2, nan, 0, 3, 3, -inf, 0, 2, 0},
                                {0, 1, 2, 3, 4, 5});
  const auto path = b.write(test::gltf_test_dir(), "model");
  expect_load_error(
      path, "accessor 0 (POSITION of mesh 0 primitive 0) element 3 is a non-finite position");
  GltfLoadOptions keep;
  keep.reject_non_finite_positions = false;
  GltfLoadStats stats;
  const Scene scene = load_gltf(path, keep, &stats);
  EXPECT_EQ(stats.non_finite_positions, 2u);
  EXPECT_EQ(scene.drawn_triangle_count(), 2u);
  const MeshPrimitive& p = scene.meshes.at(0).primitives.at(0);
  EXPECT_TRUE(std::isnan(p.positions[3].y));
  // Bounds cover the finite vertices only.
  EXPECT_EQ(p.bounds.min, glm::vec3(0, 0, 0));
  EXPECT_EQ(p.bounds.max, glm::vec3(1, 2, 0));
}

TEST(GltfErrors, UnsupportedRequiredExtension) {
  GltfBuilder b = triangle_file(kTriangle);
  const auto dir = test::gltf_test_dir();
  b.json["extensionsUsed"] = {"KHR_texture_transform", "KHR_mesh_quantization",
                              "EXT_meshopt_compression"};
  b.json["extensionsRequired"] = {"KHR_texture_transform", "KHR_mesh_quantization"};
  EXPECT_EQ(load_gltf(b.write(dir, "supported")).drawn_triangle_count(), 1u);
  b.json["extensionsRequired"].push_back("EXT_meshopt_compression");
  expect_load_error(b.write(dir, "unsupported"),
                    "unsupported required extension EXT_meshopt_compression");
}

TEST(GltfErrors, InvalidJson) {
  const auto path = test::gltf_test_dir() / "broken.gltf";
  test::write_bytes(path, R"({"asset": {"version": "2.0"}, "nodes": [ )");
  expect_load_error(path, "invalid JSON: ");
}

TEST(GltfErrors, SceneIndexOutOfRange) {
  GltfBuilder b = triangle_file(kTriangle);
  GltfLoadOptions options;
  options.scene_index = 3;
  expect_load_error(b.write(test::gltf_test_dir(), "model"),
                    "scene index 3 out of range (the file has 1 scenes)", options);
}

TEST(GltfErrors, AccessorReadsPastItsBufferView) {
  GltfBuilder b = triangle_file(kTriangle);
  b.json["accessors"][0]["count"] = 4;
  expect_load_error(b.write(test::gltf_test_dir(), "model"),
                    "accessor 0 (byteOffset 0, count 4, stride 12) reads past the end of "
                    "bufferView 0 (36 bytes)");
}

TEST(GltfErrors, AccessorOffsetAgainstBufferViewEnd) {
  GltfBuilder b = triangle_file({9, 9, 9, 0, 0, 0, 1, 0, 0, 0, 1, 0});
  const auto dir = test::gltf_test_dir();
  // Three vertices from byte 12 end exactly at the view's end (byte 48): allowed.
  b.json["accessors"][0]["count"] = 3;
  b.json["accessors"][0]["byteOffset"] = 12;
  const Scene scene = load_gltf(b.write(dir, "fits"));
  EXPECT_EQ(scene.meshes.at(0).primitives.at(0).positions,
            (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  // From byte 16 they would end at byte 52.
  b.json["accessors"][0]["byteOffset"] = 16;
  expect_load_error(b.write(dir, "overruns"), "reads past the end of bufferView 0 (48 bytes)");
}

TEST(GltfErrors, AttributeCountDiffersFromPosition) {
  GltfBuilder b = triangle_file(kTriangle);
  b.json["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] =
      b.add_data(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC3", 2);
  expect_load_error(b.write(test::gltf_test_dir(), "model"),
                    "accessor 1 (NORMAL of mesh 0 primitive 0) has 2 elements, POSITION has 3");
}

TEST(GltfErrors, SparseIndexOutOfRange) {
  GltfBuilder b = triangle_file(kTriangle);
  const int indices = b.add_view(test::as_bytes(std::vector<uint16_t>{9, 0}));
  const int values = b.add_view(test::as_bytes(std::vector<float>{1, 2, 3}));
  b.json["accessors"][0]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", indices}, {"componentType", test::kUnsignedShort}}},
      {"values", {{"bufferView", values}}}};
  expect_load_error(b.write(test::gltf_test_dir(), "model"),
                    "accessor 0 sparse index 9 out of range (count 3)");
}

TEST(GltfErrors, NormalizedFloatAccessor) {
  GltfBuilder b = triangle_file(kTriangle);
  b.json["accessors"][0]["normalized"] = true;
  expect_load_error(b.write(test::gltf_test_dir(), "model"), "accessor 0 is normalized");
}

TEST(GltfErrors, GlbWithoutMagic) {
  const auto path = test::gltf_test_dir() / "fake.glb";
  test::write_bytes(path, R"({"asset": {"version": "2.0"}})");
  expect_load_error(path, "not a GLB file");
}

TEST(GltfErrors, NodeCycle) {
  GltfBuilder b = triangle_file(kTriangle);
  b.json["nodes"][0]["children"] = json::array({1});
  b.add_node({{"children", json::array({0})}});
  expect_load_error(b.write(test::gltf_test_dir(), "model"), "node 0 is its own ancestor");
}

}  // namespace
}  // namespace ontile
