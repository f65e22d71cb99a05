// The "atrium" scene: a Sponza-like open courtyard (long axis x) with two storeys of round-arch
// arcades on the long sides, an upper gallery with balustrades, hanging striped cloths, vases,
// a camera at eye height looking down the long axis, a sun and four torch-like point lights.
// Tessellation counts scale with sqrt(size) in both directions of every curved surface, so the
// triangle count (~250k at size 1) grows linearly with size.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/gen/architecture_shapes.h"
#include "scene/gen/atrium_parts.h"
#include "scene/gen/scene_builders.h"

namespace ontile::gen {
namespace {

// Plan (metres): courtyard and aisles span x in [-14, 14]; arcades stand on z = +-5.3, the
// outer walls' inner faces on z = +-9.
constexpr float kHalfLength = 14.0f;
constexpr float kBayWidth = 4.0f;
constexpr int kBays = 7;
constexpr float kArcadeZ = 5.3f;
constexpr float kOuterWallZ = 9.0f;
constexpr float kArcadeThickness = 0.6f;

// Elevation (metres).
constexpr float kLowerColumnHeight = 4.0f;   // springing line of the lower arches
constexpr float kLowerArchHeight = 2.0f;     // arch panel, up to the gallery floor
constexpr float kGalleryFloorThickness = 0.3f;  // slab resting on the lower arches' tops
constexpr float kGalleryFloorTop = kLowerColumnHeight + kLowerArchHeight + kGalleryFloorThickness;
constexpr float kUpperScale = 0.85f;         // upper order is slimmer
constexpr float kUpperColumnHeight = 3.2f;   // springing at 9.5
constexpr float kUpperArchHeight = 1.8f;
constexpr float kCorniceHeight = 0.5f;
constexpr float kCorniceOverhang = 0.3f;
constexpr float kArchRadius = 1.6f;

constexpr float kClothTopY = 9.2f;
constexpr float kClothZ = 4.72f;  // hanging plane, 0.28 m in front of the arcade face (z = 5.0)

enum : int { kFloor, kBricks, kStone, kMarble, kFabricRed, kFabricGreen, kFabricBlue, kTerracotta };

void add_textured_material(GeneratedScene& scene, const char* name, RgbImage pixels,
                           float roughness, bool double_sided) {
  scene.images.push_back({name, std::move(pixels)});
  GenMaterial material;
  material.name = name;
  material.base_color_image = static_cast<int>(scene.images.size()) - 1;
  material.roughness_factor = roughness;
  material.double_sided = double_sided;
  scene.materials.push_back(std::move(material));
}

int add_mesh(GeneratedScene& scene, const std::string& name,
             std::vector<GenPrimitive> primitives) {
  scene.meshes.push_back({name, std::move(primitives)});
  return static_cast<int>(scene.meshes.size()) - 1;
}

void add_node(GeneratedScene& scene, const std::string& name, int mesh,
              const glm::vec3& translation, const glm::quat& rotation = glm::quat(1, 0, 0, 0)) {
  GenNode node;
  node.name = name;
  node.mesh = mesh;
  node.translation = translation;
  node.rotation = rotation;
  scene.nodes.push_back(node);
}

// Floor, the four walls' inner faces, gallery floor slabs and the roof rim (cornice).
void add_shell(GeneratedScene& scene, double detail) {
  const float cells = static_cast<float>(detail);  // cells per metre on flat surfaces
  const float wall_top = kGalleryFloorTop + kUpperColumnHeight + kUpperArchHeight + kCorniceHeight;
  const float width = 2.0f * kOuterWallZ, length = 2.0f * kHalfLength;
  const auto cells_along = [&](float metres) {
    return std::max(1, static_cast<int>(std::ceil(metres * cells)));
  };
  MeshData floor;
  add_quad(floor, {-kHalfLength, 0.0f, kOuterWallZ}, {length, 0.0f, 0.0f}, {0.0f, 0.0f, -width},
           cells_along(length), cells_along(width), 2.0f);
  MeshData walls;
  const glm::vec3 up(0.0f, wall_top, 0.0f);
  add_quad(walls, {kHalfLength, 0.0f, kOuterWallZ}, {-length, 0.0f, 0.0f}, up,
           cells_along(length), cells_along(wall_top), 2.0f);
  add_quad(walls, {-kHalfLength, 0.0f, -kOuterWallZ}, {length, 0.0f, 0.0f}, up,
           cells_along(length), cells_along(wall_top), 2.0f);
  add_quad(walls, {kHalfLength, 0.0f, -kOuterWallZ}, {0.0f, 0.0f, width}, up,
           cells_along(width), cells_along(wall_top), 2.0f);
  add_quad(walls, {-kHalfLength, 0.0f, kOuterWallZ}, {0.0f, 0.0f, -width}, up,
           cells_along(width), cells_along(wall_top), 2.0f);
  MeshData stone;
  const float slab_front = kArcadeZ - kArcadeThickness * 0.5f;
  const float cornice_bottom = wall_top - kCorniceHeight;
  for (const float side : {1.0f, -1.0f}) {
    // Mirrored boxes keep only the faces that look into the courtyard or up/down.
    const unsigned front = side > 0 ? kBoxNegZ : kBoxPosZ;
    const auto z_range = [&](float inner, float outer) {
      return std::pair(std::min(side * inner, side * outer), std::max(side * inner, side * outer));
    };
    const auto [slab_z0, slab_z1] = z_range(slab_front, kOuterWallZ);
    add_box(stone, {-kHalfLength, kGalleryFloorTop - kGalleryFloorThickness, slab_z0},
            {kHalfLength, kGalleryFloorTop, slab_z1}, cells, 2.0f, kBoxNegY | kBoxPosY | front);
    const auto [rim_z0, rim_z1] = z_range(slab_front - kCorniceOverhang, kOuterWallZ);
    add_box(stone, {-kHalfLength, cornice_bottom, rim_z0}, {kHalfLength, wall_top, rim_z1}, cells,
            2.0f, kBoxNegY | kBoxPosY | front);
    const float x_inner = side * (kHalfLength - kCorniceOverhang);
    add_box(stone, {std::min(x_inner, side * kHalfLength), cornice_bottom, -slab_front},
            {std::max(x_inner, side * kHalfLength), wall_top, slab_front}, cells, 2.0f,
            kBoxNegY | kBoxPosY | (side > 0 ? kBoxNegX : kBoxPosX));
  }
  add_node(scene, "floor", add_mesh(scene, "floor", {{std::move(floor), kFloor}}), glm::vec3(0.0f));
  add_node(scene, "walls", add_mesh(scene, "walls", {{std::move(walls), kBricks}}), glm::vec3(0.0f));
  add_node(scene, "gallery_slabs_and_cornice",
           add_mesh(scene, "gallery_slabs_and_cornice", {{std::move(stone), kStone}}),
           glm::vec3(0.0f));
}

// Both storeys of both arcades: columns, arches, the upper balustrades and the cloths.
void add_arcades(GeneratedScene& scene, double detail) {
  const float lower_shaft = kLowerColumnHeight - column_height_m(0.0f, 1.0f);
  const float upper_shaft = kUpperColumnHeight - column_height_m(0.0f, kUpperScale);
  const int lower_column = add_mesh(
      scene, "column_lower", {{column_mesh(lower_shaft, 1.0f, detail), kMarble}});
  const int upper_column = add_mesh(
      scene, "column_upper", {{column_mesh(upper_shaft, kUpperScale, detail), kMarble}});
  const auto arch = [&](const char* name, float height) {
    ArchPanelShape shape;
    shape.span_m = kBayWidth;
    shape.inner_radius_m = kArchRadius;
    shape.height_m = height;
    shape.thickness_m = kArcadeThickness;
    shape.arc_segments = scaled_segments(48, detail, 8);
    shape.radial_segments = scaled_segments(6, detail, 1);
    shape.depth_segments = scaled_segments(4, detail, 1);
    MeshData faces, soffit;
    add_arch_panel(faces, soffit, shape);
    return add_mesh(scene, name, {{std::move(faces), kStone}, {std::move(soffit), kMarble}});
  };
  const int lower_arch = arch("arch_lower", kLowerArchHeight);
  const int upper_arch = arch("arch_upper", kUpperArchHeight);
  const float balustrade_width = kBayWidth - 2.0f * 0.45f * kUpperScale;
  const int balustrade = add_mesh(
      scene, "balustrade_bay", {{balustrade_bay_mesh(balustrade_width, detail), kMarble}});
  struct ClothVariant {
    const char* name;
    int material, folds;
    float phase_rad;
  };
  const ClothVariant variants[] = {{"cloth_red", kFabricRed, 5, 0.0f},
                                   {"cloth_green", kFabricGreen, 6, 1.3f},
                                   {"cloth_blue", kFabricBlue, 4, 2.1f}};
  int cloth_meshes[3];
  for (int i = 0; i < 3; ++i) {
    ClothShape shape;
    shape.width_m = 3.0f;
    shape.drop_m = 4.0f;
    shape.fold_count = variants[i].folds;
    shape.fold_phase_rad = variants[i].phase_rad;
    shape.billow_m = 0.2f;
    shape.cols = scaled_segments(56, detail, 4);
    shape.rows = scaled_segments(46, detail, 4);
    MeshData cloth;
    add_cloth(cloth, shape);
    cloth_meshes[i] = add_mesh(scene, variants[i].name, {{std::move(cloth), variants[i].material}});
  }

  const float upper_floor = kGalleryFloorTop;
  const float upper_springing = upper_floor + kUpperColumnHeight;
  for (const float side : {1.0f, -1.0f}) {
    const std::string side_name = side > 0 ? "north" : "south";
    const float z = side * kArcadeZ;
    for (int i = 0; i <= kBays; ++i) {
      const float x = -kHalfLength + kBayWidth * static_cast<float>(i);
      const std::string index = std::to_string(i);
      add_node(scene, "column_lower_" + side_name + "_" + index, lower_column, {x, 0.0f, z});
      add_node(scene, "column_upper_" + side_name + "_" + index, upper_column, {x, upper_floor, z});
    }
    // Cloths face the courtyard: local -z is their front, so the north side (z > 0) keeps
    // the identity and the south side turns half way round.
    const glm::quat facing = side > 0 ? glm::quat(1, 0, 0, 0) : glm::quat(0, 0, 1, 0);
    for (int bay = 0; bay < kBays; ++bay) {
      const float x = -kHalfLength + kBayWidth * (static_cast<float>(bay) + 0.5f);
      const std::string index = std::to_string(bay);
      add_node(scene, "arch_lower_" + side_name + "_" + index, lower_arch,
               {x, kLowerColumnHeight, z});
      add_node(scene, "arch_upper_" + side_name + "_" + index, upper_arch, {x, upper_springing, z});
      add_node(scene, "balustrade_" + side_name + "_" + index, balustrade, {x, upper_floor, z});
      const int variant = (bay + (side > 0 ? 0 : 1)) % 3;
      add_node(scene, "cloth_" + side_name + "_" + index, cloth_meshes[variant],
               {x, kClothTopY, side * kClothZ}, facing);
    }
  }
}

void add_vases(GeneratedScene& scene, double detail) {
  const int vase = add_mesh(scene, "vase", {{vase_mesh(detail), kTerracotta}});
  int index = 0;
  for (const float x : {-8.0f, 0.0f, 8.0f}) {
    for (const float z : {3.4f, -3.4f}) {
      add_node(scene, "vase_" + std::to_string(index++), vase, {x, 0.0f, z});
    }
  }
}

void add_camera_and_lights(GeneratedScene& scene) {
  // Eye height at one end of the courtyard, looking down the long axis, slightly upwards.
  scene.cameras.push_back({"courtyard_view", glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 100.0f});
  GenNode camera;
  camera.name = "courtyard_view";
  camera.camera = 0;
  camera.translation = glm::vec3(-12.5f, 1.7f, 0.0f);
  camera.rotation = rotation_looking_along(glm::vec3(1.0f, 0.1f, 0.0f));
  scene.nodes.push_back(camera);

  scene.lights.push_back({"sun", GenLight::Type::Directional, {1.0f, 0.95f, 0.85f}, 5.0f, 0.0f});
  GenNode sun;
  sun.name = "sun";
  sun.light = 0;
  sun.translation = glm::vec3(0.0f, 20.0f, 0.0f);
  sun.rotation = rotation_looking_along(glm::vec3(0.3f, -1.0f, 0.45f));
  scene.nodes.push_back(sun);
  int index = 0;
  for (const float x : {-9.0f, 9.0f}) {
    for (const float z : {3.2f, -3.2f}) {
      const std::string name = "torch_" + std::to_string(index);
      scene.lights.push_back({name, GenLight::Type::Point, {1.0f, 0.72f, 0.42f}, 20.0f, 9.0f});
      GenNode light;
      light.name = name;
      light.light = static_cast<int>(scene.lights.size()) - 1;
      light.translation = glm::vec3(x, 2.6f, z);
      scene.nodes.push_back(light);
      ++index;
    }
  }
}

}  // namespace

GeneratedScene build_atrium_scene(double size) {
  const double detail = std::sqrt(size);
  GeneratedScene scene;
  add_textured_material(scene, "floor_tiles", make_floor_tile_texture(512, 11), 0.7f, false);
  add_textured_material(scene, "bricks", make_brick_texture(512, 23), 0.9f, false);
  add_textured_material(scene, "stone", make_ashlar_texture(512, 29), 0.8f, false);
  add_textured_material(scene, "marble", make_marble_texture(512, 37), 0.4f, false);
  add_textured_material(scene, "fabric_red",
                        make_fabric_texture(256, {{0.62f, 0.1f, 0.08f}, {0.9f, 0.75f, 0.3f},
                                                  {0.25f, 0.05f, 0.05f}}, 41),
                        0.95f, true);
  add_textured_material(scene, "fabric_green",
                        make_fabric_texture(256, {{0.12f, 0.42f, 0.2f}, {0.85f, 0.82f, 0.7f},
                                                  {0.05f, 0.2f, 0.1f}}, 43),
                        0.95f, true);
  add_textured_material(scene, "fabric_blue",
                        make_fabric_texture(256, {{0.12f, 0.2f, 0.55f}, {0.9f, 0.75f, 0.3f},
                                                  {0.6f, 0.1f, 0.08f}}, 47),
                        0.95f, true);
  add_textured_material(scene, "terracotta", make_terracotta_texture(256, 53), 0.85f, false);
  add_shell(scene, detail);
  add_arcades(scene, detail);
  add_vases(scene, detail);
  add_camera_and_lights(scene);
  return scene;
}

}  // namespace ontile::gen
