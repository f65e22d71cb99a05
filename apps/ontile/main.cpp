// Entry point of the `ontile` CLI: dispatches to the verbs and turns every error into one
// "error: ..." line and a non-zero exit.
#include <cstdio>
#include <exception>

#include "commands.h"
#include "util/error.h"

int main(int argc, char** argv) {
  CLI::App app{"ontile: a deterministic tile-based GPU simulator"};
  app.require_subcommand(1);
  ontile::cli::add_render_command(app);
  ontile::cli::add_gen_scene_command(app);
  ontile::cli::add_pipelines_command(app);
  ontile::cli::add_golden_command(app);
  ontile::cli::add_reference_command(app);
  ontile::cli::add_accuracy_command(app);
  ontile::cli::add_study_command(app);
  ontile::cli::add_sweep_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const ontile::cli::UsageError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
