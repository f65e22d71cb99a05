// glTF loader on small files written by the test: accessor component types and normalization,
// strides and offsets, sparse accessors, strip/fan conversion, node transforms, scenes,
// cameras and lights, GLB.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "gltf_test_files.h"
#include "scene/gltf_loader.h"

namespace ontile {
namespace {

using nlohmann::json;
using test::GltfBuilder;

// One mesh node whose only primitive uses `attributes` (and optional indices/mode).
std::filesystem::path write_single_primitive(GltfBuilder& b, const std::filesystem::path& dir,
                                             json primitive) {
  b.add_mesh(json::array({std::move(primitive)}));
  b.add_node({{"mesh", 0}});
  b.json["scenes"] = json::array({{{"nodes", {0}}}});
  return b.write(dir, "model");
}

template <typename T>
std::vector<float> decoded_positions(const std::vector<T>& values, int component_type,
                                     bool normalized) {
  GltfBuilder b;
  const int accessor = b.add_data(values, component_type, "VEC3", values.size() / 3, normalized);
  const auto path =
      write_single_primitive(b, test::gltf_test_dir(), {{"attributes", {{"POSITION", accessor}}}});
  const Scene scene = load_gltf(path);
  const MeshPrimitive& p = scene.meshes.at(0).primitives.at(0);
  std::vector<float> out;
  // Unindexed and without normals: de-indexed in vertex order, so corner k is vertex k.
  for (const glm::vec3& v : p.positions) out.insert(out.end(), {v.x, v.y, v.z});
  return out;
}

TEST(GltfGeometry, EveryComponentTypeNormalizedAndNot) {
  // Spec 3.11: signed max(c / (2^(n-1) - 1), -1), unsigned c / (2^n - 1).
  const std::vector<int8_t> bytes = {-128, -127, 0, 1, 127, -1, 64, 100, 5};
  EXPECT_EQ(decoded_positions(bytes, test::kByte, true),
            (std::vector<float>{-1.0f, -1.0f, 0.0f, 1.0f / 127.0f, 1.0f, -1.0f / 127.0f,
                                64.0f / 127.0f, 100.0f / 127.0f, 5.0f / 127.0f}));
  EXPECT_EQ(decoded_positions(bytes, test::kByte, false),
            (std::vector<float>{-128, -127, 0, 1, 127, -1, 64, 100, 5}));
  const std::vector<uint8_t> ubytes = {0, 255, 51, 102, 204, 1, 128, 254, 3};
  EXPECT_EQ(decoded_positions(ubytes, test::kUnsignedByte, true),
            (std::vector<float>{0.0f, 1.0f, 0.2f, 0.4f, 0.8f, 1.0f / 255.0f, 128.0f / 255.0f,
                                254.0f / 255.0f, 3.0f / 255.0f}));
  EXPECT_EQ(decoded_positions(ubytes, test::kUnsignedByte, false),
            (std::vector<float>{0, 255, 51, 102, 204, 1, 128, 254, 3}));
  const std::vector<int16_t> shorts = {-32768, -32767, 32767, 0, 1, -1, 16384, 300, -300};
  EXPECT_EQ(decoded_positions(shorts, test::kShort, true),
            (std::vector<float>{-1.0f, -1.0f, 1.0f, 0.0f, 1.0f / 32767.0f, -1.0f / 32767.0f,
                                16384.0f / 32767.0f, 300.0f / 32767.0f, -300.0f / 32767.0f}));
  EXPECT_EQ(decoded_positions(shorts, test::kShort, false),
            (std::vector<float>{-32768, -32767, 32767, 0, 1, -1, 16384, 300, -300}));
  const std::vector<uint16_t> ushorts = {0, 65535, 13107, 26214, 52428, 1, 2, 3, 4};
  EXPECT_EQ(decoded_positions(ushorts, test::kUnsignedShort, true),
            (std::vector<float>{0.0f, 1.0f, 0.2f, 0.4f, 0.8f, 1.0f / 65535.0f, 2.0f / 65535.0f,
                                3.0f / 65535.0f, 4.0f / 65535.0f}));
  EXPECT_EQ(decoded_positions(ushorts, test::kUnsignedShort, false),
            (std::vector<float>{0, 65535, 13107, 26214, 52428, 1, 2, 3, 4}));
  const std::vector<uint32_t> uints = {0, 1, 4000000000u, 16777217u, 7, 8, 9, 10, 11};
  EXPECT_EQ(decoded_positions(uints, test::kUnsignedInt, false),
            (std::vector<float>{0.0f, 1.0f, 4.0e9f, 16777216.0f, 7, 8, 9, 10, 11}));
  const std::vector<float> floats = {0.5f, -2.25f, 1e-30f, 3, 4, 5, 6, 7, 8};
  EXPECT_EQ(decoded_positions(floats, test::kFloat, false), floats);
}

TEST(GltfGeometry, InterleavedStrideAndOffsets) {
  // One bufferView that starts after 12 bytes of other data. Each vertex takes 36 bytes (the
  // byteStride): 8 junk bytes, POSITION float3 at 8, NORMAL float3 at 20, TEXCOORD_0
  // normalized ushort2 at 32.
  GltfBuilder b;
  b.add_view(std::vector<uint8_t>(12, 0xAB));
  constexpr size_t kStride = 36;
  std::vector<uint8_t> interleaved;
  const float positions[3][3] = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9.5f}};
  const float normals[3][3] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
  const uint16_t uvs[3][2] = {{0, 65535}, {13107, 26214}, {65535, 0}};
  for (int v = 0; v < 3; ++v) {
    std::vector<uint8_t> vertex(kStride, 0xCD);
    std::memcpy(vertex.data() + 8, positions[v], 12);
    std::memcpy(vertex.data() + 20, normals[v], 12);
    std::memcpy(vertex.data() + 32, uvs[v], 4);
    interleaved.insert(interleaved.end(), vertex.begin(), vertex.end());
  }
  const int view = b.add_view(interleaved, kStride);
  const int pos = b.add_accessor({{"bufferView", view},
                                  {"byteOffset", 8},
                                  {"componentType", test::kFloat},
                                  {"type", "VEC3"},
                                  {"count", 3}});
  const int nrm = b.add_accessor({{"bufferView", view},
                                  {"byteOffset", 20},
                                  {"componentType", test::kFloat},
                                  {"type", "VEC3"},
                                  {"count", 3}});
  const int uv = b.add_accessor({{"bufferView", view},
                                 {"byteOffset", 32},
                                 {"componentType", test::kUnsignedShort},
                                 {"normalized", true},
                                 {"type", "VEC2"},
                                 {"count", 3}});
  const auto path = write_single_primitive(
      b, test::gltf_test_dir(),
      {{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}}});
  const Scene scene = load_gltf(path);
  const MeshPrimitive& p = scene.meshes.at(0).primitives.at(0);
  ASSERT_EQ(p.positions.size(), 3u);
  for (int v = 0; v < 3; ++v) {
    EXPECT_EQ(p.positions[v], glm::vec3(positions[v][0], positions[v][1], positions[v][2]));
    EXPECT_EQ(p.normals[v], glm::vec3(normals[v][0], normals[v][1], normals[v][2]));
  }
  EXPECT_EQ(p.uv0[0], glm::vec2(0.0f, 1.0f));
  EXPECT_EQ(p.uv0[1], glm::vec2(0.2f, 0.4f));
  EXPECT_EQ(p.indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(p.bounds.min, glm::vec3(1, 2, 3));
  EXPECT_EQ(p.bounds.max, glm::vec3(7, 8, 9.5f));
}

