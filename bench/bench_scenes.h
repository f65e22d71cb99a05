// Scenes the benchmarks render, loaded once per process: the generated atrium at a given size
// and models from ../shared/assets (null when absent, so the benchmark reports a skip).
#pragma once
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <unistd.h>

#include "scene/gen/scene_generator.h"
#include "scene/gltf_loader.h"

namespace ontile::bench {

inline const Scene* generated_scene(const std::string& name, double size) {
  static std::map<std::pair<std::string, double>, std::unique_ptr<Scene>> cache;
  auto& slot = cache[{name, size}];
  if (!slot) {
    const auto path = std::filesystem::temp_directory_path() /
                      ("ontile_bench_" + name + "_" + std::to_string(getpid()) + ".glb");
    SceneGenOptions options;
    options.size = size;
    generate_scene(name, options, path);
    slot = std::make_unique<Scene>(load_gltf(path));
    std::filesystem::remove(path);
  }
  return slot.get();
}

inline const Scene* file_scene(const std::filesystem::path& path) {
  static std::map<std::string, std::unique_ptr<Scene>> cache;
  auto& slot = cache[path.string()];
  if (!slot && std::filesystem::exists(path)) slot = std::make_unique<Scene>(load_gltf(path));
  return slot.get();
}

inline const Scene* shared_asset(const std::string& relative) {
  return file_scene(std::filesystem::path(ONTILE_SHARED_ASSETS) / relative);
}

}  // namespace ontile::bench
