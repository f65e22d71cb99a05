// Tests of the procedural scene generators (src/scene/gen): byte determinism, glTF validity via
// tinygltf, triangle budgets, toon-material extras, camera framing and the error paths.
#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/gen/glb_writer.h"
#include "scene/gen/png_encoder.h"
#include "scene/gen/scene_generator.h"
#include "util/error.h"

namespace ontile {
namespace {

namespace fs = std::filesystem;

fs::path test_dir() {
  const fs::path dir = fs::temp_directory_path() / ("ontile_scene_gen_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

tinygltf::Model load_glb(const fs::path& path) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const bool ok = loader.LoadBinaryFromFile(&model, &err, &warn, path.string());
  EXPECT_TRUE(ok) << path;
  EXPECT_EQ(err, "");
  EXPECT_EQ(warn, "");
  return model;
}

fs::path generate(const std::string& name, double size, const std::string& file) {
  const fs::path path = test_dir() / file;
  generate_scene(name, SceneGenOptions{size}, path);
  return path;
}

// Tightly packed accessor data (the generator writes no byteStride), as floats.
std::vector<float> read_floats(const tinygltf::Model& model, int accessor_index) {
  const tinygltf::Accessor& accessor = model.accessors.at(accessor_index);
  const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
  EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  const size_t components = tinygltf::GetNumComponentsInType(accessor.type);
  std::vector<float> values(accessor.count * components);
  std::memcpy(values.data(), model.buffers.at(view.buffer).data.data() + view.byteOffset + accessor.byteOffset,
              values.size() * sizeof(float));
  return values;
}

std::vector<uint32_t> read_indices(const tinygltf::Model& model, int accessor_index) {
  const tinygltf::Accessor& accessor = model.accessors.at(accessor_index);
  const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
  const unsigned char* data =
      model.buffers.at(view.buffer).data.data() + view.byteOffset + accessor.byteOffset;
  std::vector<uint32_t> indices(accessor.count);
  for (size_t i = 0; i < accessor.count; ++i) {
    if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
      uint16_t value;
      std::memcpy(&value, data + 2 * i, 2);
      indices[i] = value;
    } else {
      EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
      std::memcpy(&indices[i], data + 4 * i, 4);
    }
  }
  return indices;
}

// Triangles drawn by the default scene: every node's mesh counted once per node (all nodes
// are roots in generated files; children are followed anyway).
uint64_t drawn_triangles(const tinygltf::Model& model) {
  uint64_t triangles = 0;
  std::vector<int> pending(model.scenes.at(model.defaultScene).nodes);
  while (!pending.empty()) {
    const tinygltf::Node& node = model.nodes.at(pending.back());
    pending.pop_back();
    pending.insert(pending.end(), node.children.begin(), node.children.end());
    if (node.mesh < 0) continue;
    for (const tinygltf::Primitive& primitive : model.meshes.at(node.mesh).primitives) {
      EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);
      triangles += model.accessors.at(primitive.indices).count / 3;
    }
  }
  return triangles;
}

// Vertex streams finite, normals and tangents unit length, tangent w = +-1, indices in range
// and uint16 exactly when the vertex count allows it, and every triangle wound
// counter-clockwise around its vertex normals (glTF front faces).
void check_geometry(const tinygltf::Model& model) {
  for (const tinygltf::Mesh& mesh : model.meshes) {
    for (const tinygltf::Primitive& primitive : mesh.primitives) {
      const std::vector<float> positions = read_floats(model, primitive.attributes.at("POSITION"));
      const std::vector<float> normals = read_floats(model, primitive.attributes.at("NORMAL"));
      const std::vector<float> tangents = read_floats(model, primitive.attributes.at("TANGENT"));
      ASSERT_EQ(read_floats(model, primitive.attributes.at("TEXCOORD_0")).size() / 2,
                positions.size() / 3);
      const size_t vertex_count = positions.size() / 3;
      ASSERT_EQ(normals.size(), positions.size());
      ASSERT_EQ(tangents.size() / 4, vertex_count);
      for (size_t v = 0; v < vertex_count; ++v) {
        const glm::vec3 p(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
        const glm::vec3 n(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
        const glm::vec3 t(tangents[4 * v], tangents[4 * v + 1], tangents[4 * v + 2]);
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << mesh.name;
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-3f) << mesh.name << " vertex " << v;
        ASSERT_NEAR(glm::length(t), 1.0f, 1e-3f) << mesh.name << " vertex " << v;
        ASSERT_NEAR(glm::dot(n, t), 0.0f, 1e-3f) << mesh.name << " vertex " << v;
        ASSERT_EQ(std::abs(tangents[4 * v + 3]), 1.0f);
      }
      const tinygltf::Accessor& index_accessor = model.accessors.at(primitive.indices);
      EXPECT_EQ(index_accessor.componentType, vertex_count <= 65535
                                                  ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                                                  : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
      const std::vector<uint32_t> indices = read_indices(model, primitive.indices);
      ASSERT_EQ(indices.size() % 3, 0u);
      for (size_t i = 0; i < indices.size(); i += 3) {
        glm::vec3 p[3], n(0.0f);
        for (int k = 0; k < 3; ++k) {
          ASSERT_LT(indices[i + k], vertex_count);
          const size_t v = indices[i + k];
          p[k] = glm::vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
          n += glm::vec3(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
        }
        const glm::vec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
        ASSERT_GT(glm::length(face), 0.0f) << mesh.name << " triangle " << i / 3;
        ASSERT_GT(glm::dot(face, n), 0.0f) << mesh.name << " triangle " << i / 3;
      }
    }
  }
}

// Generated files go to one folder per test process, removed after the suite.
class SceneGenerator : public ::testing::Test {
 protected:
  static void TearDownTestSuite() { fs::remove_all(test_dir()); }
};

const tinygltf::Value& ontile_extras(const tinygltf::Material& material) {
  EXPECT_TRUE(material.extras.Has("ontile")) << material.name;
  return material.extras.Get("ontile");
}

TEST_F(SceneGenerator, NamesAreSorted) {
  EXPECT_EQ(scene_generator_names(), (std::vector<std::string>{"atrium", "demo"}));
}

TEST_F(SceneGenerator, OutputIsByteIdenticalAcrossRuns) {
  for (const std::string name : {"demo", "atrium"}) {
    const std::string first = read_bytes(generate(name, 0.1, name + "_a.glb"));
    const std::string second = read_bytes(generate(name, 0.1, name + "_b.glb"));
    EXPECT_GT(first.size(), 1000u) << name;
    EXPECT_TRUE(first == second) << name << " differs between runs";
  }
}

TEST_F(SceneGenerator, DemoIsAValidToonShowcase) {
  const fs::path path = generate("demo", 1.0, "demo.glb");
  EXPECT_LT(fs::file_size(path), 1000000u);
  const tinygltf::Model model = load_glb(path);
  const uint64_t triangles = drawn_triangles(model);
  EXPECT_GE(triangles, 500u);
  EXPECT_LE(triangles, 20000u);
  check_geometry(model);

  ASSERT_EQ(model.cameras.size(), 1u);
  EXPECT_EQ(model.cameras[0].type, "perspective");
  EXPECT_NEAR(model.cameras[0].perspective.aspectRatio, 16.0 / 9.0, 1e-6);
  int directional = 0, point = 0;
  for (const tinygltf::Light& light : model.lights) {
    directional += light.type == "directional";
    if (light.type == "point") {
      ++point;
      EXPECT_GT(light.range, 0.0) << light.name;
    }
  }
  EXPECT_EQ(directional, 1);
  EXPECT_EQ(point, 2);

  std::set<int> cel_steps;
  std::set<std::string> shaders, matcaps;
  int bordered = 0, borderless = 0;
  for (const tinygltf::Material& material : model.materials) {
    const tinygltf::Value& extras = ontile_extras(material);
    const std::string shader = extras.Get("shader").Get<std::string>();
    shaders.insert(shader);
    if (shader == "cel") cel_steps.insert(extras.Get("steps").GetNumberAsInt());
    if (shader == "matcap") matcaps.insert(extras.Get("matcap").Get<std::string>());
    if (shader == "toon_env") {
      EXPECT_GT(extras.Get("outline_thickness").GetNumberAsDouble(), 0.0);
    }
    const tinygltf::Value& border = extras.Get("border_color");
    ASSERT_EQ(border.ArrayLen(), 4u) << material.name;
    const double alpha = border.Get(3).GetNumberAsDouble();
    bordered += alpha == 1.0;
    borderless += alpha == 0.0;
  }
  EXPECT_EQ(cel_steps, (std::set<int>{1, 3, 6}));
  EXPECT_EQ(shaders, (std::set<std::string>{"cel", "matcap", "toon_env"}));
  EXPECT_EQ(matcaps, (std::set<std::string>{"clay", "metal", "painted"}));
  EXPECT_GE(bordered, 1);
  EXPECT_GE(borderless, 1);
}

// Every mesh node of the demo lies inside the camera's view frustum (16:9).
TEST_F(SceneGenerator, DemoCameraSeesEveryObject) {
  const tinygltf::Model model = load_glb(generate("demo", 1.0, "demo_camera.glb"));
  const tinygltf::Node* camera_node = nullptr;
  for (const tinygltf::Node& node : model.nodes) {
    if (node.camera >= 0) camera_node = &node;
  }
  ASSERT_NE(camera_node, nullptr);
  const glm::quat rotation(static_cast<float>(camera_node->rotation[3]), static_cast<float>(camera_node->rotation[0]),
                           static_cast<float>(camera_node->rotation[1]), static_cast<float>(camera_node->rotation[2]));
  const glm::vec3 eye(camera_node->translation[0], camera_node->translation[1], camera_node->translation[2]);
  const tinygltf::PerspectiveCamera& lens = model.cameras.at(camera_node->camera).perspective;
  const double tan_half_y = std::tan(lens.yfov / 2), tan_half_x = tan_half_y * lens.aspectRatio;
  int objects = 0;
  for (const tinygltf::Node& node : model.nodes) {
    if (node.mesh < 0 || node.name == "ground") continue;
    ++objects;
    const glm::vec3 position(node.translation[0], node.translation[1], node.translation[2]);
    const glm::vec3 in_view = glm::conjugate(rotation) * (position - eye);
    ASSERT_LT(in_view.z, 0.0f) << node.name << " is behind the camera";
    EXPECT_LT(std::abs(in_view.x / in_view.z), 0.9 * tan_half_x) << node.name;
    EXPECT_LT(std::abs(in_view.y / in_view.z), 0.9 * tan_half_y) << node.name;
  }
  EXPECT_GE(objects, 6);
}

TEST_F(SceneGenerator, AtriumMeetsItsTriangleBudgetAndScalesLinearly) {
  const fs::path full_path = generate("atrium", 1.0, "atrium_1.glb");
  const tinygltf::Model full = load_glb(full_path);
  const uint64_t full_triangles = drawn_triangles(full);
  EXPECT_GE(full_triangles, 225000u);
  EXPECT_LE(full_triangles, 275000u);
  const uint64_t half_triangles = drawn_triangles(load_glb(generate("atrium", 0.5, "atrium_05.glb")));
  const double ratio = static_cast<double>(half_triangles) / static_cast<double>(full_triangles);
  EXPECT_GT(ratio, 0.4);
  EXPECT_LT(ratio, 0.6);
  EXPECT_LT(full.nodes.size(), 500u);
}

TEST_F(SceneGenerator, AtriumIsValidAndTextured) {
  const tinygltf::Model model = load_glb(generate("atrium", 0.1, "atrium_01.glb"));
  check_geometry(model);
  ASSERT_EQ(model.cameras.size(), 1u);
  int directional = 0, point = 0;
  for (const tinygltf::Light& light : model.lights) {
    directional += light.type == "directional";
    point += light.type == "point" && light.range > 0.0;
  }
  EXPECT_EQ(directional, 1);
  EXPECT_EQ(point, 4);
  int textured = 0;
  for (const tinygltf::Material& material : model.materials) {
    const int texture = material.pbrMetallicRoughness.baseColorTexture.index;
    if (texture < 0) continue;
    ++textured;
    ASSERT_LT(texture, static_cast<int>(model.textures.size()));
    const tinygltf::Image& image = model.images.at(model.textures[texture].source);
    EXPECT_GE(image.width, 256) << material.name;
    EXPECT_EQ(image.width, image.height) << material.name;
    EXPECT_EQ(image.image.size(), static_cast<size_t>(image.width) * image.height * image.component);
  }
  EXPECT_EQ(textured, static_cast<int>(model.materials.size()));
}

// The PNG encoder round-trips exactly through a standard decoder (stb_image in tinygltf),
// on a noisy texture that exercises literals, matches and all row filters.
TEST_F(SceneGenerator, PngEncoderRoundTrips) {
  const gen::RgbImage marble = gen::make_marble_texture(96, 5);
  const std::vector<uint8_t> png = gen::encode_png(marble);
  tinygltf::Image decoded;
  std::string err, warn;
  ASSERT_TRUE(tinygltf::LoadImageData(&decoded, 0, &err, &warn, 0, 0, png.data(),
                                      static_cast<int>(png.size()), nullptr))
      << err;
  ASSERT_EQ(decoded.width, 96);
  ASSERT_EQ(decoded.height, 96);
  ASSERT_EQ(decoded.component, 4);  // tinygltf expands to RGBA
  for (size_t i = 0; i < marble.rgb.size() / 3; ++i) {
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(decoded.image[4 * i + c], marble.rgb[3 * i + c]) << i;
    }
    ASSERT_EQ(decoded.image[4 * i + 3], 255);
  }
}

// Primitives beyond 65535 vertices get 32-bit indices and still load.
TEST_F(SceneGenerator, LargePrimitivesUse32BitIndices) {
  gen::GeneratedScene scene;
  gen::MeshData grid;
  gen::add_quad(grid, glm::vec3(0.0f), glm::vec3(10, 0, 0), glm::vec3(0, 0, -10), 300, 300, 1.0f);
  ASSERT_EQ(grid.vertex_count(), 301u * 301u);
  scene.meshes.push_back({"grid", {{std::move(grid), -1}}});
  scene.nodes.push_back({"grid", 0, -1, -1, glm::vec3(0.0f), glm::quat(1, 0, 0, 0)});
  const fs::path path = test_dir() / "large_grid.glb";
  gen::write_glb(scene, path);
  const tinygltf::Model model = load_glb(path);
  EXPECT_EQ(drawn_triangles(model), 2u * 300u * 300u);
  check_geometry(model);
}

TEST_F(SceneGenerator, RejectsUnknownNamesAndBadSizes) {
  const fs::path path = test_dir() / "never_written.glb";
  try {
    generate_scene("sponza", SceneGenOptions{}, path);
    FAIL() << "unknown name accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'sponza'"), std::string::npos) << message;
    EXPECT_NE(message.find("atrium, demo"), std::string::npos) << message;
  }
  for (const double size : {0.0, 0.049, 64.5, -1.0, std::nan(""), HUGE_VAL}) {
    EXPECT_THROW(generate_scene("atrium", SceneGenOptions{size}, path), Error) << size;
  }
  EXPECT_NO_THROW(generate_scene("demo", SceneGenOptions{0.05}, test_dir() / "demo_min.glb"));
  EXPECT_FALSE(fs::exists(path));
  EXPECT_THROW(generate_scene("demo", SceneGenOptions{}, test_dir() / "missing_dir" / "x.glb"),
               Error);
}

}  // namespace
}  // namespace ontile
