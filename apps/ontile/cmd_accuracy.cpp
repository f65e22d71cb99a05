// `ontile accuracy`: renders a scene with the rasterizer (lambert image + AOVs) and with the
// ray-traced reference, and prints (optionally writes as JSON) how far they agree.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "commands.h"
#include "reference/accuracy_run.h"
#include "scene/gltf_loader.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace ontile::cli {
namespace {

struct AccuracyOptions {
  std::string scene, json, size = "1280x720", pipeline = "lambert";
  int camera = -1, threads = 0;
};

void run_accuracy(const AccuracyOptions& o) {
  RenderSettings settings;
  parse_size(o.size, settings.width_px, settings.height_px);
  settings.pipeline = o.pipeline;
  settings.camera_index = o.camera;
  settings.context.threads = o.threads;
  if (o.pipeline != "lambert") {
    throw Error("--pipeline '" + o.pipeline + "': accuracy has a reference only for 'lambert'");
  }
  const Scene scene = load_gltf(o.scene);
  const AccuracyRun run = measure_accuracy(scene, settings);
  std::printf("%s: %dx%d, pipeline %s vs ray-traced reference\n%s", o.scene.c_str(), settings.width_px,
              settings.height_px, o.pipeline.c_str(), accuracy_text(run.metrics).c_str());
  if (!o.json.empty()) {
    const std::filesystem::path path(o.json);
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    nlohmann::json j = accuracy_json(run.metrics);
    j["scene"] = o.scene;
    j["pipeline"] = o.pipeline;
    const std::string text = j.dump(2) + "\n";
    write_file_atomically(path, [&](const std::filesystem::path& tmp) {
      std::ofstream f(tmp, std::ios::binary);
      f << text;
      if (!f) throw Error(path.string() + ": cannot write");
    });
    std::printf("wrote %s\n", o.json.c_str());
  }
}

}  // namespace

void add_accuracy_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("accuracy", "Compare the rasterizer with the ray-traced reference");
  auto o = std::make_shared<AccuracyOptions>();
  cmd->add_option("--scene", o->scene, "glTF scene (.gltf or .glb)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT (default 1280x720)");
  cmd->add_option("--camera", o->camera, "Camera index in the scene (default: first camera, or a framing camera)")
      ->check(CLI::Range(0, 1 << 20));
  cmd->add_option("--pipeline", o->pipeline, "Pipeline to check (only lambert has a reference)");
  cmd->add_option("--threads", o->threads, "Rasterizer worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_option("--json", o->json, "Write the metrics as JSON here");
  cmd->callback([o] { run_accuracy(*o); });
}

}  // namespace ontile::cli
