// Progress of a long run on stderr ("golden: 3/15 cartoon-demo, 12.4 s"): what is running, n of
// N, elapsed time. Shown when stderr is a terminal (one line, redrawn) or when --progress asks
// for it (one line per step, for logs); silent otherwise, so pipes and test logs stay clean.
#pragma once
#include <chrono>
#include <functional>
#include <mutex>
#include <string>

namespace ontile {

// What long-running library calls report: `done` of `total` steps finished, `what` is the step.
using ProgressCallback = std::function<void(int done, int total, const std::string& what)>;

class Progress {
 public:
  // forced: --progress. A terminal stderr shows progress without it.
  Progress(std::string verb, bool forced);
  ~Progress();  // ends a redrawn line
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool enabled() const { return enabled_; }
  void step(int done, int total, const std::string& what);  // thread-safe
  // A callback for library calls that report their steps; does nothing when disabled.
  ProgressCallback callback();

 private:
  std::string verb_;
  bool enabled_ = false, terminal_ = false, line_open_ = false;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

}  // namespace ontile
