// `ontile gen-scene NAME --out FILE.glb [--size S]`: writes a generated scene.
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "scene/gen/scene_generator.h"

namespace ontile::cli {

void add_gen_scene_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("gen-scene", "Write a generated scene as .glb (deterministic)");
  struct Options {
    std::string name, out;
    double size = 1.0;
  };
  auto opt = std::make_shared<Options>();
  std::string names;
  for (const auto& n : scene_generator_names()) names += (names.empty() ? "" : ", ") + n;
  cmd->add_option("name", opt->name, "Scene to generate: " + names)->required();
  cmd->add_option("--out", opt->out, "Output .glb file")->required();
  cmd->add_option("--size", opt->size, "Size multiplier (atrium: 1.0 is about 250k triangles)");
  cmd->callback([opt] {
    const std::filesystem::path out(opt->out);
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    SceneGenOptions options;
    options.size = opt->size;
    generate_scene(opt->name, options, out);
    std::printf("wrote %s (%s, size %.3g)\n", opt->out.c_str(), opt->name.c_str(), opt->size);
  });
}

}  // namespace ontile::cli
