// The process-wide oneTBB parallelism limit (see worker_threads.h). oneTBB applies the smallest
// of the active global_control values, so exactly one is kept, replaced by a larger one when a
// render asks for more threads.
#include "util/worker_threads.h"

#include <memory>
#include <mutex>

#include <tbb/global_control.h>

namespace ontile {
namespace {

std::mutex limit_mutex;
std::unique_ptr<tbb::global_control> limit;

}  // namespace

void allow_worker_threads(int threads) {
  const std::lock_guard<std::mutex> lock(limit_mutex);
  const size_t wanted = static_cast<size_t>(threads > 0 ? threads : 1);
  const size_t current = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  if (wanted <= current) return;
  // The new limit is created before the old one goes, so parallelism never drops in between.
  auto raised = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, wanted);
  limit = std::move(raised);
}

}  // namespace ontile
