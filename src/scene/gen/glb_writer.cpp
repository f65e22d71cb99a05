// Converts a GeneratedScene to a tinygltf::Model (one binary buffer, PNG images in buffer views)
// and writes it as .glb. tinygltf serialises JSON through nlohmann::json, whose objects are
// key-sorted and whose number formatting ignores the locale, so equal models give equal bytes.
#include "scene/gen/glb_writer.h"

#include <charconv>
#include <fstream>
#include <limits>

#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

#include "scene/gen/png_encoder.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace ontile::gen {
namespace {

constexpr int kSamplerRepeat = TINYGLTF_TEXTURE_WRAP_REPEAT;

// Appends byte ranges to the single GLB buffer, each as its own 4-byte-aligned buffer view
// (glTF 2.0 3.6.2.4: accessor offsets must be multiples of the component size).
class BufferAssembler {
 public:
  explicit BufferAssembler(tinygltf::Model& model) : model_(model) {}
  int add_view(const void* bytes, size_t size_bytes, int target) {
    std::vector<unsigned char>& data = model_.buffers[0].data;
    data.resize((data.size() + 3) & ~size_t{3}, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size_bytes;
    view.target = target;
    const auto* first = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), first, first + size_bytes);
    model_.bufferViews.push_back(view);
    return static_cast<int>(model_.bufferViews.size()) - 1;
  }
  template <typename T>
  int add_accessor(const std::vector<T>& values, int component_type, int type, int target) {
    tinygltf::Accessor accessor;
    accessor.bufferView = add_view(values.data(), values.size() * sizeof(T), target);
    accessor.componentType = component_type;
    accessor.type = type;
    accessor.count = values.size();
    model_.accessors.push_back(accessor);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

 private:
  tinygltf::Model& model_;
};

tinygltf::Value to_value(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      tinygltf::Value::Object object;
      for (const auto& [key, item] : j.items()) object[key] = to_value(item);
      return tinygltf::Value(std::move(object));
    }
    case nlohmann::json::value_t::array: {
      tinygltf::Value::Array array;
      for (const auto& item : j) array.push_back(to_value(item));
      return tinygltf::Value(std::move(array));
    }
    case nlohmann::json::value_t::string: return tinygltf::Value(j.get<std::string>());
    case nlohmann::json::value_t::boolean: return tinygltf::Value(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned: return tinygltf::Value(j.get<int>());
    case nlohmann::json::value_t::number_float: return tinygltf::Value(j.get<double>());
    default: return tinygltf::Value();
  }
}

// The double nearest to the float's shortest decimal form (to_chars / from_chars, no locale),
// so 0.8f is written as 0.8 rather than 0.800000011920929 and still reads back as 0.8f.
double clean_double(float value) {
  char text[32];
  const auto written = std::to_chars(text, text + sizeof(text), value);
  double result = 0.0;
  std::from_chars(text, written.ptr, result);
  return result;
}

std::vector<double> to_doubles(const float* values, int count) {
  std::vector<double> out;
  for (int i = 0; i < count; ++i) out.push_back(clean_double(values[i]));
  return out;
}

