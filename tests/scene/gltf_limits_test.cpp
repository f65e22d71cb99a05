// Hostile glTF files (issue 12's robustness audit): each fails fast with one error line naming
// the file and the problem, within bounded memory, instead of crashing, hanging or reading
// files outside the scene's folder. The files are built here; docs/robustness.md lists the
// limits.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <string>

#include "gltf_test_files.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile {
namespace {

using nlohmann::json;
using test::expect_load_error;
using test::GltfBuilder;

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

// One triangle mesh (mesh 0) and no nodes yet.
GltfBuilder triangle_mesh() {
  GltfBuilder b;
  b.add_mesh(json::array({{{"attributes", {{"POSITION", b.add_positions(kTriangle)}}}}}));
  return b;
}

// A chain: node i's only child is node i + 1; the last node has the mesh.
GltfBuilder node_chain(int length) {
  GltfBuilder b = triangle_mesh();
  for (int i = 0; i < length; ++i) {
    json node = {{"translation", {0.0, 0.0, -0.001}}};
    if (i + 1 < length) node["children"] = {i + 1};
    else node["mesh"] = 0;
    b.add_node(node);
  }
  b.json["scenes"] = json::array({{{"nodes", {0}}}});
  return b;
}

// Peak resident memory of this process so far, in MiB (Linux reports ru_maxrss in KiB).
double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

TEST(GltfLimits, NodeChain10000DeepIsRefusedAndWalkedWithoutRecursion) {
  const auto dir = test::gltf_test_dir();
  const auto path = node_chain(10000).write(dir, "chain");
  // The old recursive walk overflowed the stack (SIGSEGV) here.
  expect_load_error(path, "node 1024 is nested 1025 levels deep, more than 1024 "
                          "(GltfLimits::max_node_depth)");
  GltfLoadOptions deeper;
  deeper.limits.max_node_depth = 10000;
  const Scene scene = load_gltf(path, deeper);
  ASSERT_EQ(scene.instances.size(), 1u);
  EXPECT_NEAR(scene.instances[0].world[3].z, -10.0, 1e-9);
  EXPECT_EQ(load_gltf(node_chain(1024).write(dir, "chain1024")).instances.size(), 1u);
}

// `{"asset": ..., "extras": [[[...]]]}` nested `depth` deep, as raw text (a JSON library would
// recurse to write it).
std::string deeply_nested_json(const GltfBuilder& b, int depth) {
  const std::string text = b.json.dump();
  return "{\"extras\":" + std::string(static_cast<size_t>(depth), '[') +
         std::string(static_cast<size_t>(depth), ']') + "," + text.substr(1);
}

TEST(GltfLimits, JsonNested15000DeepIsRefusedBeforeParsing) {
  const auto dir = test::gltf_test_dir();
  GltfBuilder b = triangle_mesh();
  b.add_node({{"mesh", 0}});
  b.json["buffers"] = json::array({{{"byteLength", b.bin.size()},
                                    {"uri", "data:application/octet-stream;base64," + test::base64(b.bin)}}});
  test::write_bytes(dir / "nested.gltf", deeply_nested_json(b, 15000));
  expect_load_error(dir / "nested.gltf",
                    "JSON nesting deeper than 512 levels at byte 521 (GltfLimits::max_json_nesting_depth)");
  // The same in a GLB's JSON chunk.
  std::string text = deeply_nested_json(b, 15000);
  while (text.size() % 4 != 0) text += ' ';
  std::string glb = "glTF";
  auto put32 = [&glb](uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  put32(2);
  put32(static_cast<uint32_t>(12 + 8 + text.size()));
  put32(static_cast<uint32_t>(text.size()));
  put32(0x4E4F534Au);  // "JSON"
  glb += text;
  test::write_bytes(dir / "nested.glb", glb);
  expect_load_error(dir / "nested.glb", "JSON nesting deeper than 512 levels");
  // 100 levels of extras are fine.
  test::write_bytes(dir / "shallow.gltf", deeply_nested_json(b, 100));
  EXPECT_NO_THROW(load_gltf(dir / "shallow.gltf"));
}

TEST(GltfLimits, NodeTreesMustBeTrees) {
  const auto dir = test::gltf_test_dir();
  // 40 nodes each listing the next one twice: 2^40 paths to the last node.
  GltfBuilder doubled = triangle_mesh();
  for (int i = 0; i < 40; ++i) {
    json node = {{"mesh", 0}};
    if (i + 1 < 40) node["children"] = {i + 1, i + 1};
    doubled.add_node(node);
  }
  doubled.json["scenes"] = json::array({{{"nodes", {0}}}});
  expect_load_error(doubled.write(dir, "doubled"),
                    "node 1 is listed twice among the children of node 0 (glTF 2.0 3.5.2");

  GltfBuilder two_parents = triangle_mesh();
  two_parents.add_node({{"children", {2}}});
  two_parents.add_node({{"children", {2}}});
  two_parents.add_node({{"mesh", 0}});
  two_parents.json["scenes"] = json::array({{{"nodes", {0, 1}}}});
  expect_load_error(two_parents.write(dir, "two_parents"), "node 2 is a child of both node 0 and node 1");

  GltfBuilder cycle = triangle_mesh();
  cycle.add_node({{"children", {1}}});
  cycle.add_node({{"children", {0}}, {"mesh", 0}});
  cycle.json["scenes"] = json::array({{{"nodes", {0}}}});
  expect_load_error(cycle.write(dir, "cycle"), "node 0 is its own ancestor (cycle");

  GltfBuilder root_and_child = triangle_mesh();
  root_and_child.add_node({{"children", {1}}});
  root_and_child.add_node({{"mesh", 0}});
  root_and_child.json["scenes"] = json::array({{{"nodes", {0, 1}}}});
  expect_load_error(root_and_child.write(dir, "root_and_child"), "node 1 is reached twice");
}

TEST(GltfLimits, FlattenedInstancesAreCapped) {
  GltfBuilder b = triangle_mesh();
  for (int i = 0; i < 5; ++i) b.add_node({{"mesh", 0}});
  b.json["scenes"] = json::array({{{"nodes", {0, 1, 2, 3, 4}}}});
  const auto path = b.write(test::gltf_test_dir(), "five");
  EXPECT_EQ(load_gltf(path).instances.size(), 5u);
  GltfLoadOptions options;
  options.limits.max_instances = 4;
  expect_load_error(path, "node 4 would be mesh instance 5, more than 4 (GltfLimits::max_instances)",
                    options);
}

// POSITION accessor 0 with `count` elements over the 36-byte bufferView of one triangle.
std::filesystem::path oversized_accessor(const std::filesystem::path& dir, const std::string& name,
                                         uint64_t count) {
  GltfBuilder b = triangle_mesh();
  b.json["accessors"][0]["count"] = count;
  b.add_node({{"mesh", 0}});
  b.json["scenes"] = json::array({{{"nodes", {0}}}});
  return b.write(dir, name);
}

TEST(GltfLimits, HugeAccessorCountsFailBeforeAllocating) {
  const auto dir = test::gltf_test_dir();
  const double peak_before_mib = peak_rss_mib();
  // 2^27 elements of 12 bytes: 1.5 GiB of zeros used to be written before the bounds check.
  expect_load_error(oversized_accessor(dir, "two_pow_27", uint64_t{1} << 27),
                    "accessor 0 (byteOffset 0, count 134217728, stride 12) reads past the end of "
                    "bufferView 0 (36 bytes)");
  // 2^29 elements (6 GiB) and 2^31 (a bare std::bad_alloc naming no file) pass the file's
  // geometry budget before anything is allocated.
  expect_load_error(oversized_accessor(dir, "two_pow_29", uint64_t{1} << 29),
                    "mesh 0 primitive 0 attribute POSITION would bring the decoded geometry to "
                    "6442450944 bytes, more than 4294967296");
  expect_load_error(oversized_accessor(dir, "two_pow_31", uint64_t{1} << 31),
                    "(GltfLimits::max_decoded_geometry_bytes)");
  // Without a bufferView the elements are zeros (spec 3.6.2.3): bounded by the geometry budget.
  GltfBuilder zeros = triangle_mesh();
  zeros.json["accessors"][0].erase("bufferView");
  zeros.json["accessors"][0]["count"] = uint64_t{1} << 31;
  zeros.add_node({{"mesh", 0}});
  zeros.json["scenes"] = json::array({{{"nodes", {0}}}});
  expect_load_error(zeros.write(dir, "zeros"),
                    "mesh 0 primitive 0 attribute POSITION would bring the decoded geometry to "
                    "25769803776 bytes, more than 4294967296 (GltfLimits::max_decoded_geometry_bytes)");
  EXPECT_LT(peak_rss_mib() - peak_before_mib, 256.0) << "MiB more resident memory at the peak";
}

TEST(GltfLimits, DecodedGeometryBudgetCountsEveryAccessor) {
  GltfBuilder b = triangle_mesh();
  b.add_node({{"mesh", 0}});
  b.json["scenes"] = json::array({{{"nodes", {0}}}});
  const auto path = b.write(test::gltf_test_dir(), "triangle");
  GltfLoadOptions options;
  // 36 bytes of positions fit; the 12 bytes of generated indices do not.
  options.limits.max_decoded_geometry_bytes = 40;
  expect_load_error(path, "mesh 0 primitive 0 generated indices would bring the decoded geometry "
                          "to 48 bytes, more than 40", options);
}

// A PNG whose header declares width x height: a 1x1 image with its IHDR size rewritten (and
// the chunk CRC recomputed). The pixel data does not match; only the header is read first.
std::vector<uint8_t> png_declaring(uint32_t width, uint32_t height) {
  std::vector<uint8_t> png = test::make_png(1, 1, 2, 8, {10, 20, 30});
  // Signature (8), IHDR length (4), "IHDR" (4), width at 16, height at 20, CRC after 13 bytes.
  for (int k = 0; k < 4; ++k) {
    png[16 + k] = static_cast<uint8_t>(width >> (24 - 8 * k));
    png[20 + k] = static_cast<uint8_t>(height >> (24 - 8 * k));
  }
  uint32_t crc = 0xFFFFFFFFu;
  for (size_t i = 12; i < 12 + 4 + 13; ++i) {
    crc ^= png[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  crc ^= 0xFFFFFFFFu;
  for (int k = 0; k < 4; ++k) png[29 + k] = static_cast<uint8_t>(crc >> (24 - 8 * k));
  return png;
}

// A triangle whose material's base colour texture is image 0 with the given URI.
GltfBuilder textured_triangle(const std::string& image_uri) {
  GltfBuilder b = triangle_mesh();
  b.json["meshes"][0]["primitives"][0]["material"] = 0;
  b.add_node({{"mesh", 0}});
  b.json["scenes"] = json::array({{{"nodes", {0}}}});
  b.json["images"] = json::array({{{"uri", image_uri}}});
  b.json["textures"] = json::array({{{"source", 0}}});
  b.json["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
  return b;
}

std::string png_data_uri(const std::vector<uint8_t>& png) {
  return "data:image/png;base64," + test::base64(png);
}

TEST(GltfLimits, ImageSizesAreCheckedBeforeDecoding) {
  const auto dir = test::gltf_test_dir();
  const double peak_before_mib = peak_rss_mib();
  const auto path = textured_triangle(png_data_uri(png_declaring(16384, 16384))).write(dir, "huge");
  expect_load_error(path, "image 0 declares 16384x16384 texels, more than 67108864 "
                          "(GltfLimits::max_image_texels)");
  EXPECT_LT(peak_rss_mib() - peak_before_mib, 256.0) << "MiB more resident memory at the peak";
  // Raising the limit lets the decoder try; the corrupt pixel data is then named as such.
  GltfLoadOptions raised;
  raised.limits.max_image_texels = raised.limits.max_total_image_texels = uint64_t{1} << 28;
  expect_load_error(path, "image 0 cannot be decoded: ", raised);
  // Each image within the limit, the two together over a lowered total.
  GltfLoadOptions small_total;
  small_total.limits.max_total_image_texels = 1000;
  const std::vector<uint8_t> png_30x30 = test::make_png(30, 30, 2, 8, std::vector<uint16_t>(2700, 128));
  GltfBuilder b = textured_triangle(png_data_uri(png_30x30));
  b.json["images"].push_back({{"uri", png_data_uri(png_30x30)}});
  const auto two = b.write(dir, "two");
  EXPECT_NO_THROW(load_gltf(two));
  expect_load_error(two, "image 1 brings the file's images to 1800 texels, more than 1000 "
                         "(GltfLimits::max_total_image_texels)", small_total);
}

TEST(GltfLimits, UndecodableImagesNameTheImageAndTheProblem) {
  const auto dir = test::gltf_test_dir();
  test::write_bytes(dir / "bad.png", "\x89PNG but not really a PNG file");
  expect_load_error(textured_triangle("bad.png").write(dir, "external"),
                    "image 0 ('bad.png') cannot be decoded: ");
  const std::vector<uint8_t> text = {'h', 'e', 'l', 'l', 'o', '!'};
  expect_load_error(textured_triangle(png_data_uri(text)).write(dir, "embedded"),
                    "image 0 cannot be decoded: ");
}

TEST(GltfLimits, UrisOutsideTheSceneFolderAreRefused) {
  const auto dir = test::gltf_test_dir();
  GltfBuilder b = triangle_mesh();
  b.add_node({{"mesh", 0}});
  b.json["scenes"] = json::array({{{"nodes", {0}}}});
  const auto escaping = b.write(dir, "escaping", "../../../../../../../../etc/passwd", false);
  expect_load_error(escaping, "URI '");
  expect_load_error(escaping, "resolves outside the scene's folder");
  const auto absolute = b.write(dir, "absolute", "/etc/passwd", false);
  expect_load_error(absolute, "URI '/etc/passwd' is an absolute path");

  // A valid texture one folder up: refused by default, loaded when the caller allows it.
  const auto outside_png = dir.parent_path() / "outside_texture.png";
  const std::vector<uint8_t> png = test::make_png(1, 1, 2, 8, {10, 20, 30});
  test::write_bytes(outside_png, std::string(png.begin(), png.end()));
  const auto up = textured_triangle("../outside_texture.png").write(dir, "up");
  expect_load_error(up, "resolves outside the scene's folder");
  GltfLoadOptions allowed;
  allowed.allow_uris_outside_scene_folder = true;
  EXPECT_NO_THROW(load_gltf(up, allowed));
  // A subfolder is inside.
  std::filesystem::create_directories(dir / "textures");
  test::write_bytes(dir / "textures" / "inside.png", std::string(png.begin(), png.end()));
  EXPECT_NO_THROW(load_gltf(textured_triangle("textures/inside.png").write(dir, "inside")));
}

TEST(GltfLimits, DataUrisWithBadBase64AreRefused) {
  const auto dir = test::gltf_test_dir();
  GltfBuilder b = triangle_mesh();
  b.add_node({{"mesh", 0}});
  b.json["scenes"] = json::array({{{"nodes", {0}}}});
  const std::string header = "data:application/octet-stream;base64,";
  const std::string good = test::base64(b.bin);  // 36 bytes: 48 symbols, no padding
  std::string bad_symbol = good;
  bad_symbol[20] = '*';
  b.json["buffers"] = json::array({{{"byteLength", b.bin.size()}, {"uri", header + bad_symbol}}});
  test::write_bytes(dir / "symbol.gltf", b.json.dump());
  expect_load_error(dir / "symbol.gltf", "is not valid base64: '*' at payload position 20");
  b.json["buffers"][0]["uri"] = header + good.substr(0, 47);
  test::write_bytes(dir / "length.gltf", b.json.dump());
  expect_load_error(dir / "length.gltf", "payload length 47 is not a multiple of 4");
  b.json["buffers"][0]["uri"] = header + good.substr(0, 40) + "==" + good.substr(42);
  test::write_bytes(dir / "padding.gltf", b.json.dump());
  expect_load_error(dir / "padding.gltf", "'=' padding before the end of the payload");
  b.json["buffers"][0]["uri"] = header + good;
  test::write_bytes(dir / "good.gltf", b.json.dump());
  EXPECT_EQ(load_gltf(dir / "good.gltf").instances.size(), 1u);
}

TEST(GltfLimits, CameraWithZeroScaleIsRefused) {
  GltfBuilder b = triangle_mesh();
  b.add_node({{"mesh", 0}});
  b.add_node({{"camera", 0}, {"translation", {0.0, 0.0, 3.0}}, {"scale", {0.0, 0.0, 0.0}}});
  b.json["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}});
  b.json["scenes"] = json::array({{{"nodes", {0, 1}}}});
  expect_load_error(b.write(test::gltf_test_dir(), "zero_scale"),
                    "node 1 (camera 0) has a degenerate transform (zero scale");
}

}  // namespace
}  // namespace ontile