TEST(GltfGeometry, TangentsAndVertexColours) {
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const int nrm =
      b.add_data(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}, test::kFloat, "VEC3", 3);
  const int tan =
      b.add_data(std::vector<float>{1, 0, 0, 1, 1, 0, 0, -1, 0, 1, 0, 1}, test::kFloat, "VEC4", 3);
  const int rgb = b.add_data(std::vector<uint8_t>{255, 0, 51, 0, 102, 255, 204, 204, 0},
                             test::kUnsignedByte, "VEC3", 3, true);
  const int rgba = b.add_data(
      std::vector<uint16_t>{65535, 0, 13107, 26214, 0, 0, 0, 65535, 52428, 52428, 52428, 0},
      test::kUnsignedShort, "VEC4", 3, true);
  const json with_normals = {{"POSITION", pos}, {"NORMAL", nrm}, {"TANGENT", tan}};
  json first = with_normals, second = with_normals;
  first["COLOR_0"] = rgb;
  second["COLOR_0"] = rgba;
  b.add_mesh(json::array({{{"attributes", first}}, {{"attributes", second}}}));
  b.add_node({{"mesh", 0}});
  const Scene scene = load_gltf(b.write(test::gltf_test_dir(), "colours"));
  const auto& prims = scene.meshes.at(0).primitives;
  EXPECT_EQ(prims.at(0).tangents,
            (std::vector<glm::vec4>{{1, 0, 0, 1}, {1, 0, 0, -1}, {0, 1, 0, 1}}));
  // VEC3 colours get alpha 1.
  EXPECT_EQ(prims.at(0).colors,
            (std::vector<glm::vec4>{{1, 0, 0.2f, 1}, {0, 0.4f, 1, 1}, {0.8f, 0.8f, 0, 1}}));
  EXPECT_EQ(prims.at(1).colors,
            (std::vector<glm::vec4>{{1, 0, 0.2f, 0.4f}, {0, 0, 0, 1}, {0.8f, 0.8f, 0.8f, 0}}));
}

