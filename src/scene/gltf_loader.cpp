// glTF 2.0 loader entry point: reads the file with tinygltf, turns its errors into one-line
// ontile::Errors, checks required extensions and flattens the chosen scene's node tree into
// mesh instances, cameras and KHR_lights_punctual lights.
#include "scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "scene/gltf_internal.h"
#include "util/error.h"

namespace ontile {
namespace gltf {

void throw_error(const LoadContext& context, const std::string& problem) {
  throw Error(context.file_label + ": " + problem);
}

}  // namespace gltf

namespace {

using gltf::LoadContext;
using gltf::throw_error;

// tinygltf reports problems as several newline-terminated sentences; they become one line.
std::string one_line(const std::string& text) {
  std::istringstream lines(text);
  std::string line, joined;
  while (std::getline(lines, line)) {
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const size_t last = line.find_last_not_of(" \t\r");
    if (!joined.empty()) joined += "; ";
    joined += line.substr(first, last - first + 1);
  }
  return joined;
}

// The lines of tinygltf's text that mention `subject` (all of them when none does), as one line.
std::string lines_mentioning(const std::string& text, const std::string& subject) {
  std::istringstream lines(text);
  std::string line, matching;
  while (std::getline(lines, line)) {
    if (!subject.empty() && line.find(subject) != std::string::npos) matching += line + "\n";
  }
  return one_line(matching.empty() ? text : matching);
}

bool starts_with_glb_magic(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::array<char, 4> magic{};
  file.read(magic.data(), magic.size());
  return file.gcount() == 4 && std::string(magic.data(), 4) == "glTF";
}

// Extensions that the loader understands well enough to draw the file correctly. Lights and
// emissive strength are applied; KHR_mesh_quantization needs only the integer attribute
// decoding every accessor gets; KHR_texture_transform is accepted but not applied (textures
// using it sample with untransformed UVs).
bool is_supported_required_extension(const std::string& name) {
  return name == "KHR_lights_punctual" || name == "KHR_materials_emissive_strength" ||
         name == "KHR_texture_transform" || name == "KHR_mesh_quantization";
}

// A node's local transform: "matrix" (column-major) or T * R * S (spec 3.5.3). The quaternion
// (x, y, z, w) is used as stored; the spec requires it to be unit length.
glm::dmat4 local_transform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::dmat4 m;
    for (int column = 0; column < 4; ++column) {
      for (int row = 0; row < 4; ++row)
        m[column][row] = node.matrix[static_cast<size_t>(4 * column + row)];
    }
    return m;
  }
  glm::dmat4 translation(1.0), rotation(1.0), scale(1.0);
  if (node.translation.size() == 3) {
    translation[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  }
  if (node.rotation.size() == 4) {
    const double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2],
                 w = node.rotation[3];
    rotation[0] = glm::dvec4(1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0);
    rotation[1] = glm::dvec4(2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0);
    rotation[2] = glm::dvec4(2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0);
  }
  if (node.scale.size() == 3) {
    scale[0][0] = node.scale[0];
    scale[1][1] = node.scale[1];
    scale[2][2] = node.scale[2];
  }
  return translation * rotation * scale;
}

// Cameras ignore scale (and any shear from scaled parents): the camera-to-world matrix keeps
// the node's world position and viewing direction (-Z exactly), with +Y made orthogonal to it
// (Gram-Schmidt) and X completing a right-handed frame.
glm::mat4 rigid_camera_frame(const glm::dmat4& world) {
  const glm::dvec3 back = glm::normalize(glm::dvec3(world[2]));
  glm::dvec3 up = glm::dvec3(world[1]);
  up = glm::normalize(up - back * glm::dot(up, back));
  const glm::dvec3 right = glm::cross(up, back);
  glm::dmat4 frame(1.0);
  frame[0] = glm::dvec4(right, 0.0);
  frame[1] = glm::dvec4(up, 0.0);
  frame[2] = glm::dvec4(back, 0.0);
  frame[3] = glm::dvec4(glm::dvec3(world[3]), 1.0);
  return glm::mat4(frame);
}

Bounds transform_bounds(const Bounds& bounds, const glm::mat4& world) {
  Bounds result;
  if (bounds.empty()) return result;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                      (corner & 2) ? bounds.max.y : bounds.min.y,
                      (corner & 4) ? bounds.max.z : bounds.min.z);
    result.extend(glm::vec3(world * glm::vec4(p, 1.0f)));
  }
  return result;
}

