// `ontile golden [--update]`: compares every golden case with golden/, or rewrites golden/.
// Exit 1 when an image differs or is missing, 2 when a file cannot be read or written.
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "golden/golden_images.h"
#include "util/error.h"

namespace ontile::cli {

void add_golden_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("golden", "Compare the golden images (or rewrite them with --update)");
  struct Options {
    bool update = false, progress = false;
    std::string golden_dir = std::string(ONTILE_SOURCE_DIR) + "/golden";
    std::string failure_dir = "out/golden_failures";
    std::string shared_assets = std::string(ONTILE_SOURCE_DIR) + "/../shared/assets";
  };
  auto o = std::make_shared<Options>();
  cmd->add_flag("--update", o->update, "Rewrite the golden images from the current renderer");
  cmd->add_option("--dir", o->golden_dir, "Golden image folder");
  cmd->add_option("--failures", o->failure_dir, "Where mismatches write actual and diff images");
  cmd->add_option("--assets", o->shared_assets, "Shared assets folder");
  add_progress_flag(cmd, o->progress);
  cmd->callback([o] {
    std::error_code ec;
    if (!std::filesystem::is_directory(o->golden_dir, ec)) {
      throw UsageError("--dir " + o->golden_dir + ": folder does not exist");
    }
    int failures = 0, done = 0;
    Progress progress("golden", o->progress);
    const std::vector<GoldenCase> cases = golden_cases(ONTILE_SOURCE_DIR, o->shared_assets);
    for (const GoldenCase& c : cases) {
      progress.step(++done, static_cast<int>(cases.size()), c.name);
      const GoldenResult r = run_golden_case(c, o->golden_dir, o->failure_dir, o->update);
      const char* status[] = {"match", "MISMATCH", "MISSING", "updated", "skipped"};
      std::printf("%-28s %-9s %s\n", c.name.c_str(), status[static_cast<int>(r.status)], r.message.c_str());
      failures += r.status == GoldenResult::Status::Mismatch || r.status == GoldenResult::Status::Missing;
    }
    if (failures) {
      throw MismatchError(std::to_string(failures) + " golden image(s) differ from " + o->golden_dir +
                          " (actual and diff images in " + o->failure_dir + ")");
    }
  });
}

}  // namespace ontile::cli
