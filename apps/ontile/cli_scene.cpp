// The scene options every verb that loads a glTF file shares (see commands.h).
#include "commands.h"
#include "scene/gltf_loader.h"

namespace ontile::cli {

void add_scene_options(CLI::App* cmd, std::string& scene, bool& allow_outside_files,
                       const std::string& description) {
  cmd->add_option("--scene", scene, description)->required()->check(CLI::ExistingFile);
  cmd->add_flag("--allow-outside-files", allow_outside_files,
                "let the scene's buffer and image URIs name files outside its folder (absolute "
                "paths, '..'); refused by default");
}

Scene load_scene(const std::string& scene, bool allow_outside_files, TextureCompression texture_compression) {
  GltfLoadOptions options;
  options.allow_uris_outside_scene_folder = allow_outside_files;
  options.texture_compression = texture_compression;
  return load_gltf(scene, options);
}

}  // namespace ontile::cli
