// A generated scene (scene/gen) loaded as tests load files: written to a temporary .glb, loaded,
// and the file removed, so the test exercises the same loader path as the CLI.
#pragma once
#include <filesystem>
#include <string>
#include <unistd.h>

#include "scene/gen/scene_generator.h"
#include "scene/gltf_loader.h"

namespace ontile::test {

inline Scene generated_scene(const std::string& name, double size) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("ontile_generated_" + name + "_" + std::to_string(getpid()) + ".glb");
  SceneGenOptions options;
  options.size = size;
  generate_scene(name, options, path);
  Scene scene = load_gltf(path);
  std::filesystem::remove(path);
  return scene;
}

}  // namespace ontile::test
