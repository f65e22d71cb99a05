// Process-wide allocator tuning for measuring frame times in the steady state a renderer that
// reuses its buffers reaches (used by the timing verbs and the benchmarks).
#pragma once

namespace ontile {

// Every frame allocates its surfaces, parameter buffer and tile memories afresh. With glibc's
// defaults the large ones are mmapped and returned to the kernel when freed, so each frame pays
// page faults for them (measured once: 45 ms against 27 ms for a 640x360 demo frame on one
// thread), and how much depends on the
// allocation history (glibc adapts its mmap threshold to earlier frees), so one measurement
// would depend on what ran before it. This keeps freed memory in the heap (glibc mallopt:
// M_MMAP_THRESHOLD at its 32 MiB maximum, trimming only above 1 GiB).
void keep_freed_memory_in_the_heap();

}  // namespace ontile
