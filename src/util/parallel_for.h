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

// One loop's synchronisation objects for TSan (only their addresses matter): the caller
// releases `fork` before the loop and acquires `join` after it; every body acquires `fork`
// first and releases `join` last.
struct ForkJoinEdges {
  char fork = 0;
  char join = 0;
};

template <typename Body>
auto with_fork_join_edges(ForkJoinEdges* edges, const Body& body) {
  return [edges, &body](const auto& index_or_range) {
    __tsan_acquire(&edges->fork);
    body(index_or_range);
    __tsan_release(&edges->join);
  };
}

}  // namespace parallel_detail
#endif

// tbb::parallel_for(range, body).
template <typename Range, typename Body>
void parallel_for(const Range& range, const Body& body) {
#ifdef ONTILE_THREAD_SANITIZER
  parallel_detail::ForkJoinEdges edges;
  __tsan_release(&edges.fork);
  tbb::parallel_for(range, parallel_detail::with_fork_join_edges(&edges, body));
  __tsan_acquire(&edges.join);
#else
  tbb::parallel_for(range, body);
#endif
}

// tbb::parallel_for(first, last, body): body(i) for every i in [first, last).
template <typename Index, typename Body>
void parallel_for(Index first, Index last, const Body& body) {
#ifdef ONTILE_THREAD_SANITIZER
  parallel_detail::ForkJoinEdges edges;
  __tsan_release(&edges.fork);
  tbb::parallel_for(first, last, parallel_detail::with_fork_join_edges(&edges, body));
  __tsan_acquire(&edges.join);
#else
  tbb::parallel_for(first, last, body);
#endif
}

}  // namespace ontile
