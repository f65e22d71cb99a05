// ontile's parallel loops: tbb::parallel_for, plus (in ThreadSanitizer builds only) the fork and
// join edges oneTBB guarantees, declared to TSan. Debian's libtbb is not instrumented, so TSan
// cannot see that the caller's writes happen before the loop bodies run on TBB's workers, nor
// that the bodies finish before the caller goes on (google/sanitizers#1004): it would report
// every parallel loop. The bodies get no edge between each other, so a race between two
// iterations is still reported (docs/robustness.md, "Sanitizers"). Elsewhere: tbb::parallel_for.
#pragma once
#include <tbb/parallel_for.h>

#if defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define ONTILE_THREAD_SANITIZER 1
#endif
#endif
#if defined(__SANITIZE_THREAD__) && !defined(ONTILE_THREAD_SANITIZER)
#define ONTILE_THREAD_SANITIZER 1
#endif

#ifdef ONTILE_THREAD_SANITIZER
#include <sanitizer/tsan_interface.h>
#endif

namespace ontile {

#ifdef ONTILE_THREAD_SANITIZER
namespace parallel_detail {

// The synchronisation objects TSan sees (only their addresses matter): the caller releases
// `fork_token` before a loop and acquires `join_token` after it; every body acquires
// `fork_token` first and releases `join_token` last. They are global rather than per loop
// because a body must acquire before it reads anything the caller wrote, its own captures
// included. The cost: two loops started at the same time by different threads would look
// ordered to TSan; ontile starts its loops from one thread per frame.
inline char fork_token = 0;
inline char join_token = 0;

template <typename Body>
auto with_fork_join_edges(const Body& body) {
  return [&body](const auto& index_or_range) {
    __tsan_acquire(&fork_token);
    body(index_or_range);
    __tsan_release(&join_token);
  };
}

}  // namespace parallel_detail
#endif

// tbb::parallel_for(range, body).
template <typename Range, typename Body>
void parallel_for(const Range& range, const Body& body) {
#ifdef ONTILE_THREAD_SANITIZER
  __tsan_release(&parallel_detail::fork_token);
  tbb::parallel_for(range, parallel_detail::with_fork_join_edges(body));
  __tsan_acquire(&parallel_detail::join_token);
#else
  tbb::parallel_for(range, body);
#endif
}

// tbb::parallel_for(first, last, body): body(i) for every i in [first, last).
template <typename Index, typename Body>
void parallel_for(Index first, Index last, const Body& body) {
#ifdef ONTILE_THREAD_SANITIZER
  __tsan_release(&parallel_detail::fork_token);
  tbb::parallel_for(first, last, parallel_detail::with_fork_join_edges(body));
  __tsan_acquire(&parallel_detail::join_token);
#else
  tbb::parallel_for(first, last, body);
#endif
}

// While alive, declares one loop body's use of an object kept per task-arena slot (indexed by
// tbb::this_task_arena::current_thread_index()) ordered after the previous body's use of it:
// oneTBB gives a slot to one thread at a time and hands it over through its own synchronisation,
// which TSan cannot see, so a body that takes over another thread's slot would be reported
// racing with that thread's earlier bodies. A no-op outside ThreadSanitizer builds.
class SlotObjectUse {
 public:
  explicit SlotObjectUse(const void* object) : object_(object) {
#ifdef ONTILE_THREAD_SANITIZER
    __tsan_acquire(const_cast<void*>(object_));
#endif
  }
  ~SlotObjectUse() {
#ifdef ONTILE_THREAD_SANITIZER
    __tsan_release(const_cast<void*>(object_));
#endif
  }
  SlotObjectUse(const SlotObjectUse&) = delete;
  SlotObjectUse& operator=(const SlotObjectUse&) = delete;

 private:
  [[maybe_unused]] const void* object_;
};

}  // namespace ontile