Camera convert_camera(const LoadContext& context, int camera_index, const glm::dmat4& world) {
  const tinygltf::Camera& source = context.model.cameras[static_cast<size_t>(camera_index)];
  const std::string where = "camera " + std::to_string(camera_index);
  Camera camera;
  camera.name = source.name;
  camera.world = rigid_camera_frame(world);
  if (source.type == "perspective") {
    const auto& p = source.perspective;
    if (!(p.yfov > 0.0 && p.yfov < std::numbers::pi) || !(p.znear > 0.0) || p.aspectRatio < 0.0 ||
        (p.zfar != 0.0 && !(p.zfar > p.znear))) {
      throw_error(context, where + " has invalid perspective parameters (yfov " +
                               std::to_string(p.yfov) + ", znear " + std::to_string(p.znear) +
                               ", zfar " + std::to_string(p.zfar) + ")");
    }
    camera.type = Camera::Type::Perspective;
    camera.yfov_rad = static_cast<float>(p.yfov);
    camera.aspect_ratio = static_cast<float>(p.aspectRatio);  // 0 when absent
    camera.znear = static_cast<float>(p.znear);
    camera.zfar = static_cast<float>(p.zfar);  // 0 when absent: infinite
  } else if (source.type == "orthographic") {
    const auto& o = source.orthographic;
    if (o.xmag == 0.0 || o.ymag == 0.0 || !(o.znear >= 0.0) || !(o.zfar > o.znear)) {
      throw_error(context, where + " has invalid orthographic parameters");
    }
    camera.type = Camera::Type::Orthographic;
    camera.xmag = static_cast<float>(o.xmag);
    camera.ymag = static_cast<float>(o.ymag);
    camera.znear = static_cast<float>(o.znear);
    camera.zfar = static_cast<float>(o.zfar);
  } else {
    throw_error(context, where + " has unknown type '" + source.type + "'");
  }
  return camera;
}

Light convert_light(const LoadContext& context, int light_index, const glm::dmat4& world) {
  const tinygltf::Light& source = context.model.lights[static_cast<size_t>(light_index)];
  Light light;
  light.name = source.name;
  if (source.type == "directional") {
    light.type = Light::Type::Directional;
  } else if (source.type == "point") {
    light.type = Light::Type::Point;
  } else if (source.type == "spot") {
    light.type = Light::Type::Spot;
    light.inner_cone_rad = static_cast<float>(source.spot.innerConeAngle);
    light.outer_cone_rad = static_cast<float>(source.spot.outerConeAngle);
  } else {
    throw_error(context,
                "light " + std::to_string(light_index) + " has unknown type '" + source.type + "'");
  }
  if (source.color.size() == 3)
    light.color = glm::vec3(source.color[0], source.color[1], source.color[2]);
  light.intensity = static_cast<float>(source.intensity);
  light.range = static_cast<float>(source.range);
  // KHR_lights_punctual: lights sit at the node's origin and shine down its local -Z.
  light.position = glm::vec3(world[3]);
  light.direction = glm::vec3(glm::normalize(glm::dvec3(world * glm::dvec4(0.0, 0.0, -1.0, 0.0))));
  return light;
}

class SceneFlattener {
 public:
  SceneFlattener(const LoadContext& context, Scene& scene)
      : context_(context), scene_(scene), on_path_(context.model.nodes.size(), false) {}

  void visit(int node_index, const glm::dmat4& parent_world) {
    const auto& model = context_.model;
    if (node_index < 0 || static_cast<size_t>(node_index) >= model.nodes.size()) {
      throw_error(context_, "node " + std::to_string(node_index) +
                                " does not exist (the file has " +
                                std::to_string(model.nodes.size()) + " nodes)");
    }
    if (on_path_[static_cast<size_t>(node_index)]) {
      throw_error(context_, "node " + std::to_string(node_index) + " is its own ancestor (cycle)");
    }
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(node_index)];
    const glm::dmat4 world = parent_world * local_transform(node);
    if (node.mesh >= 0) add_instance(node_index, node, world);
    if (node.camera >= 0) {
      if (static_cast<size_t>(node.camera) >= model.cameras.size()) {
        throw_error(context_, "node " + std::to_string(node_index) + " refers to camera " +
                                  std::to_string(node.camera) + ", which does not exist");
      }
      scene_.cameras.push_back(convert_camera(context_, node.camera, world));
    }
    const auto light_extension = node.extensions.find("KHR_lights_punctual");
    if (light_extension != node.extensions.end() && light_extension->second.Has("light")) {
      const int light = light_extension->second.Get("light").GetNumberAsInt();
      if (light < 0 || static_cast<size_t>(light) >= model.lights.size()) {
        throw_error(context_, "node " + std::to_string(node_index) + " refers to light " +
                                  std::to_string(light) + ", which does not exist");
      }
      scene_.lights.push_back(convert_light(context_, light, world));
    }
    on_path_[static_cast<size_t>(node_index)] = true;
    for (int child : node.children) visit(child, world);
    on_path_[static_cast<size_t>(node_index)] = false;
  }

 private:
  void add_instance(int node_index, const tinygltf::Node& node, const glm::dmat4& world) {
    if (static_cast<size_t>(node.mesh) >= scene_.meshes.size()) {
      throw_error(context_, "node " + std::to_string(node_index) + " refers to mesh " +
                                std::to_string(node.mesh) + ", which does not exist");
    }
    MeshInstance instance;
    instance.mesh = node.mesh;
    instance.node_name = node.name;
    // A skinned mesh ignores its node's transform (spec 3.7.3); without animation ontile draws
    // it in its bind pose, which is the mesh's own coordinates.
    instance.world = node.skin >= 0 ? glm::mat4(1.0f) : glm::mat4(world);
    Bounds object_bounds;
    for (const MeshPrimitive& primitive :
         scene_.meshes[static_cast<size_t>(node.mesh)].primitives) {
      object_bounds.extend(primitive.bounds);
    }
    instance.world_bounds = transform_bounds(object_bounds, instance.world);
    scene_.world_bounds.extend(instance.world_bounds);
    scene_.instances.push_back(std::move(instance));
  }

  const LoadContext& context_;
  Scene& scene_;
  std::vector<bool> on_path_;
};