tinygltf::Primitive convert_primitive(GenPrimitive& primitive, BufferAssembler& buffers,
                                      tinygltf::Model& model) {
  MeshData& mesh = primitive.geometry;
  if (mesh.tangents.size() != mesh.positions.size()) compute_tangents(mesh);
  tinygltf::Primitive out;
  out.mode = TINYGLTF_MODE_TRIANGLES;
  out.material = primitive.material;
  const int position = buffers.add_accessor(mesh.positions, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                            TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
  // POSITION requires min and max (glTF 2.0 3.7.2.1).
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  model.accessors[position].minValues = to_doubles(&lo.x, 3);
  model.accessors[position].maxValues = to_doubles(&hi.x, 3);
  out.attributes["POSITION"] = position;
  out.attributes["NORMAL"] = buffers.add_accessor(
      mesh.normals, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
  out.attributes["TANGENT"] = buffers.add_accessor(
      mesh.tangents, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER);
  out.attributes["TEXCOORD_0"] = buffers.add_accessor(
      mesh.uvs, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, TINYGLTF_TARGET_ARRAY_BUFFER);
  if (mesh.vertex_count() <= 65535) {
    const std::vector<uint16_t> narrow(mesh.indices.begin(), mesh.indices.end());
    out.indices = buffers.add_accessor(narrow, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                       TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  } else {
    out.indices = buffers.add_accessor(mesh.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                       TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  }
  return out;
}

tinygltf::Model build_model(GeneratedScene& scene) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "ontile gen-scene";
  model.buffers.resize(1);
  BufferAssembler buffers(model);

  if (!scene.images.empty()) {
    tinygltf::Sampler sampler;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.wrapS = kSamplerRepeat;
    sampler.wrapT = kSamplerRepeat;
    model.samplers.push_back(sampler);
  }
  for (const GenImage& image : scene.images) {
    const std::vector<uint8_t> png = encode_png(image.pixels);
    tinygltf::Image out;
    out.name = image.name;
    out.mimeType = "image/png";
    out.bufferView = buffers.add_view(png.data(), png.size(), 0);  // images have no target
    model.images.push_back(out);
    tinygltf::Texture texture;
    texture.name = image.name;
    texture.sampler = 0;
    texture.source = static_cast<int>(model.images.size()) - 1;
    model.textures.push_back(texture);
  }
  for (const GenMaterial& material : scene.materials) {
    tinygltf::Material out;
    out.name = material.name;
    out.pbrMetallicRoughness.baseColorFactor = to_doubles(&material.base_color_factor.x, 4);
    out.pbrMetallicRoughness.metallicFactor = clean_double(material.metallic_factor);
    out.pbrMetallicRoughness.roughnessFactor = clean_double(material.roughness_factor);
    out.pbrMetallicRoughness.baseColorTexture.index = material.base_color_image;
    out.doubleSided = material.double_sided;
    if (!material.extras.is_null()) out.extras = to_value(material.extras);
    model.materials.push_back(out);
  }
  for (GenMesh& mesh : scene.meshes) {
    tinygltf::Mesh out;
    out.name = mesh.name;
    for (GenPrimitive& primitive : mesh.primitives) {
      out.primitives.push_back(convert_primitive(primitive, buffers, model));
    }
    model.meshes.push_back(out);
  }
  for (const GenCamera& camera : scene.cameras) {
    tinygltf::Camera out;
    out.name = camera.name;
    out.type = "perspective";
    out.perspective.yfov = clean_double(camera.yfov_rad);
    out.perspective.aspectRatio = clean_double(camera.aspect_ratio);
    out.perspective.znear = clean_double(camera.znear_m);
    out.perspective.zfar = clean_double(camera.zfar_m);
    model.cameras.push_back(out);
  }
  for (const GenLight& light : scene.lights) {
    tinygltf::Light out;
    out.name = light.name;
    out.type = light.type == GenLight::Type::Directional ? "directional" : "point";
    out.color = to_doubles(&light.colour.x, 3);
    out.intensity = clean_double(light.intensity);
    out.range = clean_double(light.range_m);
    model.lights.push_back(out);
  }
  tinygltf::Scene root;
  root.name = "scene";
  for (const GenNode& node : scene.nodes) {
    tinygltf::Node out;
    out.name = node.name;
    out.mesh = node.mesh;
    out.camera = node.camera;
    if (node.light >= 0) {
      tinygltf::Value::Object light_ref;
      light_ref["light"] = tinygltf::Value(node.light);
      out.extensions["KHR_lights_punctual"] = tinygltf::Value(std::move(light_ref));
    }
    if (node.translation != glm::vec3(0.0f)) out.translation = to_doubles(&node.translation.x, 3);
    if (node.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
      const float xyzw[4] = {node.rotation.x, node.rotation.y, node.rotation.z, node.rotation.w};
      out.rotation = to_doubles(xyzw, 4);
    }
    root.nodes.push_back(static_cast<int>(model.nodes.size()));
    model.nodes.push_back(out);
  }
  model.scenes.push_back(root);
  model.defaultScene = 0;
  return model;
}

}  // namespace

glm::quat rotation_looking_along(const glm::vec3& direction, const glm::vec3& up) {
  const glm::vec3 back = -glm::normalize(direction);
  glm::vec3 right = glm::cross(up, back);
  if (glm::length(right) < 1e-6f) right = glm::cross(glm::vec3(0.0f, 0.0f, 1.0f), back);
  right = glm::normalize(right);
  const glm::vec3 local_up = glm::cross(back, right);
  return glm::normalize(glm::quat_cast(glm::mat3(right, local_up, back)));
}

void write_glb(GeneratedScene& scene, const std::filesystem::path& out_glb) {
  const tinygltf::Model model = build_model(scene);
  write_file_atomically(out_glb, [&](const std::filesystem::path& tmp_path) {
    std::ofstream stream(tmp_path, std::ios::binary | std::ios::trunc);
    if (!stream) throw Error(out_glb.string() + ": cannot open '" + tmp_path.string() + "' for writing");
    // The stream variant of tinygltf's writer, because WriteGltfSceneToFile does not report
    // failed writes (tinygltf 2.7 ignores the stream state); the serialisation is the same.
    tinygltf::TinyGLTF writer;
    const bool serialised = writer.WriteGltfSceneToStream(&model, stream, /*prettyPrint=*/false,
                                                          /*writeBinary=*/true);
    stream.close();
    if (!serialised || stream.fail()) throw Error(out_glb.string() + ": writing the .glb failed");
  });
}

}  // namespace ontile::gen
