// libFuzzer target: `ontile render --pipeline NAME --set KEY=VALUE ...`. The input is text:
// the first line names the pipeline, every further line is one --set argument. Each argument
// is split at its first '=' exactly as apps/ontile/cmd_render.cpp does, the pipeline parses
// the options and renders a small frame of the generated demo scene on one thread, so option
// combinations reach the passes they configure. An ontile::Error is the expected outcome for
// a bad option; anything else is a finding (scripts/fuzz_smoke.sh, docs/robustness.md).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_scratch.h"
#include "pipelines/kit/render_frame.h"
#include "scene/gen/scene_generator.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace {

const ontile::Scene& demo_scene() {
  static const ontile::Scene scene = [] {
    const std::filesystem::path path = ontile::fuzz::scratch_folder() / "demo.glb";
    ontile::generate_scene("demo", {}, path);
    return ontile::load_gltf(path);
  }();
  return scene;
}

// The CLI's --set rule: KEY=VALUE with a non-empty key; the value may be empty or hold '='.
void set_option(ontile::PipelineOptions& options, const std::string& argument) {
  const size_t eq = argument.find('=');
  if (eq == std::string::npos || eq == 0) throw ontile::Error("--set '" + argument + "': expected KEY=VALUE");
  options.set(argument.substr(0, eq), argument.substr(eq + 1));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  ontile::RenderSettings settings;
  // Small for many frames a second, yet six 16x16 tiles (the CLI's default tile size).
  settings.width_px = 40;
  settings.height_px = 24;
  settings.context.threads = 1;
  size_t line_start = 0;
  bool first_line = true;
  try {
    while (line_start <= text.size()) {
      size_t line_end = text.find('\n', line_start);
      if (line_end == std::string::npos) line_end = text.size();
      const std::string line = text.substr(line_start, line_end - line_start);
      if (first_line) {
        settings.pipeline = line;
        first_line = false;
      } else if (!line.empty()) {
        set_option(settings.options, line);
      }
      line_start = line_end + 1;
    }
    const ontile::RenderedFrame frame = ontile::render_frame(demo_scene(), settings);
    if (frame.outputs.color == nullptr) __builtin_trap();  // every pipeline returns an image
  } catch (const ontile::Error&) {
    // A rejected option or pipeline: the contract for bad input.
  }
  return 0;
}
