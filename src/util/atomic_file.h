// Writes an output file so that readers never see it half-written: the content goes to a
// temporary file in the same folder, which is renamed over the target only on success.
#pragma once
#include <filesystem>
#include <functional>

namespace ontile {

// Calls write(tmp_path); on success renames tmp_path to path. On any exception the temporary
// file is removed and the exception propagates; path is left as it was.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path& tmp_path)>& write);

}  // namespace ontile
