// Deterministic procedural test scenes written as .glb (the `ontile gen-scene` verb): "demo", a
// small toon-material showcase, and "atrium", a Sponza-like courtyard whose triangle count
// scales with SceneGenOptions::size. The same name and options always give the same bytes.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace ontile {

struct SceneGenOptions {
  // atrium: triangle budget multiplier (1.0 ~ 250k triangles, linear in size); must be finite
  // and within [0.05, 64]. demo: validated the same way, otherwise unused.
  double size = 1.0;
};

// Valid generator names, sorted.
std::vector<std::string> scene_generator_names();

// Generates scene `name` into out_glb (written atomically). Throws ontile::Error for an
// unknown name (the message lists the valid ones), a size out of range, or a failed write.
void generate_scene(const std::string& name, const SceneGenOptions& options,
                    const std::filesystem::path& out_glb);

}  // namespace ontile
