// The "demo" scene: a small toon showcase (a few thousand triangles) whose materials carry the
// "ontile" extras the toon pipelines read: cel shading with 1, 3 and 6 steps, MatCap (clay,
// metal, painted), toon_env with an outline, and borders with and without alpha.
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/gen/scene_builders.h"

namespace ontile::gen {
namespace {

using Rgb = std::array<double, 3>;
using Rgba = std::array<double, 4>;

constexpr Rgba kNoBorder = {0.0, 0.0, 0.0, 0.0};

nlohmann::json cel_extras(int steps, const Rgb& lit, const Rgb& shadow, const Rgba& border) {
  return {{"ontile",
           {{"shader", "cel"},
            {"steps", steps},
            {"lit_color", lit},
            {"shadow_color", shadow},
            {"border_color", border}}}};
}

nlohmann::json matcap_extras(const char* matcap, const Rgba& border) {
  return {{"ontile", {{"shader", "matcap"}, {"matcap", matcap}, {"border_color", border}}}};
}

nlohmann::json toon_env_extras(double outline_thickness, const Rgba& border) {
  return {{"ontile",
           {{"shader", "toon_env"},
            {"outline_thickness", outline_thickness},
            {"border_color", border}}}};
}

GenMaterial material(const char* name, const Rgb& base, float metallic, float roughness,
                     nlohmann::json extras) {
  GenMaterial m;
  m.name = name;
  m.base_color_factor = glm::vec4(static_cast<float>(base[0]), static_cast<float>(base[1]),
                                  static_cast<float>(base[2]), 1.0f);
  m.metallic_factor = metallic;
  m.roughness_factor = roughness;
  m.extras = std::move(extras);
  return m;
}

// Adds a one-primitive mesh and a node placing it at translation.
void add_object(GeneratedScene& scene, const char* name, MeshData geometry, int material,
                const glm::vec3& translation) {
  GenMesh mesh;
  mesh.name = name;
  mesh.primitives.push_back({std::move(geometry), material});
  scene.meshes.push_back(std::move(mesh));
  GenNode node;
  node.name = name;
  node.mesh = static_cast<int>(scene.meshes.size()) - 1;
  node.translation = translation;
  scene.nodes.push_back(node);
}

glm::mat4 translation(float x, float y, float z) {
  return glm::translate(glm::mat4(1.0f), glm::vec3(x, y, z));
}

// A little figure built from primitives: legs, body, arms, head (body material) and eyes.
GenMesh character_mesh(int body_material, int eye_material) {
  MeshData body, eyes;
  add_cylinder(body, translation(-0.17f, 0.0f, 0.0f), 0.13f, 0.5f, 16, 1);
  add_cylinder(body, translation(0.17f, 0.0f, 0.0f), 0.13f, 0.5f, 16, 1);
  add_capsule(body, translation(0.0f, 0.4f, 0.0f), 0.38f, 1.25f, 24, 6);
  for (const float side : {-1.0f, 1.0f}) {
    // Arms hang from the shoulders, tilted 25 degrees outwards.
    const glm::mat4 arm = glm::rotate(translation(side * 0.4f, 1.45f, 0.0f),
                                      -side * glm::radians(155.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    add_capsule(body, arm, 0.1f, 0.7f, 12, 4);
    add_sphere(eyes, glm::vec3(side * 0.11f, 2.02f, 0.27f), 0.06f, 12, 6);
  }
  add_sphere(body, glm::vec3(0.0f, 1.95f, 0.0f), 0.32f, 24, 12);
  GenMesh mesh;
  mesh.name = "character";
  mesh.primitives.push_back({std::move(body), body_material});
  mesh.primitives.push_back({std::move(eyes), eye_material});
  return mesh;
}

}  // namespace

GeneratedScene build_demo_scene() {
  GeneratedScene scene;
  scene.images.push_back(
      {"ground_checker", make_checker_texture(128, 8, glm::vec3(0.78f, 0.80f, 0.74f),
                                              glm::vec3(0.52f, 0.60f, 0.50f))});

  // Material indices, in the order pushed below.
  enum : int { kGround, kRedCel1, kBlueCel3, kYellowCel6, kClay, kMetal, kPainted, kToonEnv, kEyes };
  GenMaterial ground = material("ground_cel3_checker", {1.0, 1.0, 1.0}, 0.0f, 0.9f,
                                cel_extras(3, {1.0, 1.0, 1.0}, {0.55, 0.58, 0.7}, kNoBorder));
  ground.base_color_image = 0;
  scene.materials.push_back(ground);
  scene.materials.push_back(material("red_cel1", {0.85, 0.18, 0.15}, 0.0f, 0.5f,
                                     cel_extras(1, {0.85, 0.18, 0.15}, {0.45, 0.06, 0.1},
                                                {0.0, 0.0, 0.0, 1.0})));
  scene.materials.push_back(material("blue_cel3", {0.2, 0.4, 0.9}, 0.0f, 0.4f,
                                     cel_extras(3, {0.2, 0.4, 0.9}, {0.08, 0.12, 0.4},
                                                {0.02, 0.05, 0.2, 1.0})));
  scene.materials.push_back(material("yellow_cel6", {0.95, 0.78, 0.2}, 0.0f, 0.35f,
                                     cel_extras(6, {0.95, 0.78, 0.2}, {0.5, 0.3, 0.12},
                                                {0.25, 0.12, 0.0, 1.0})));
  scene.materials.push_back(material("clay_matcap", {0.8, 0.62, 0.5}, 0.0f, 0.8f,
                                     matcap_extras("clay", {0.1, 0.05, 0.02, 1.0})));
  scene.materials.push_back(material("metal_matcap_no_border", {0.75, 0.76, 0.8}, 1.0f, 0.25f,
                                     matcap_extras("metal", kNoBorder)));
  scene.materials.push_back(material("painted_matcap", {0.3, 0.75, 0.45}, 0.0f, 0.3f,
                                     matcap_extras("painted", {0.0, 0.0, 0.0, 1.0})));
  scene.materials.push_back(material("character_toon_env", {0.95, 0.55, 0.3}, 0.0f, 0.6f,
                                     toon_env_extras(0.02, {0.05, 0.05, 0.1, 1.0})));
  scene.materials.push_back(material("eyes_cel1", {0.03, 0.03, 0.05}, 0.0f, 0.2f,
                                     cel_extras(1, {0.03, 0.03, 0.05}, {0.0, 0.0, 0.0},
                                                kNoBorder)));

  MeshData ground_mesh;
  // Large enough that the camera does not see its far edge.
  add_quad(ground_mesh, glm::vec3(-20.0f, 0.0f, 20.0f), glm::vec3(40.0f, 0.0f, 0.0f),
           glm::vec3(0.0f, 0.0f, -40.0f), 10, 10, 4.0f);
  add_object(scene, "ground", std::move(ground_mesh), kGround, glm::vec3(0.0f));

  MeshData sphere_large, sphere_small, torus, capsule, cylinder, sphere_painted;
  add_sphere(sphere_large, glm::vec3(0.0f), 0.8f, 32, 16);
  add_object(scene, "sphere_cel1", std::move(sphere_large), kRedCel1, {-3.0f, 0.8f, 0.0f});
  add_sphere(sphere_small, glm::vec3(0.0f), 0.6f, 24, 12);
  add_object(scene, "sphere_cel3", std::move(sphere_small), kBlueCel3, {-1.2f, 0.6f, 1.3f});
  // Torus standing tilted 70 degrees so both its hole and its rim face the camera.
  add_torus(torus, glm::rotate(glm::mat4(1.0f), glm::radians(70.0f), glm::vec3(1, 0, 0)), 0.7f,
            0.25f, 40, 20);
  add_object(scene, "torus_cel6", std::move(torus), kYellowCel6, {-0.1f, 0.96f, 1.0f});
  add_capsule(capsule, glm::mat4(1.0f), 0.45f, 1.8f, 24, 6);
  add_object(scene, "capsule_matcap_clay", std::move(capsule), kClay, {2.9f, 0.0f, -0.3f});
  add_cylinder(cylinder, glm::mat4(1.0f), 0.5f, 1.2f, 32, 4);
  add_object(scene, "cylinder_matcap_metal", std::move(cylinder), kMetal, {-2.3f, 0.0f, -2.2f});
  add_sphere(sphere_painted, glm::vec3(0.0f), 0.35f, 24, 12);
  add_object(scene, "sphere_matcap_painted", std::move(sphere_painted), kPainted,
             {2.2f, 0.35f, 1.9f});
  scene.meshes.push_back(character_mesh(kToonEnv, kEyes));
  GenNode character;
  character.name = "character_toon_env";
  character.mesh = static_cast<int>(scene.meshes.size()) - 1;
  character.translation = glm::vec3(1.6f, 0.0f, -2.4f);
  scene.nodes.push_back(character);

  // 16:9 camera in front (+Z), above, looking down at the group's centre.
  scene.cameras.push_back({"main_camera", glm::radians(40.0f), 16.0f / 9.0f, 0.1f, 100.0f});
  const glm::vec3 eye(0.0f, 3.2f, 8.5f), target(0.0f, 0.8f, -0.3f);
  GenNode camera;
  camera.name = "main_camera";
  camera.camera = 0;
  camera.translation = eye;
  camera.rotation = rotation_looking_along(target - eye);
  scene.nodes.push_back(camera);

  // Sun from the upper left front (as seen by the camera), plus a warm and a cool fill light.
  scene.lights.push_back({"sun", GenLight::Type::Directional, {1.0f, 0.96f, 0.88f}, 3.0f, 0.0f});
  scene.lights.push_back({"warm_fill", GenLight::Type::Point, {1.0f, 0.8f, 0.6f}, 8.0f, 6.0f});
  scene.lights.push_back({"cool_fill", GenLight::Type::Point, {0.55f, 0.7f, 1.0f}, 6.0f, 5.0f});
  const glm::vec3 light_positions[] = {{-4.0f, 6.0f, 4.0f}, {-2.5f, 2.2f, 2.2f}, {3.0f, 1.8f, -1.2f}};
  for (int i = 0; i < 3; ++i) {
    GenNode light;
    light.name = scene.lights[i].name;
    light.light = i;
    light.translation = light_positions[i];
    if (i == 0) light.rotation = rotation_looking_along(glm::vec3(1.0f, -1.4f, -0.8f));
    scene.nodes.push_back(light);
  }
  return scene;
}

}  // namespace ontile::gen