TEST(GltfGeometry, DefaultCameraOfAnEmptySceneFramesTheUnitSphere) {
  const Camera camera = default_camera(Scene{});
  // Radius 1 at the origin: distance 1 / sin(22.5 deg), raised 15 degrees.
  const double distance = 1.0 / std::sin(22.5 * std::numbers::pi / 180.0);
  const double elevation = 15.0 * std::numbers::pi / 180.0;
  EXPECT_EQ(glm::dvec3(camera.world[3]),
            glm::dvec3(0.0, distance * std::sin(elevation), distance * std::cos(elevation)));
  EXPECT_EQ(camera.znear, static_cast<float>(distance - 1.1));
  EXPECT_EQ(camera.zfar, static_cast<float>(distance + 1.1));
  EXPECT_EQ(camera.type, Camera::Type::Perspective);
}

TEST(GltfGeometry, SparseWithAndWithoutBufferView) {
  GltfBuilder b;
  const int sparse_indices = b.add_view(test::as_bytes(std::vector<uint8_t>{1, 3}));
  const int sparse_values = b.add_view(test::as_bytes(std::vector<float>{10, 11, 12, 20, 21, 22}));
  const json sparse = {
      {"count", 2},
      {"indices", {{"bufferView", sparse_indices}, {"componentType", test::kUnsignedByte}}},
      {"values", {{"bufferView", sparse_values}}}};
  // No bufferView: starts as zeros.
  const int zeros = b.add_accessor(
      {{"componentType", test::kFloat}, {"type", "VEC3"}, {"count", 4}, {"sparse", sparse}});
  const int base = b.add_data(std::vector<float>(12, 1.0f), test::kFloat, "VEC3", 4);
  b.json["accessors"][base]["sparse"] = sparse;
  const int normals =
      b.add_data(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, test::kFloat, "VEC3", 4);
  const int indices =
      b.add_data(std::vector<uint8_t>{0, 1, 2, 0, 2, 3}, test::kUnsignedByte, "SCALAR", 6);
  b.add_mesh(json::array(
      {{{"attributes", {{"POSITION", zeros}, {"NORMAL", normals}}}, {"indices", indices}},
       {{"attributes", {{"POSITION", base}, {"NORMAL", normals}}}, {"indices", indices}}}));
  b.add_node({{"mesh", 0}});
  const Scene scene = load_gltf(b.write(test::gltf_test_dir(), "sparse"));
  const auto& prims = scene.meshes.at(0).primitives;
  EXPECT_EQ(prims.at(0).positions,
            (std::vector<glm::vec3>{{0, 0, 0}, {10, 11, 12}, {0, 0, 0}, {20, 21, 22}}));
  EXPECT_EQ(prims.at(1).positions,
            (std::vector<glm::vec3>{{1, 1, 1}, {10, 11, 12}, {1, 1, 1}, {20, 21, 22}}));
  EXPECT_EQ(prims.at(1).indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(GltfGeometry, StripFanAndSkippedModes) {
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0});
  const int nrm = b.add_data(std::vector<float>(15, 0.0f), test::kFloat, "VEC3", 5);
  const int reversed =
      b.add_data(std::vector<uint8_t>{4, 3, 2, 1, 0}, test::kUnsignedByte, "SCALAR", 5);
  const json attributes = {{"POSITION", pos}, {"NORMAL", nrm}};
  b.add_mesh(json::array({{{"attributes", attributes}, {"mode", 5}},
                          {{"attributes", attributes}, {"mode", 6}, {"indices", reversed}},
                          {{"attributes", attributes}, {"mode", 0}},
                          {{"attributes", attributes}, {"mode", 1}},
                          {{"attributes", attributes}, {"mode", 3}},
                          {{"attributes", attributes}, {"mode", 4}}}));
  b.add_node({{"mesh", 0}});
  GltfLoadStats stats;
  const Scene scene = load_gltf(b.write(test::gltf_test_dir(), "modes"), {}, &stats);
  const auto& prims = scene.meshes.at(0).primitives;
  ASSERT_EQ(prims.size(), 3u);
  // Strip (spec 3.7.2.1): {v_i, v_(i+1+i%2), v_(i+2-i%2)}.
  EXPECT_EQ(prims[0].indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4}));
  // Fan over sequence 4,3,2,1,0: {s_(i+1), s_(i+2), s_0}.
  EXPECT_EQ(prims[1].indices, (std::vector<uint32_t>{3, 2, 4, 2, 1, 4, 1, 0, 4}));
  // TRIANGLES over 5 vertices: one triangle, two vertices left over (warned).
  EXPECT_EQ(prims[2].indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(stats.skipped_point_primitives, 1u);
  EXPECT_EQ(stats.skipped_line_primitives, 2u);
  ASSERT_EQ(stats.warnings.size(), 1u);
  EXPECT_NE(stats.warnings[0].find("not a multiple of 3"), std::string::npos);
  EXPECT_EQ(scene.drawn_triangle_count(), 3u + 3u + 1u);
}

