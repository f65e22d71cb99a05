// `ontile sweep`: time against error. Renders a 64-spp ray-traced reference once, then the
// lambert pipeline at every sweep setting (MSAA, subpixel precision, depth format and reversed
// Z, normal storage, texture filtering), and writes the measurements as CSV and a plot (SVG).

#include <cstdio>
#include <filesystem>

#include "analysis/sweep_csv.h"
#include "analysis/sweep_plot.h"
#include "commands.h"
#include "reference/reference_renderer.h"
#include "scene/gltf_loader.h"
#include "util/error.h"
#include "util/heap_tuning.h"

namespace ontile::cli {
namespace {

struct SweepOptions {
  std::string scene, csv, plot, size = "640x360";
  bool allow_outside_files = false, progress = false;
  int camera = -1, frames = 5, threads = 0, spp = 64;
};

void require_extension(const std::string& path, const char* option, const char* extension) {
  if (std::filesystem::path(path).extension() != extension) {
    throw UsageError(std::string(option) + " " + path + ": needs a " + extension + " file");
  }
}

void print_row(std::FILE* out, const SweepRow& r) {
  std::fprintf(out, "%-24s %8.2f ms (cpu %8.2f) %9llu B  PSNR %7.3f dB  mean %.4f  max %3d", r.setting.name.c_str(),
               r.time_ms_median, r.cpu_ms_median, static_cast<unsigned long long>(r.bytes_per_frame()), r.color.psnr_db,
               r.color.mean_abs, r.color.max_abs);
  if (r.id_mismatch_vs_default) std::fprintf(out, "  ids vs default %.4f%%", 100.0 * *r.id_mismatch_vs_default);
  if (r.normal) std::fprintf(out, "  normal mean %.4f max %.4f deg", r.normal->mean_deg, r.normal->max_deg);
  if (r.normal_storage) {
    std::fprintf(out, " (storage mean %.5f max %.5f)", r.normal_storage->mean_deg, r.normal_storage->max_deg);
  }
  std::fprintf(out, "\n");
  std::fflush(out);
}

void run_sweep_command(const SweepOptions& o) {
  SweepConfig config;
  parse_size(o.size, config.width_px, config.height_px);
  config.camera_index = o.camera;
  config.frames = o.frames;
  Progress progress("sweep", o.progress);
  config.steps = progress.callback();
  config.threads = o.threads;
  config.reference_spp = o.spp;
  try {
    check_samples_per_pixel(o.spp);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
  if (!is_stdout(o.csv)) require_extension(o.csv, "--csv", ".csv");
  require_extension(o.plot, "--plot", ".svg");
  check_output_option("--csv", o.csv, true);
  check_output_option("--plot", o.plot, false);
  check_distinct_outputs({{"--csv", o.csv}, {"--plot", o.plot}});
  // With --csv -, standard output is the CSV alone; the progress goes to standard error.
  std::FILE* summary = summary_stream(is_stdout(o.csv));
  keep_freed_memory_in_the_heap();
  const Scene scene = load_scene(o.scene, o.allow_outside_files);
  std::fprintf(summary, "%s: %dx%d, %d frames per setting, reference %d spp\n", o.scene.c_str(), config.width_px,
               config.height_px, config.frames, config.reference_spp);
  const SweepResult result =
      run_sweep(scene, config, sweep_settings(), [summary](const SweepRow& r) { print_row(summary, r); });
  std::fprintf(summary, "reference: %.0f ms\nPareto front (time, mean error):", result.reference_ms);
  for (const SweepRow& r : result.rows) {
    if (r.pareto_time) std::fprintf(summary, " %s", r.setting.name.c_str());
  }
  std::fprintf(summary, "\nPareto front (bytes, mean error):");
  for (const SweepRow& r : result.rows) {
    if (r.pareto_bytes) std::fprintf(summary, " %s", r.setting.name.c_str());
  }
  std::fprintf(summary, "\n");

  RunOutputs outputs;
  outputs.text(o.csv, sweep_csv(result));
  outputs.text(o.plot, scatter_chart_svg(sweep_plot_spec(result, std::filesystem::path(o.scene).filename().string())));
  outputs.commit();
  std::fprintf(summary, "wrote %s and %s\n", o.csv.c_str(), o.plot.c_str());
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("sweep", "Time against error: lambert settings vs a ray-traced reference (CSV + plot)");
  auto o = std::make_shared<SweepOptions>();
  add_scene_options(cmd, o->scene, o->allow_outside_files, "glTF scene (.gltf or .glb)");
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT, each side 1..16384 (default 640x360)");
  cmd->add_option("--camera", o->camera, "Camera index in the scene (default: first camera, or a framing camera)")
      ->check(CLI::Range(0, 1 << 20));
  cmd->add_option("--frames", o->frames, "Timed frames per setting; the median is reported (default 5)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--threads", o->threads, "Rasterizer worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_option("--spp", o->spp, "Reference samples per pixel, a perfect square (default 64)");
  cmd->add_option("--csv", o->csv, "Write the measurements here (.csv, or - for standard output)")->required();
  cmd->add_option("--plot", o->plot, "Write the error-vs-time plot here (.svg)")->required();
  add_progress_flag(cmd, o->progress);
  cmd->callback([o] { run_sweep_command(*o); });
}

}  // namespace ontile::cli
