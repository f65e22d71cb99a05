// `ontile golden [--update] [--cases FILE.json]`: compares the built-in golden cases with
// golden/ (or a user's own cases, with their tolerances), or rewrites the references.
// Exit 1 when an image differs or is missing, 2 when a file cannot be read or written.
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "golden/golden_cases_file.h"
#include "golden/golden_images.h"
#include "util/error.h"

namespace ontile::cli {

void add_golden_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("golden", "Compare the golden images (or rewrite them with --update)");
  struct Options {
    bool update = false, progress = false;
    std::string golden_dir = (data_dir() / "golden").string();
    std::string failure_dir = "out/golden_failures";
    std::string shared_assets = (data_dir() / "assets").string();
    std::string cases_file;
  };
  auto o = std::make_shared<Options>();
  cmd->add_flag("--update", o->update, "Rewrite the reference images from the current renderer");
  CLI::Option* dir = cmd->add_option("--dir", o->golden_dir, "Golden image folder of the built-in cases");
  cmd->add_option("--failures", o->failure_dir, "Where mismatches write actual and diff images");
  CLI::Option* assets = cmd->add_option("--assets", o->shared_assets, "Shared assets folder of the built-in cases");
  cmd->add_option("--cases", o->cases_file, "Your own cases (JSON: docs/golden.md) instead of the built-in ones")
      ->excludes(dir)
      ->excludes(assets);
  add_progress_flag(cmd, o->progress);
  cmd->callback([o] {
    std::vector<GoldenCase> cases;
    std::string compared_with;
    if (!o->cases_file.empty()) {
      cases = read_golden_cases_file(o->cases_file);
      compared_with = "their references in " + o->cases_file;
    } else {
      std::error_code ec;
      if (!std::filesystem::is_directory(o->golden_dir, ec)) {
        throw UsageError("--dir " + o->golden_dir + ": folder does not exist");
      }
      cases = golden_cases(data_dir() / "scenes" / "demo.glb", o->shared_assets);
      compared_with = o->golden_dir;
    }
    int failures = 0, done = 0;
    Progress progress("golden", o->progress);
    for (const GoldenCase& c : cases) {
      progress.step(++done, static_cast<int>(cases.size()), c.name);
      const GoldenResult r = run_golden_case(c, o->golden_dir, o->failure_dir, o->update);
      const char* status[] = {"match", "MISMATCH", "MISSING", "updated", "skipped"};
      std::printf("%-28s %-9s %s\n", c.name.c_str(), status[static_cast<int>(r.status)], r.message.c_str());
      failures += r.status == GoldenResult::Status::Mismatch || r.status == GoldenResult::Status::Missing;
    }
    if (failures) {
      throw MismatchError(std::to_string(failures) + " golden image(s) differ from " + compared_with +
                          " (actual and diff images in " + o->failure_dir + ")");
    }
  });
}

}  // namespace ontile::cli
