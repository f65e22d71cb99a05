// Progress on stderr (see progress.h).
#include "util/progress.h"

#include <unistd.h>

#include <cstdio>

namespace ontile {

Progress::Progress(std::string verb, bool forced)
    : verb_(std::move(verb)), terminal_(isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()) {
  enabled_ = forced || terminal_;
}

Progress::~Progress() {
  if (line_open_) std::fputc('\n', stderr);
}

void Progress::step(int done, int total, const std::string& what) {
  if (!enabled_) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::lock_guard<std::mutex> lock(mutex_);
  // On a terminal the line is redrawn in place ("\r" and clear to the end); in a log, one line each.
  std::fprintf(stderr, "%s%s: %d/%d %s, %.1f s%s", terminal_ ? "\r\033[K" : "", verb_.c_str(), done, total,
               what.c_str(), seconds, terminal_ ? "" : "\n");
  std::fflush(stderr);
  line_open_ = terminal_;
}

ProgressCallback Progress::callback() {
  if (!enabled_) return {};
  return [this](int done, int total, const std::string& what) { step(done, total, what); };
}

}  // namespace ontile
