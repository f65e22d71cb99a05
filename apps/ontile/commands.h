// The verbs of the `ontile` command line; each file under apps/ontile/ adds one verb.
#pragma once
#include <CLI/CLI.hpp>

#include "util/error.h"

namespace ontile::cli {

// A bad option value found after parsing: main prints one "error: ..." line and exits with 2.
class UsageError : public Error {
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

// Parses "WxH" (e.g. 1920x1080) into positive sizes; throws ontile::Error otherwise.
void parse_size(const std::string& text, int& width_px, int& height_px);

}  // namespace ontile::cli
