// glTF 2.0 loader entry point: reads the file (gltf_reader.cpp), converts meshes and materials,
// and flattens the chosen scene's node tree, composed in double, into mesh instances, cameras
// and KHR_lights_punctual lights.
#include "scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <cmath>
#include <numbers>

#include "scene/gltf_internal.h"
#include "util/error.h"

namespace ontile {
namespace gltf {

void throw_error(const LoadContext& context, const std::string& problem) {
  throw Error(context.file_label + ": " + problem);
}

void charge_geometry_bytes(const LoadContext& context, uint64_t bytes, const std::string& what) {
  const uint64_t limit = context.options.limits.max_decoded_geometry_bytes;
  if (bytes > limit || context.decoded_geometry_bytes > limit - bytes) {
    throw_error(context, what + " would bring the decoded geometry to " +
                             std::to_string(context.decoded_geometry_bytes + bytes) +
                             " bytes, more than " + std::to_string(limit) +
                             " (GltfLimits::max_decoded_geometry_bytes)");
  }
  context.decoded_geometry_bytes += bytes;
}

}  // namespace gltf

namespace {

using gltf::LoadContext;
using gltf::throw_error;

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
glm::dmat4 rigid_camera_frame(const glm::dmat4& world) {
  const glm::dvec3 back = glm::normalize(glm::dvec3(world[2]));
  glm::dvec3 up = glm::dvec3(world[1]);
  up = glm::normalize(up - back * glm::dot(up, back));
  const glm::dvec3 right = glm::cross(up, back);
  glm::dmat4 frame(1.0);
  frame[0] = glm::dvec4(right, 0.0);
  frame[1] = glm::dvec4(up, 0.0);
  frame[2] = glm::dvec4(back, 0.0);
  frame[3] = glm::dvec4(glm::dvec3(world[3]), 1.0);
  return frame;
}

// World bounds stay float (scene.h); they are computed with the float-rounded matrix, as before
// the transforms became double, so that the default camera framing them keeps its bits.
Bounds transform_bounds(const Bounds& bounds, const glm::dmat4& world) {
  Bounds result;
  if (bounds.empty()) return result;
  const glm::mat4 world_float(world);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                      (corner & 2) ? bounds.max.y : bounds.min.y,
                      (corner & 4) ? bounds.max.z : bounds.min.z);
    result.extend(glm::vec3(world_float * glm::vec4(p, 1.0f)));
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

bool all_finite(const glm::dmat4& m) {
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row)
      if (!std::isfinite(m[column][row])) return false;
  return true;
}

// Flattens the node tree depth first, each node before its children and children in order
// (the order of a recursive walk, which the primitive ids and camera order follow), with an
// explicit stack so that depth costs heap, not call stack. glTF 2.0 3.5.2 makes the nodes a
// forest: a node has at most one parent and no cycles, so each node is met once.
class SceneFlattener {
 public:
  SceneFlattener(const LoadContext& context, Scene& scene)
      : context_(context), scene_(scene), parent_(context.model.nodes.size(), -1),
        visited_(context.model.nodes.size(), false) {}

  void flatten(const std::vector<int>& roots) {
    record_single_parents();
    std::vector<Pending> stack;
    for (auto root = roots.rbegin(); root != roots.rend(); ++root) {
      check_exists(*root);
      stack.push_back({*root, -1, 1, glm::dmat4(1.0)});
    }
    const int max_depth = context_.options.limits.max_node_depth;
    while (!stack.empty()) {
      const Pending pending = stack.back();
      stack.pop_back();
      const size_t n = static_cast<size_t>(pending.node);
      if (visited_[n]) reached_twice(pending);
      if (pending.depth > max_depth) {
        throw_error(context_, "node " + std::to_string(pending.node) + " is nested " +
                                  std::to_string(pending.depth) + " levels deep, more than " +
                                  std::to_string(max_depth) + " (GltfLimits::max_node_depth)");
      }
      visited_[n] = true;
      const tinygltf::Node& node = context_.model.nodes[n];
      const glm::dmat4 world = pending.parent_world * local_transform(node);
      visit(pending.node, node, world);
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
        stack.push_back({*child, pending.node, pending.depth + 1, world});
      }
    }
  }

 private:
  struct Pending {
    int node;
    int parent;  // -1 for a scene root
    int depth;   // roots have depth 1
    glm::dmat4 parent_world;
  };

  void check_exists(int node_index) const {
    const size_t count = context_.model.nodes.size();
    if (node_index < 0 || static_cast<size_t>(node_index) >= count) {
      throw_error(context_, "node " + std::to_string(node_index) +
                                " does not exist (the file has " + std::to_string(count) +
                                " nodes)");
    }
  }

