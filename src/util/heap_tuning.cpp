// Allocator tuning (see heap_tuning.h).
#include "util/heap_tuning.h"

#include <malloc.h>

namespace ontile {

void keep_freed_memory_in_the_heap() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

}  // namespace ontile