TEST(GltfGeometry, FlatNormalsForPrimitivesWithoutNormal) {
  GltfBuilder b;
  // Two triangles sharing an edge, folded 90 degrees. Counter-clockwise corners give the
  // right-handed normals: +Z for (0,0,0) (1,0,0) (0,1,0), -Y for (1,0,0) (0,0,0) (0,0,-1).
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, -1});
  const int idx =
      b.add_data(std::vector<uint16_t>{0, 1, 2, 1, 0, 3}, test::kUnsignedShort, "SCALAR", 6);
  GltfLoadStats stats;
  const Scene scene =
      load_gltf(write_single_primitive(b, test::gltf_test_dir(),
                                       {{"attributes", {{"POSITION", pos}}}, {"indices", idx}}),
                {}, &stats);
  const MeshPrimitive& p = scene.meshes.at(0).primitives.at(0);
  EXPECT_EQ(stats.primitives_with_generated_normals, 1u);
  EXPECT_EQ(p.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(p.positions[4], glm::vec3(0, 0, 0));
  EXPECT_EQ(p.positions[5], glm::vec3(0, 0, -1));
  for (int c = 0; c < 3; ++c) EXPECT_EQ(p.normals[c], glm::vec3(0, 0, 1));
  for (int c = 3; c < 6; ++c) EXPECT_EQ(p.normals[c], glm::vec3(0, -1, 0));
}

