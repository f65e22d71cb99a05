// `ontile study deferred`: the deferred-shading bandwidth study (src/studies/deferred_study.h),
// printed as Markdown and optionally written to a file.
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "scene/gltf_loader.h"
#include "studies/architecture_study.h"
#include "studies/deferred_study.h"
#include "tiler/gpu_presets.h"
#include "util/error.h"
#include "util/heap_tuning.h"

namespace ontile::cli {
namespace {

// --markdown and --json of a study verb, checked before any work.
void check_study_outputs(const std::string& markdown, const std::string& json) {
  if (!markdown.empty()) check_output_option("--markdown", markdown, true);
  if (!json.empty()) check_output_option("--json", json, true);
  check_distinct_outputs({{"--markdown", markdown}, {"--json", json}});
}

// The tables go to standard output unless the JSON does; --markdown - asks for nothing more.
void write_study_outputs(const std::string& markdown_path, const std::string& json_path, const std::string& md,
                         const nlohmann::json& json) {
  RunOutputs outputs;
  if (!markdown_path.empty() && !is_stdout(markdown_path)) outputs.text(markdown_path, md);
  if (!json_path.empty()) outputs.text(json_path, json.dump(2) + "\n");
  outputs.commit();
  std::fputs(md.c_str(), is_stdout(json_path) ? stderr : stdout);
}

struct StudyOptions {
  std::string scene, size = "2220x1080", markdown, json, varying_precision = "fp32", texture_compression = "none";
  bool allow_outside_files = false, progress = false;
  StudySettings settings;
};

void run_deferred_study(const StudyOptions& o) {
  StudySettings s = o.settings;
  parse_size(o.size, s.width_px, s.height_px);
  s.varying_precision = o.varying_precision == "fp16" ? VaryingPrecision::Fp16 : VaryingPrecision::Fp32;
  s.texture_compression = o.texture_compression;
  check_study_outputs(o.markdown, o.json);
  const Scene scene = load_scene(o.scene, o.allow_outside_files, *parse_texture_compression(o.texture_compression));
  keep_freed_memory_in_the_heap();  // frame times in the steady state, independent of order
  Progress progress("study", o.progress);
  s.progress = progress.callback();
  const std::vector<StudyRow> rows = run_study(scene, s, deferred_study_variants(s.lights));
  const std::string scene_name = std::filesystem::path(o.scene).filename().string();
  write_study_outputs(o.markdown, o.json, deferred_study_markdown(rows, s, scene_name),
                      deferred_study_json(rows, s, scene_name));
}

struct ArchitectureOptions {
  std::string scene, size = "1920x1080", markdown, json;
  bool allow_outside_files = false, progress = false;
  ArchitectureStudySettings settings;
};

void run_architecture_study_command(const ArchitectureOptions& o) {
  ArchitectureStudySettings s = o.settings;
  parse_size(o.size, s.width_px, s.height_px);
  check_study_outputs(o.markdown, o.json);
  const Scene scene = load_scene(o.scene, o.allow_outside_files);
  Progress progress("study", o.progress);
  s.progress = progress.callback();
  const std::vector<ArchitectureRow> rows = run_architecture_study(scene, s);
  const std::string scene_name = std::filesystem::path(o.scene).filename().string();
  write_study_outputs(o.markdown, o.json, architecture_study_markdown(rows, s, scene_name),
                      architecture_study_json(rows, s, scene_name));
}

void add_architecture_study(CLI::App* study) {
  auto o = std::make_shared<ArchitectureOptions>();
  CLI::App* cmd = study->add_subcommand(
      "architecture", "Tile-based vs immediate mode and tile size, after Antochi et al. 2004 (docs/fidelity.md)");
  add_scene_options(cmd, o->scene, o->allow_outside_files, "glTF scene");
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT, each side 1..16384 (default 1920x1080)");
  cmd->add_option("--tiles", o->settings.tile_sizes_px, "TBDR tile sizes, comma-separated (default 8,16,32,64)")
      ->delimiter(',')
      ->check(CLI::IsMember({4, 8, 16, 32, 64}));
  cmd->add_option("--pipelines", o->settings.pipelines, "Pipelines, comma-separated (default lambert)")->delimiter(',');
  cmd->add_option("--parameter-cache-kib", o->settings.parameter_cache_kib,
                  "Model an L2 for parameter-buffer reads, in KiB (default 0: none)")
      ->check(CLI::Range(0, 65536));
  cmd->add_option("--threads", o->settings.threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  add_progress_flag(cmd, o->progress);
  cmd->add_option("--markdown", o->markdown, "Also write the tables to this file (they are always printed)");
  cmd->add_option("--json", o->json, "Also write the rows and ratios as JSON (- for standard output)");
  cmd->callback([o] { run_architecture_study_command(*o); });
}

}  // namespace

void add_study_command(CLI::App& app) {
  CLI::App* study = app.add_subcommand("study", "Reproducible bandwidth studies of pipeline designs");
  study->require_subcommand(1);
  auto o = std::make_shared<StudyOptions>();
  CLI::App* cmd = study->add_subcommand(
      "deferred", "Classic vs subpass deferred, transient attachments, G-buffer size, MSAA resolve (docs/deferred.md)");
  add_scene_options(cmd, o->scene, o->allow_outside_files, "glTF scene (the docs use the generated atrium)");
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT, each side 1..16384 (default 2220x1080, the sample's device)");
  cmd->add_option("--tile", o->settings.tile_size_px, "Tile size in pixels (default 16)")->check(CLI::IsMember({8, 16, 32}));
  cmd->add_option("--budget", o->settings.color_budget_bits_per_px, "Colour budget in bits per pixel (default 128)")
      ->check(CLI::Range(32, 1024));
  cmd->add_option("--lights", o->settings.lights, "Generated point lights (default 48, as the sample)")->check(CLI::Range(0, 65536));
  cmd->add_option("--frames", o->settings.frames, "Frames per variant; time is their median (default 1)")->check(CLI::Range(1, 100));
  cmd->add_option("--parameter-cache-kib", o->settings.parameter_cache_kib,
                  "Model an L2 for parameter-buffer reads, in KiB (default 0: none)")
      ->check(CLI::Range(0, 65536));
  cmd->add_option("--threads", o->settings.threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_option("--gpu", o->settings.gpu,
                  "GPU preset instead of --tile/--budget/--parameter-cache-kib (see `ontile render --help`); with "
                  "transaction elimination each variant renders a first frame the row does not count")
      ->check(CLI::IsMember(gpu_preset_list()))
      ->excludes("--tile")
      ->excludes("--budget")
      ->excludes("--parameter-cache-kib");
  cmd->add_option("--varying-precision", o->varying_precision,
                  "Stored varying size: fp32 (default) or fp16, as `ontile render --varying-precision`")
      ->check(CLI::IsMember({"fp32", "fp16"}));
  cmd->add_option("--texture-compression", o->texture_compression,
                  "Storage of the scene's textures: none (default), astc4x4, astc8x8, etc2, as `ontile render "
                  "--texture-compression`")
      ->check(CLI::IsMember({"none", "astc4x4", "astc8x8", "etc2"}));
  add_progress_flag(cmd, o->progress);
  cmd->add_option("--markdown", o->markdown, "Also write the tables to this file (they are always printed)");
  cmd->add_option("--json", o->json,
                  "Also write the variants, their bytes and the two-passes-over-subpasses ratios as JSON "
                  "(- for standard output; the tables then go to stderr)");
  cmd->callback([o] { run_deferred_study(*o); });
  add_architecture_study(study);
}

}  // namespace ontile::cli
