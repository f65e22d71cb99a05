// Median and minimum of per-frame times, shared by the llvmpipe runner and the peer benchmark
// so both sides summarise their frames the same way.
#pragma once
#include <algorithm>
#include <ctime>
#include <vector>

namespace ontile::peer {

struct FrameTimes {
  double median_ms = 0.0, min_ms = 0.0;
  // CPU time of the whole process (all its threads) per timed frame, and divided by the wall
  // time: how many cores the renderer kept busy on average. On a machine shared with other
  // work the wall times grow with the load but the CPU times much less.
  double cpu_ms_per_frame = 0.0, cores_busy = 0.0;
};

// CPU time of this process, all threads, in milliseconds.
inline double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Even counts give the mean of the two middle frames. `ms` must not be empty.
// cpu_ms: process_cpu_ms() spent over all the frames.
inline FrameTimes summarize_frames(std::vector<double> ms, double cpu_ms) {
  double wall_ms = 0.0;
  for (double m : ms) wall_ms += m;
  std::sort(ms.begin(), ms.end());
  const size_t n = ms.size();
  return {n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]), ms.front(), cpu_ms / double(n),
          wall_ms > 0.0 ? cpu_ms / wall_ms : 0.0};
}

}  // namespace ontile::peer