TEST(GltfGeometry, NodeTrsAndMatrixComposeParentTimesChild) {
  GltfBuilder b;
  const int pos = b.add_positions({1, 0, 1, 0, 0, 0, 0, 1, 0});
  b.add_mesh(json::array({{{"attributes", {{"POSITION", pos}}}}}));
  // Parent: T(1,2,3) * R(180 deg about Z, quaternion xyzw (0,0,1,0)) * S(2).
  b.add_node({{"name", "parent"},
              {"translation", {1, 2, 3}},
              {"rotation", {0, 0, 1, 0}},
              {"scale", {2, 2, 2}},
              {"children", {1}},
              {"mesh", 0}});
  // Child: column-major matrix = T(0,1,0) * S(1,1,3).
  b.add_node({{"name", "child"},
              {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 3, 0, 0, 1, 0, 1}},
              {"mesh", 0}});
  b.json["scenes"] = json::array({{{"nodes", {0}}}});
  const Scene scene = load_gltf(b.write(test::gltf_test_dir(), "nodes"));
  ASSERT_EQ(scene.instances.size(), 2u);
  const MeshInstance& child = scene.instances[1];
  EXPECT_EQ(child.node_name, "child");
  // (1,0,1) -> child (1,1,3) -> scale (2,2,6) -> rotate (-2,-2,6) -> translate (-1,0,9).
  EXPECT_EQ(glm::dvec3(child.world * glm::dvec4(1, 0, 1, 1)), glm::dvec3(-1, 0, 9));
  EXPECT_EQ(glm::dvec3(scene.instances[0].world * glm::dvec4(1, 0, 1, 1)), glm::dvec3(-1, 2, 5));
  // Object bounds [0,1]x[0,1]x[0,1] through the child's world: x in [-1,1], y in [-2,0],
  // z in [3,9].
  EXPECT_EQ(child.world_bounds.min, glm::vec3(-1, -2, 3));
  EXPECT_EQ(child.world_bounds.max, glm::vec3(1, 0, 9));
  EXPECT_EQ(scene.world_bounds.min, glm::vec3(-1, -2, 3));
  EXPECT_EQ(scene.world_bounds.max, glm::vec3(1, 2, 9));
}

