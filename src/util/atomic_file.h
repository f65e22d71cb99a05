// Writes output files so that readers never see one half-written and the outputs of one run
// appear together or not at all: each file goes to a temporary file in its destination folder,
// is flushed to disk (fsync), and all are renamed over their targets only at the end.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace ontile {

// Throws Error (naming the file) unless `path` can be written without side effects: its folder
// exists (folders are never created implicitly), it is not a folder itself, and an existing file
// is writable (a read-only file is refused, never replaced: even root, which may write anything,
// keeps it).
void check_output_path(const std::filesystem::path& path);

// A set of outputs committed together. stage() writes each one to a temporary file (after
// check_output_path); commit() renames them all over their targets, keeping an existing
// target's permission bits. Temporaries not committed (an exception, or destruction before
// commit) are removed, also on SIGINT/SIGTERM once install_temporary_file_cleanup() ran.
class StagedOutputs {
 public:
  StagedOutputs() = default;
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;
  ~StagedOutputs();

  // Calls write(tmp_path) (tmp_path keeps path's extension, for writers that pick a format from
  // it), then fsyncs the temporary. On any exception the temporary is removed and it propagates.
  void stage(const std::filesystem::path& path,
             const std::function<void(const std::filesystem::path& tmp_path)>& write);
  // Stages a file holding `text` exactly.
  void stage_text(const std::filesystem::path& path, const std::string& text);
  // Renames every staged file over its target, in staging order, then fsyncs their folders.
  void commit();

 private:
  struct Staged {
    std::filesystem::path target, tmp;
    int cleanup_slot;  // index in the signal cleanup registry, or -1
  };
  void discard(Staged& s);
  std::vector<Staged> staged_;
};

// One output on its own: stage + commit.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path& tmp_path)>& write);

// Installs SIGINT and SIGTERM handlers that unlink every temporary file still staged, then
// re-raise the signal with its default action (so the exit status still says "killed by").
void install_temporary_file_cleanup();

}  // namespace ontile