  // glTF 2.0 3.5.2: "each node MUST have at most one parent". Without this a node listed twice
  // per level multiplies the paths (40 levels: 2^40 instances).
  void record_single_parents() {
    const auto& nodes = context_.model.nodes;
    for (size_t n = 0; n < nodes.size(); ++n) {
      for (int child : nodes[n].children) {
        check_exists(child);
        int& parent = parent_[static_cast<size_t>(child)];
        if (parent == static_cast<int>(n)) {
          throw_error(context_, "node " + std::to_string(child) + " is listed twice among the "
                                "children of node " + std::to_string(n) +
                                " (glTF 2.0 3.5.2: a node has at most one parent)");
        }
        if (parent >= 0) {
          throw_error(context_, "node " + std::to_string(child) + " is a child of both node " +
                                    std::to_string(parent) + " and node " + std::to_string(n) +
                                    " (glTF 2.0 3.5.2: a node has at most one parent)");
        }
        parent = static_cast<int>(n);
      }
    }
  }

  [[noreturn]] void reached_twice(const Pending& pending) const {
    // With single parents, meeting a node again means it is its own ancestor, or a scene root
    // that is also listed twice or is some node's child.
    int ancestor = pending.parent;
    for (size_t steps = 0; ancestor >= 0 && steps <= parent_.size(); ++steps) {
      if (ancestor == pending.node) {
        throw_error(context_, "node " + std::to_string(pending.node) +
                                  " is its own ancestor (cycle; glTF 2.0 3.5.2)");
      }
      ancestor = parent_[static_cast<size_t>(ancestor)];
    }
    throw_error(context_, "node " + std::to_string(pending.node) +
                              " is reached twice from the scene's roots (a root listed twice, or "
                              "a root that is also a child; glTF 2.0 3.5.2)");
  }

  void visit(int node_index, const tinygltf::Node& node, const glm::dmat4& world) {
    const auto& model = context_.model;
    if (node.mesh >= 0) add_instance(node_index, node, world);
    if (node.camera >= 0) {
      if (static_cast<size_t>(node.camera) >= model.cameras.size()) {
        throw_error(context_, "node " + std::to_string(node_index) + " refers to camera " +
                                  std::to_string(node.camera) + ", which does not exist");
      }
      check_camera_transform(node_index, node.camera, world);
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
  }

  // A camera needs a viewing frame: a zero scale or collapsed axes leave no direction to look
  // down (the image would be blank), so the file is refused rather than drawn.
  void check_camera_transform(int node_index, int camera_index, const glm::dmat4& world) const {
    const double determinant = glm::determinant(glm::dmat3(world));
    if (!all_finite(world) || !std::isfinite(determinant) || determinant == 0.0 ||
        !all_finite(rigid_camera_frame(world))) {
      throw_error(context_, "node " + std::to_string(node_index) + " (camera " +
                                std::to_string(camera_index) +
                                ") has a degenerate transform (zero scale, collapsed axes or "
                                "non-finite values; determinant " +
                                std::to_string(determinant) + "), so the camera has no view");
    }
  }

  void add_instance(int node_index, const tinygltf::Node& node, const glm::dmat4& world) {
    if (static_cast<size_t>(node.mesh) >= scene_.meshes.size()) {
      throw_error(context_, "node " + std::to_string(node_index) + " refers to mesh " +
                                std::to_string(node.mesh) + ", which does not exist");
    }
    const uint64_t max_instances = context_.options.limits.max_instances;
    if (scene_.instances.size() >= max_instances) {
      throw_error(context_, "node " + std::to_string(node_index) + " would be mesh instance " +
                                std::to_string(scene_.instances.size() + 1) + ", more than " +
                                std::to_string(max_instances) + " (GltfLimits::max_instances)");
    }
    MeshInstance instance;
    instance.mesh = node.mesh;
    instance.node_name = node.name;
    // A skinned mesh ignores its node's transform (spec 3.7.3); without animation ontile draws
    // it in its bind pose, which is the mesh's own coordinates.
    instance.world = node.skin >= 0 ? glm::dmat4(1.0) : world;
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
  std::vector<int> parent_;    // -1: no parent
  std::vector<bool> visited_;
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

}  // namespace

Scene load_gltf(const std::filesystem::path& path, const GltfLoadOptions& options,
                GltfLoadStats* stats) {
  GltfLoadStats local_stats;
  GltfLoadStats& out_stats = stats ? *stats : local_stats;
  out_stats = GltfLoadStats{};
  const std::string label = path.string();
  const tinygltf::Model model = gltf::read_model(path, label, options, out_stats);
  uint64_t decoded_geometry_bytes = 0;
  const LoadContext context{model, label, options, out_stats, decoded_geometry_bytes};

  Scene scene;
  scene.source_path = label;
  for (size_t m = 0; m < model.meshes.size(); ++m) {
    scene.meshes.push_back(gltf::convert_mesh(context, static_cast<int>(m)));
  }
  scene.materials = gltf::convert_materials(context);
  SceneFlattener(context, scene).flatten(root_nodes(context));
  return scene;
}

}  // namespace ontile
