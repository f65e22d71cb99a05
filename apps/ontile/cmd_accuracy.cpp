// `ontile accuracy`: renders a scene with the rasterizer (lambert image + AOVs) and with the
// ray-traced reference, and prints (optionally writes as JSON) how far they agree.
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "reference/accuracy_run.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile::cli {
namespace {

struct AccuracyOptions {
  std::string scene, json, size = "1280x720", pipeline = "lambert";
  bool allow_outside_files = false, progress = false;
  int camera = -1, threads = 0;
};

void run_accuracy(const AccuracyOptions& o) {
  RenderSettings settings;
  parse_size(o.size, settings.width_px, settings.height_px);
  settings.pipeline = o.pipeline;
  settings.camera_index = o.camera;
  settings.context.threads = o.threads;
  if (o.pipeline != "lambert") {
    throw UsageError("--pipeline '" + o.pipeline + "': accuracy has a reference only for 'lambert'");
  }
  if (!o.json.empty()) check_output_option("--json", o.json, true);
  const Scene scene = load_scene(o.scene, o.allow_outside_files);
  Progress progress("accuracy", o.progress);
  const AccuracyRun run = measure_accuracy(scene, settings, progress.callback());
  RunOutputs outputs;
  if (!o.json.empty()) {
    nlohmann::json j = accuracy_json(run.metrics);
    j["scene"] = o.scene;
    j["pipeline"] = o.pipeline;
    outputs.text(o.json, j.dump(2) + "\n");
  }
  outputs.commit();
  std::FILE* summary = summary_stream(is_stdout(o.json));
  std::fprintf(summary, "%s: %dx%d, pipeline %s vs ray-traced reference\n%s", o.scene.c_str(), settings.width_px,
               settings.height_px, o.pipeline.c_str(), accuracy_text(run.metrics).c_str());
  if (!o.json.empty()) std::fprintf(summary, "wrote %s\n", o.json.c_str());
}

}  // namespace

void add_accuracy_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("accuracy", "Compare the rasterizer with the ray-traced reference");
  auto o = std::make_shared<AccuracyOptions>();
  add_scene_options(cmd, o->scene, o->allow_outside_files, "glTF scene (.gltf or .glb)");
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT, each side 1..16384 (default 1280x720)");
  cmd->add_option("--camera", o->camera, "Camera index in the scene (default: first camera, or a framing camera)")
      ->check(CLI::Range(0, 1 << 20));
  cmd->add_option("--pipeline", o->pipeline, "Pipeline to check (only lambert has a reference)");
  cmd->add_option("--threads", o->threads, "Rasterizer worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_option("--json", o->json, "Write the metrics as JSON here (- for standard output)");
  add_progress_flag(cmd, o->progress);
  cmd->callback([o] { run_accuracy(*o); });
}

}  // namespace ontile::cli
