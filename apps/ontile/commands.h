// The verbs of the `ontile` command line (each file under apps/ontile/ adds one) and what they
// share: the exit-code contract, size parsing and the outputs of a run.
#pragma once
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/progress.h"

namespace ontile::cli {

// Exit codes of every verb (README, "The CLI"): 0 success or match, 1 mismatch (golden), 2 usage
// or input error. Every error is one "error: ..." line on stderr naming the file or option.
constexpr int kExitSuccess = 0;
constexpr int kExitMismatch = 1;
constexpr int kExitUsageOrInput = 2;

// A bad option value found after parsing: main prints one "error: ..." line and exits with 2.
class UsageError : public Error {
 public:
  using Error::Error;
};

// Outputs that differ from their references (golden): main prints the line and exits with 1.
class MismatchError : public Error {
 public:
  using Error::Error;
};

void add_render_command(CLI::App& app);
void add_gen_scene_command(CLI::App& app);
void add_pipelines_command(CLI::App& app);
void add_golden_command(CLI::App& app);
void add_reference_command(CLI::App& app);
void add_accuracy_command(CLI::App& app);
void add_study_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_diff_command(CLI::App& app);
void add_compare_command(CLI::App& app);

// The folder of bundled data (scenes/demo.glb, golden/, assets/ for the shared assets):
// $ONTILE_DATA_DIR when set, else share/ontile beside the executable (a build tree) or in its
// parent (an installed prefix: P/bin/ontile and P/share/ontile).
std::filesystem::path data_dir();

// The largest --size side in pixels: the render target limit (kMaxTargetSizePx).
int max_image_side_px();
// Parses "WxH" (e.g. 1920x1080): decimal digits only, each side 1..max_image_side_px(), checked
// before any conversion can overflow. Throws UsageError naming `option` otherwise.
void parse_size(const std::string& text, int& width_px, int& height_px, const char* option = "--size");

// --scene FILE (required, must exist) and --allow-outside-files: by default the loader refuses
// buffer and image URIs that leave the scene file's folder (docs/robustness.md).
void add_scene_options(CLI::App* cmd, std::string& scene, bool& allow_outside_files,
                       const std::string& description);
// Loads the glTF scene with the loader options the verb's flags chose; `texture_compression`
// lays its images out in that block format for the texture-cache model (--texture-compression).
Scene load_scene(const std::string& scene, bool allow_outside_files,
                 TextureCompression texture_compression = TextureCompression::None);

// --progress: progress on stderr even when it is not a terminal (util/progress.h).
inline void add_progress_flag(CLI::App* cmd, bool& progress) {
  cmd->add_flag("--progress", progress, "Print progress on stderr even when it is not a terminal (a log)");
}

// "-" as a report path means standard output.
inline bool is_stdout(const std::string& path) { return path == "-"; }

// Checks an output option before any work is done (check_output_path: the folder exists, the
// target is not read-only or a folder); "-" is accepted when allow_stdout. Throws UsageError
// naming the option and the file.
void check_output_option(const char* option, const std::string& path, bool allow_stdout);
// Throws UsageError when two output options name the same file (the second would replace the
// first). Empty paths and "-" are ignored.
void check_distinct_outputs(const std::vector<std::pair<const char*, std::string>>& outputs);

// The outputs of one run: files are staged (temporary files) and texts for standard output
// held back; commit() renames all files, then prints the texts, so a failure anywhere before it
// leaves no new file behind and prints no partial report.
class RunOutputs {
 public:
  StagedOutputs& files() { return files_; }
  // Writes `text` to `path` at commit, or to standard output when path is "-".
  void text(const std::string& path, const std::string& text);
  void commit();

 private:
  StagedOutputs files_;
  std::vector<std::string> stdout_texts_;
};

// Where a verb prints its human summary: standard error when a report goes to standard output
// (so that stdout is the report alone and can be piped), else standard output.
inline std::FILE* summary_stream(bool report_on_stdout) { return report_on_stdout ? stderr : stdout; }

}  // namespace ontile::cli
