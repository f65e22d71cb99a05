// The generators' scene description (meshes, materials, images, nodes, camera, lights) and
// its conversion to a binary glTF 2.0 (.glb) file with textures embedded as PNG.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "scene/gen/mesh_builder.h"
#include "scene/gen/procedural_textures.h"

namespace ontile::gen {

struct GenImage {
  std::string name;
  RgbImage pixels;  // stored as PNG in the binary chunk, sampled with repeat wrapping
};

struct GenMaterial {
  std::string name;
  glm::vec4 base_color_factor{1.0f};
  float metallic_factor = 0.0f;
  float roughness_factor = 0.8f;
  int base_color_image = -1;  // index into GeneratedScene::images, -1: none
  bool double_sided = false;
  nlohmann::json extras;      // the material's glTF "extras"; null: none
};

struct GenPrimitive {
  MeshData geometry;  // tangents are computed on write when empty
  int material = -1;
};

struct GenMesh {
  std::string name;
  std::vector<GenPrimitive> primitives;
};

struct GenCamera {
  std::string name;
  float yfov_rad = 0.8f;
  float aspect_ratio = 16.0f / 9.0f;
  float znear_m = 0.1f;
  float zfar_m = 100.0f;
};

// KHR_lights_punctual; intensity in lux (directional) or candela (point).
struct GenLight {
  enum class Type { Directional, Point };
  std::string name;
  Type type = Type::Directional;
  glm::vec3 colour{1.0f};
  float intensity = 1.0f;
  float range_m = 0.0f;  // 0: infinite (omitted from the file)
};

// A root node of the default scene: at most one of mesh, camera, light.
struct GenNode {
  std::string name;
  int mesh = -1, camera = -1, light = -1;
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // (w, x, y, z): identity
};

struct GeneratedScene {
  std::vector<GenImage> images;
  std::vector<GenMaterial> materials;
  std::vector<GenMesh> meshes;
  std::vector<GenCamera> cameras;
  std::vector<GenLight> lights;
  std::vector<GenNode> nodes;
};

// Rotation that turns a node's local -Z (the way glTF cameras and lights point) towards
// direction, keeping local +Y as close to world up as possible.
glm::quat rotation_looking_along(const glm::vec3& direction, const glm::vec3& up = {0, 1, 0});

// Fills empty tangent streams (compute_tangents), then writes scene as a .glb at out_glb
// atomically (temporary file + rename). Vertex streams are
// tightly packed float32, indices uint16 when the primitive has at most 65535 vertices (glTF
// 2.0 3.7.2.1 reserves the maximum index value) and uint32 otherwise.
void write_glb(GeneratedScene& scene, const std::filesystem::path& out_glb);

}  // namespace ontile::gen
