// `ontile gen-scene NAME --out FILE.glb [--size S]`: writes a generated scene.
#include <cstdio>
#include <filesystem>
#include <optional>

#include "commands.h"
#include "scene/gen/scene_generator.h"

namespace ontile::cli {
namespace {

// The generators whose output depends on SceneGenOptions::size (scene_generator.h); --size for
// any other is refused rather than silently ignored.
bool scene_takes_size(const std::string& name) { return name == "atrium"; }

std::string names_of_generators() {
  std::string names;
  for (const auto& n : scene_generator_names()) names += (names.empty() ? "" : ", ") + n;
  return names;
}

}  // namespace

void add_gen_scene_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("gen-scene", "Write a generated scene as .glb (deterministic)");
  struct Options {
    std::string name, out;
    std::optional<double> size;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("name", opt->name, "Scene to generate: " + names_of_generators())->required();
  cmd->add_option("--out", opt->out, "Output .glb file (its folder must exist)")->required();
  cmd->add_option("--size", opt->size, "Size multiplier, atrium only (1.0 is about 250k triangles; 0.05..64)");
  cmd->callback([opt] {
    bool known = false;
    for (const auto& n : scene_generator_names()) known |= n == opt->name;
    if (!known) throw UsageError("gen-scene: unknown scene '" + opt->name + "' (valid: " + names_of_generators() + ")");
    if (opt->size && !scene_takes_size(opt->name)) {
      throw UsageError("--size: scene '" + opt->name + "' has no size (only atrium takes --size)");
    }
    if (std::filesystem::path(opt->out).extension() != ".glb") {
      throw UsageError("--out " + opt->out + ": gen-scene writes .glb files");
    }
    check_output_option("--out", opt->out, false);
    SceneGenOptions options;
    options.size = opt->size.value_or(1.0);
    generate_scene(opt->name, options, opt->out);
    if (scene_takes_size(opt->name)) {
      std::printf("wrote %s (%s, size %.3g)\n", opt->out.c_str(), opt->name.c_str(), options.size);
    } else {
      std::printf("wrote %s (%s)\n", opt->out.c_str(), opt->name.c_str());
    }
  });
}

}  // namespace ontile::cli