TEST(GltfGeometry, SceneSelection) {
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  b.add_mesh(json::array({{{"attributes", {{"POSITION", pos}}}}}));
  for (const char* name : {"a", "b", "c"}) b.add_node({{"name", name}, {"mesh", 0}});
  b.json["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {1, 2}}}});
  b.json["scene"] = 1;
  const auto dir = test::gltf_test_dir();
  const auto path = b.write(dir, "scenes");
  EXPECT_EQ(load_gltf(path).instances.size(), 2u);
  GltfLoadOptions first;
  first.scene_index = 0;
  const Scene scene0 = load_gltf(path, first);
  ASSERT_EQ(scene0.instances.size(), 1u);
  EXPECT_EQ(scene0.instances[0].node_name, "a");
  // No scenes at all: every root node.
  b.json.erase("scenes");
  b.json.erase("scene");
  b.json["nodes"][0]["children"] = json::array({2});
  const Scene roots = load_gltf(b.write(dir, "no_scenes"));
  ASSERT_EQ(roots.instances.size(), 3u);
  EXPECT_EQ(roots.instances[0].node_name, "a");
  EXPECT_EQ(roots.instances[1].node_name, "c");
  EXPECT_EQ(roots.instances[2].node_name, "b");
}

TEST(GltfGeometry, CamerasAndLightsFromNodes) {
  GltfBuilder b;
  b.json["cameras"] =
      json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.25}}}},
                   {{"type", "orthographic"},
                    {"orthographic", {{"xmag", 2}, {"ymag", 1.5}, {"znear", 0}, {"zfar", 10}}}}});
  b.json["extensionsUsed"] = {"KHR_lights_punctual"};
  b.json["extensions"]["KHR_lights_punctual"]["lights"] =
      json::array({{{"type", "spot"},
                    {"color", {1, 0.5, 0.25}},
                    {"intensity", 3},
                    {"range", 7},
                    {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.2}}}},
                   {{"type", "directional"}}});
  // Node 0: translated and scaled by 3, rotated 180 deg about Y; carries camera 0 and light 0.
  b.add_node({{"translation", {1, 2, 3}},
              {"rotation", {0, 1, 0, 0}},
              {"scale", {3, 3, 3}},
              {"camera", 0},
              {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}},
              {"children", {1}}});
  b.add_node({{"camera", 1}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  b.json["scenes"] = json::array({{{"nodes", {0}}}});
  b.add_view({0, 0, 0, 0});
  const Scene scene = load_gltf(b.write(test::gltf_test_dir(), "cameras"));
  ASSERT_EQ(scene.cameras.size(), 2u);
  const Camera& persp = scene.cameras[0];
  EXPECT_EQ(persp.type, Camera::Type::Perspective);
  EXPECT_EQ(persp.yfov_rad, 0.5f);
  EXPECT_EQ(persp.znear, 0.25f);
  EXPECT_EQ(persp.zfar, 0.0f);          // absent: infinite
  EXPECT_EQ(persp.aspect_ratio, 0.0f);  // absent: image aspect
  // Scale dropped: rotation about Y by 180 degrees and the translation remain.
  EXPECT_EQ(persp.world, glm::dmat4(glm::dvec4(-1, 0, 0, 0), glm::dvec4(0, 1, 0, 0),
                                    glm::dvec4(0, 0, -1, 0), glm::dvec4(1, 2, 3, 1)));
  const Camera& ortho = scene.cameras[1];
  EXPECT_EQ(ortho.type, Camera::Type::Orthographic);
  EXPECT_EQ(ortho.xmag, 2.0f);
  EXPECT_EQ(ortho.ymag, 1.5f);
  EXPECT_EQ(ortho.zfar, 10.0f);
  EXPECT_EQ(ortho.world, persp.world);  // child with identity transform, parent scale dropped
  ASSERT_EQ(scene.lights.size(), 2u);
  const Light& spot = scene.lights[0];
  EXPECT_EQ(spot.type, Light::Type::Spot);
  EXPECT_EQ(spot.color, glm::vec3(1, 0.5f, 0.25f));
  EXPECT_EQ(spot.intensity, 3.0f);
  EXPECT_EQ(spot.range, 7.0f);
  EXPECT_EQ(spot.inner_cone_rad, 0.1f);
  EXPECT_EQ(spot.outer_cone_rad, 0.2f);
  EXPECT_EQ(spot.position, glm::vec3(1, 2, 3));
  EXPECT_EQ(spot.direction, glm::vec3(0, 0, 1));  // local -Z turned 180 deg about Y
  EXPECT_EQ(scene.lights[1].type, Light::Type::Directional);
  EXPECT_EQ(scene.lights[1].direction, glm::vec3(0, 0, 1));
}

TEST(GltfGeometry, GlbLoadsLikeGltf) {
  GltfBuilder b;
  const int pos = b.add_positions({0, 0, 0, 2, 0, 0, 0, 2, 0});
  b.add_mesh(json::array({{{"attributes", {{"POSITION", pos}}}}}));
  b.add_node({{"mesh", 0}, {"translation", {0, 0, 5}}});
  b.json["scenes"] = json::array({{{"nodes", {0}}}});
  const Scene scene = load_gltf(b.write_glb(test::gltf_test_dir(), "triangle"));
  EXPECT_EQ(scene.drawn_triangle_count(), 1u);
  EXPECT_EQ(scene.world_bounds.min, glm::vec3(0, 0, 5));
  EXPECT_EQ(scene.world_bounds.max, glm::vec3(2, 2, 5));
}

}  // namespace
}  // namespace ontile
