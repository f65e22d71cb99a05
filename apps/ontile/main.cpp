// Entry point of the `ontile` CLI: dispatches to the verbs and turns every error, the argument
// parser's included, into one "error: ..." line on stderr and the exit codes of commands.h.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "commands.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace {

// One line, whatever the message holds (CLI11 and OpenImageIO messages may span lines).
int print_error(std::string message, int exit_code) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  while (!message.empty() && message.back() == ' ') message.pop_back();
  std::fprintf(stderr, "error: %s\n", message.c_str());
  return exit_code;
}

// CLI11 says only "A subcommand is required"; name the verb and what it takes instead, and what
// was given in its place.
std::string missing_subcommand_message(CLI::App& app) {
  CLI::App* verb = &app;
  while (!verb->get_subcommands().empty()) verb = verb->get_subcommands().front();
  std::string names;
  for (const CLI::App* sub : verb->get_subcommands({})) names += (names.empty() ? "" : ", ") + sub->get_name();
  const std::string who = verb == &app ? std::string("ontile") : "ontile " + verb->get_name();
  std::string message = who + ": expected one of " + names;
  const std::vector<std::string> given = verb->remaining();
  if (!given.empty()) message += "; got '" + given.front() + "'";
  return message;
}

// The wording of CLI11's own ExtrasError, so an unknown option reads the same whether or not a
// required option is also missing.
std::string unexpected_arguments_message(const std::vector<std::string>& unknown) {
  std::string message = unknown.size() == 1 ? "The following argument was not expected:"
                                             : "The following arguments were not expected:";
  for (const std::string& argument : unknown) message += " " + argument;
  return message;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ontile::cli;
  ontile::install_temporary_file_cleanup();
  CLI::App app{"ontile: a deterministic tile-based GPU simulator"};
  app.set_version_flag("--version", std::string("ontile ") + ONTILE_VERSION);
  app.require_subcommand(1);
  add_render_command(app);
  add_gen_scene_command(app);
  add_pipelines_command(app);
  add_golden_command(app);
  add_reference_command(app);
  add_accuracy_command(app);
  add_study_command(app);
  add_sweep_command(app);
  add_diff_command(app);
  add_compare_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help and --version: printed on stdout, exit 0
  } catch (const CLI::RequiredError& e) {
    const bool no_subcommand = std::string(e.what()) == "A subcommand is required";
    if (no_subcommand) return print_error(missing_subcommand_message(app), kExitUsageOrInput);
    // CLI11 checks required options before it rejects unknown ones, so `render --bogus` would
    // be told "--scene is required": name the argument it does not know first.
    const std::vector<std::string> unknown = app.remaining(true);
    if (!unknown.empty()) return print_error(unexpected_arguments_message(unknown), kExitUsageOrInput);
    return print_error(e.what(), kExitUsageOrInput);
  } catch (const CLI::ParseError& e) {
    return print_error(e.what(), kExitUsageOrInput);
  } catch (const MismatchError& e) {
    return print_error(e.what(), kExitMismatch);
  } catch (const std::bad_alloc&) {
    return print_error("out of memory (the scene or --size needs more than this machine has)", kExitUsageOrInput);
  } catch (const std::exception& e) {
    return print_error(e.what(), kExitUsageOrInput);
  }
  return kExitSuccess;
}
