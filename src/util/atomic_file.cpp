// Temporary-file-and-rename outputs, committed together, cleaned up on errors and on SIGINT /
// SIGTERM (see atomic_file.h).
#include "util/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <system_error>

#include "util/error.h"

namespace ontile {
namespace {

namespace fs = std::filesystem;

// The signal handler may only call async-signal-safe functions (POSIX.1-2017 2.4.3): it reads
// fixed arrays through lock-free atomics and calls unlink(), signal() and raise(). A slot is
// Free, Claimed (its path being copied) or Live (the handler unlinks it).
constexpr int kCleanupSlots = 64;
constexpr size_t kCleanupPathBytes = 4096;
enum SlotState : int { kFree = 0, kClaimed = 1, kLive = 2 };
struct CleanupSlot {
  std::atomic<int> state{kFree};
  char path[kCleanupPathBytes];
};
CleanupSlot g_cleanup_slots[kCleanupSlots];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

// Returns the slot holding `path`, or -1 when the registry is full or the path too long (the file
// is then still removed on errors, only not on signals).
int register_for_cleanup(const std::string& path) {
  if (path.size() >= kCleanupPathBytes) return -1;
  for (int i = 0; i < kCleanupSlots; ++i) {
    int expected = kFree;
    if (g_cleanup_slots[i].state.compare_exchange_strong(expected, kClaimed)) {
      std::memcpy(g_cleanup_slots[i].path, path.c_str(), path.size() + 1);
      g_cleanup_slots[i].state.store(kLive, std::memory_order_release);
      return i;
    }
  }
  return -1;
}

void unregister_for_cleanup(int slot) {
  if (slot >= 0) g_cleanup_slots[slot].state.store(kFree, std::memory_order_release);
}

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  for (CleanupSlot& slot : g_cleanup_slots) {
    if (slot.state.load(std::memory_order_acquire) == kLive) unlink(slot.path);
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

// fsync of a file or folder: the data (or the rename) is on disk before we report success.
void sync_path(const fs::path& path, bool folder) {
  const int fd = open(path.c_str(), O_RDONLY | (folder ? O_DIRECTORY : 0));
  if (fd < 0) throw Error(path.string() + ": cannot open to flush: " + std::strerror(errno));
  const int result = fsync(fd);
  const int saved_errno = errno;
  close(fd);
  // Some file systems cannot fsync a folder (EINVAL); the rename is still atomic there.
  if (result != 0 && !(folder && saved_errno == EINVAL)) {
    throw Error(path.string() + ": cannot flush to disk: " + std::strerror(saved_errno));
  }
}

fs::path folder_of(const fs::path& path) { return path.has_parent_path() ? path.parent_path() : fs::path("."); }

}  // namespace

void check_output_path(const fs::path& path) {
  if (path.empty()) throw Error("output path is empty");
  const fs::path folder = folder_of(path);
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    throw Error(path.string() + ": folder '" + folder.string() +
                "' does not exist (outputs never create folders)");
  }
  struct stat st;
  if (stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw Error(path.string() + ": is a folder, not a file");
    if (!S_ISREG(st.st_mode)) throw Error(path.string() + ": exists and is not a regular file");
    // Mode bits first: root passes access(W_OK) for any file.
    if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0 || access(path.c_str(), W_OK) != 0) {
      throw Error(path.string() + ": file is read-only; refusing to replace it");
    }
  }
  if (access(folder.c_str(), W_OK) != 0) {
    throw Error(path.string() + ": folder '" + folder.string() + "' is not writable");
  }
}

StagedOutputs::~StagedOutputs() {
  for (Staged& s : staged_) discard(s);
}

void StagedOutputs::discard(Staged& s) {
  std::error_code ec;
  fs::remove(s.tmp, ec);
  unregister_for_cleanup(s.cleanup_slot);
  s.cleanup_slot = -1;
}

void StagedOutputs::stage(const fs::path& path, const std::function<void(const fs::path&)>& write) {
  static std::atomic<unsigned> counter{0};
  check_output_path(path);
  // Hidden, unique per process and call, extension kept last.
  std::string tmp_name = ".";
  tmp_name += path.stem().string();
  tmp_name += ".tmp" + std::to_string(getpid()) + "_" + std::to_string(counter++);
  tmp_name += path.extension().string();
  Staged s{path, folder_of(path) / tmp_name, -1};
  // Registered before the file exists, so a signal at any later moment removes it.
  s.cleanup_slot = register_for_cleanup(s.tmp.string());
  try {
    write(s.tmp);
    sync_path(s.tmp, false);
  } catch (...) {
    discard(s);
    throw;
  }
  staged_.push_back(s);
}

void StagedOutputs::stage_text(const fs::path& path, const std::string& text) {
  stage(path, [&](const fs::path& tmp) {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    f.close();
    if (!f) throw Error(path.string() + ": cannot write");
  });
}

void StagedOutputs::commit() {
  for (Staged& s : staged_) {
    struct stat target;
    if (stat(s.target.c_str(), &target) == 0) {
      // Replacing a file keeps its permission bits (the temporary has the umask's).
      chmod(s.tmp.c_str(), target.st_mode & 07777);
    }
    std::error_code ec;
    fs::rename(s.tmp, s.target, ec);
    if (ec) throw Error(s.target.string() + ": cannot write: " + ec.message());
    unregister_for_cleanup(s.cleanup_slot);
    s.cleanup_slot = -1;
  }
  for (const Staged& s : staged_) sync_path(folder_of(s.target), true);
  staged_.clear();
}

void write_file_atomically(const fs::path& path, const std::function<void(const fs::path&)>& write) {
  StagedOutputs outputs;
  outputs.stage(path, write);
  outputs.commit();
}

void install_temporary_file_cleanup() {
  struct sigaction action {};
  action.sa_handler = remove_temporaries_and_reraise;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace ontile