// Root nodes of the scene to draw (spec 3.5.2): options.scene_index, else the file's "scene",
// else scene 0, else every node that is no other node's child.
std::vector<int> root_nodes(const LoadContext& context) {
  const auto& model = context.model;
  int scene_index = context.options.scene_index;
  if (scene_index < -1 ||
      (scene_index >= 0 && static_cast<size_t>(scene_index) >= model.scenes.size())) {
    throw_error(context, "scene index " + std::to_string(scene_index) +
                             " out of range (the file has " + std::to_string(model.scenes.size()) +
                             " scenes)");
  }
  if (scene_index < 0) scene_index = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (static_cast<size_t>(scene_index) < model.scenes.size()) {
    return model.scenes[static_cast<size_t>(scene_index)].nodes;
  }
  if (!model.scenes.empty()) {
    throw_error(context, "default scene " + std::to_string(scene_index) +
                             " out of range (the file has " + std::to_string(model.scenes.size()) +
                             " scenes)");
  }
  std::vector<bool> is_child(model.nodes.size(), false);
  for (const auto& node : model.nodes) {
    for (int child : node.children) {
      if (child >= 0 && static_cast<size_t>(child) < is_child.size())
        is_child[static_cast<size_t>(child)] = true;
    }
  }
  std::vector<int> roots;
  for (size_t n = 0; n < model.nodes.size(); ++n) {
    if (!is_child[n]) roots.push_back(static_cast<int>(n));
  }
  return roots;
}

tinygltf::Model read_model(const std::filesystem::path& path, const std::string& label,
                           GltfLoadStats& stats) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw Error(label + (std::filesystem::exists(path, error) ? ": not a regular file"
                                                              : ": file not found"));
  }
  const bool binary = starts_with_glb_magic(path);
  if (!binary && path.extension() == ".glb") {
    throw Error(label + ": not a GLB file (no 'glTF' magic at the start)");
  }
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string tiny_error, tiny_warning;
  const bool loaded =
      binary ? loader.LoadBinaryFromFile(&model, &tiny_error, &tiny_warning, path.string())
             : loader.LoadASCIIFromFile(&model, &tiny_error, &tiny_warning, path.string());
  if (!loaded) {
    const std::string reason = one_line(tiny_error + "\n" + tiny_warning);
    // tinygltf passes on the JSON parser's message; name the problem plainly in front of it.
    const bool json_syntax = reason.find("parse_error") != std::string::npos ||
                             reason.find("parse JSON") != std::string::npos;
    throw Error(label + (json_syntax ? ": invalid JSON: " : ": cannot load glTF: ") +
                (reason.empty() ? "unknown tinygltf error" : reason));
  }
  for (const std::string& extension : model.extensionsRequired) {
    if (!is_supported_required_extension(extension)) {
      throw Error(label + ": unsupported required extension " + extension);
    }
  }
  // tinygltf only warns when an external image is missing or unreadable; ontile refuses to
  // draw a model with a texture silently missing.
  for (size_t i = 0; i < model.images.size(); ++i) {
    const tinygltf::Image& image = model.images[i];
    if (image.image.empty()) {
      throw Error(label + ": image " + std::to_string(i) +
                  (image.uri.empty() ? std::string() : " ('" + image.uri + "')") +
                  " could not be loaded: " + lines_mentioning(tiny_warning, image.uri));
    }
  }
  const std::string warnings = one_line(tiny_warning);
  if (!warnings.empty()) stats.warnings.push_back(warnings);
  return model;
}

}  // namespace

Scene load_gltf(const std::filesystem::path& path, const GltfLoadOptions& options,
                GltfLoadStats* stats) {
  GltfLoadStats local_stats;
  GltfLoadStats& out_stats = stats ? *stats : local_stats;
  out_stats = GltfLoadStats{};
  const std::string label = path.string();
  const tinygltf::Model model = read_model(path, label, out_stats);
  const LoadContext context{model, label, options, out_stats};

  Scene scene;
  scene.source_path = label;
  for (size_t m = 0; m < model.meshes.size(); ++m) {
    scene.meshes.push_back(gltf::convert_mesh(context, static_cast<int>(m)));
  }
  scene.materials = gltf::convert_materials(context);
  SceneFlattener flattener(context, scene);
  for (int root : root_nodes(context)) flattener.visit(root, glm::dmat4(1.0));
  return scene;
}

}  // namespace ontile
