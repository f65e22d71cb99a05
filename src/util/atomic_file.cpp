// Temporary-file-and-rename output (see atomic_file.h).
#include "util/atomic_file.h"

#include <atomic>
#include <string>
#include <system_error>
#include <unistd.h>

#include "util/error.h"

namespace ontile {

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path&)>& write) {
  static std::atomic<unsigned> counter{0};
  namespace fs = std::filesystem;
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(parent, ec)) {
    throw Error(path.string() + ": output folder '" + parent.string() + "' does not exist");
  }
  // Keep the extension last so that writers that pick a format from the name still can.
  std::string tmp_name = ".";
  tmp_name += path.stem().string();
  tmp_name += ".tmp" + std::to_string(getpid()) + "_" + std::to_string(counter++);
  tmp_name += path.extension().string();
  const fs::path tmp = parent / tmp_name;
  try {
    write(tmp);
    fs::rename(tmp, path);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
}

}  // namespace ontile
