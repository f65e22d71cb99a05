// The verbs of the `ontile` command line; each file under apps/ontile/ adds one verb.
#pragma once
#include <CLI/CLI.hpp>

namespace ontile::cli {

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
