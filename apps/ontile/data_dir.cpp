// Where the CLI finds its bundled data (the demo scene, the golden images, the shared assets):
// beside the executable, so that no source path is compiled in and an installed or moved
// binary finds its own copy (cmake/package.cmake makes the build tree's links).
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "commands.h"

namespace ontile::cli {

std::filesystem::path data_dir() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("ONTILE_DATA_DIR"); env && *env) return fs::path(env);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);  // Linux: the running binary
  if (ec) return fs::path("share") / "ontile";
  const fs::path bin = exe.parent_path();
  for (const fs::path& candidate : {bin / "share" / "ontile", bin.parent_path() / "share" / "ontile"}) {
    if (fs::is_directory(candidate, ec)) return candidate;
  }
  return bin.parent_path() / "share" / "ontile";  // the installed layout, named in errors
}

}  // namespace ontile::cli
