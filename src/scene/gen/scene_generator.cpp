// Registry of the procedural scene generators and the generate_scene() entry point.
#include "scene/gen/scene_generator.h"

#include <cmath>
#include <functional>
#include <locale>
#include <sstream>

#include "scene/gen/scene_builders.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr double kMinSize = 0.05, kMaxSize = 64.0;

struct GeneratorEntry {
  const char* name;
  std::function<gen::GeneratedScene(double size)> build;
};

// Kept sorted by name: scene_generator_names() promises sorted output.
const std::vector<GeneratorEntry>& registry() {
  static const std::vector<GeneratorEntry> entries = {
      {"atrium", [](double size) { return gen::build_atrium_scene(size); }},
      {"demo", [](double) { return gen::build_demo_scene(); }},
  };
  return entries;
}

std::string format_number(double value) {
  std::ostringstream text;
  text.imbue(std::locale::classic());
  text << value;
  return text.str();
}

}  // namespace

std::vector<std::string> scene_generator_names() {
  std::vector<std::string> names;
  for (const GeneratorEntry& entry : registry()) names.emplace_back(entry.name);
  return names;
}

void generate_scene(const std::string& name, const SceneGenOptions& options,
                    const std::filesystem::path& out_glb) {
  const GeneratorEntry* found = nullptr;
  for (const GeneratorEntry& entry : registry()) {
    if (name == entry.name) found = &entry;
  }
  if (found == nullptr) {
    std::string valid;
    for (const std::string& known : scene_generator_names()) {
      valid += (valid.empty() ? "" : ", ") + known;
    }
    throw Error(out_glb.string() + ": unknown scene generator '" + name + "' (valid: " + valid +
                ")");
  }
  if (!std::isfinite(options.size) || options.size < kMinSize || options.size > kMaxSize) {
    throw Error(out_glb.string() + ": scene size " + format_number(options.size) +
                " out of range (finite, " + format_number(kMinSize) + " to " +
                format_number(kMaxSize) + ")");
  }
  gen::GeneratedScene scene = found->build(options.size);
  gen::write_glb(scene, out_glb);
}

}  // namespace ontile
