// The in-memory scene every pipeline draws: meshes, materials, textures, flattened node
// instances, cameras and punctual lights. Loaded from glTF (gltf_loader.h) or generated.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "raster/texture.h"

namespace ontile {

struct Bounds {
  glm::vec3 min{1e30f};
  glm::vec3 max{-1e30f};
  bool empty() const { return min.x > max.x; }
  void extend(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
  void extend(const Bounds& b) { if (!b.empty()) { extend(b.min); extend(b.max); } }
  glm::vec3 center() const { return (min + max) * 0.5f; }
};

// One indexed triangle list (glTF primitive, mode TRIANGLES) with per-vertex attribute streams.
// Strips and fans are converted to lists at load time. Every stream that is present has one
// entry per vertex; absent optional streams are empty.
struct MeshPrimitive {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;    // generated (flat, per face) when the file has none
  std::vector<glm::vec4> tangents;   // xyz tangent, w handedness; may be empty
  std::vector<glm::vec2> uv0;        // may be empty
  std::vector<glm::vec4> colors;     // COLOR_0 as linear RGBA; may be empty
  std::vector<uint32_t> indices;     // always present: 3 per triangle (generated if unindexed)
  int material = -1;                 // index into Scene::materials, -1 = default material
  Bounds bounds;                     // object space
  uint32_t triangle_count() const { return static_cast<uint32_t>(indices.size() / 3); }
};

struct Mesh {
  std::string name;
  std::vector<MeshPrimitive> primitives;
};

// A texture slot of a material: an image with a sampler. The colour space is decided by the
// slot (base colour and emissive are sRGB, the rest linear), so the same image may appear as two
// Texture2D objects.
struct TextureSlot {
  std::shared_ptr<const Texture2D> texture;  // null: slot unused
  SamplerDesc sampler;
  int uv_set = 0;
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
  std::string name;
  glm::vec4 base_color_factor{1.0f};
  TextureSlot base_color_texture;
  float metallic_factor = 1.0f;
  float roughness_factor = 1.0f;
  TextureSlot metallic_roughness_texture;
  TextureSlot normal_texture;
  float normal_scale = 1.0f;
  glm::vec3 emissive_factor{0.0f};
  TextureSlot emissive_texture;
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  bool double_sided = false;
  // The material's "extras" object as JSON text ("" when absent); pipelines read their
  // per-material settings from it (documented key "ontile").
  std::string extras_json;
};

// A mesh placed in the world by the default scene's node tree (hierarchy flattened).
// Transforms are double: composed from the file's values without a float rounding, so a node
// 1e6 units from the origin keeps its position to ~1e-10 units instead of float's 1/16 unit;
// renderers fold them into a camera-relative model-view-projection before going to float
// (docs/stability.md, "Far from the origin through glTF").
struct MeshInstance {
  int mesh = -1;
  glm::dmat4 world{1.0};  // object-to-world
  std::string node_name;
  Bounds world_bounds;  // float: a culling and framing aid, not used to place vertices
};

struct Camera {
  enum class Type { Perspective, Orthographic } type = Type::Perspective;
  std::string name;
  float yfov_rad = 0.8f;       // perspective
  float aspect_ratio = 0.0f;   // 0: use the image's aspect ratio
  float xmag = 1.0f, ymag = 1.0f;  // orthographic half extents
  float znear = 0.1f;
  float zfar = 0.0f;           // 0: infinite (perspective only)
  glm::dmat4 world{1.0};       // camera-to-world (rigid); looks down its local -Z, +Y up
};

// KHR_lights_punctual.
struct Light {
  enum class Type { Directional, Point, Spot } type = Type::Directional;
  std::string name;
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  float range = 0.0f;  // 0: infinite
  float inner_cone_rad = 0.0f, outer_cone_rad = 0.7853982f;
  glm::vec3 position{0.0f};    // world space
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // world space, the way the light travels
};

struct Scene {
  std::string source_path;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<MeshInstance> instances;
  std::vector<Camera> cameras;  // in node order of the default scene
  std::vector<Light> lights;
  Bounds world_bounds;

  uint64_t drawn_triangle_count() const;
};

// A camera that frames the scene's bounds from the front (+Z side, looking down -Z, slightly
// above), used when the file has no camera.
Camera default_camera(const Scene& scene);

}  // namespace ontile
