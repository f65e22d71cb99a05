// Lets oneTBB run as many worker threads as a render asks for, even above the machine's core
// count: determinism is tested at thread counts (7, 16) a 2-core CI machine does not have, and
// oneTBB otherwise caps its workers at the core count and prints a warning on stderr.
#pragma once

namespace ontile {

// Raises oneTBB's process-wide limit on parallelism to at least `threads` for the rest of the
// process (it never lowers it). Thread-safe.
void allow_worker_threads(int threads);

}  // namespace ontile
