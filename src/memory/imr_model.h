// The immediate-mode (IMR) comparison model: the same pass, but colour and depth live in
// external memory and every fragment's reads and writes go through a write-back render-target
// cache. Fragments are replayed in submission order (triangle by triangle; within a triangle,
// tiles in index order, as a block-rasterizing IMR walks it).
#pragma once
#include <cstdint>
#include <vector>

#include "memory/pass_memory.h"
#include "memory/tile_trace.h"

namespace ontile {

// Set-associative, write-back, write-allocate cache with LRU replacement (the shared
// SetAssociativeCache, set_associative_cache.h). line_bytes must be a power of two and size_bytes a multiple of line_bytes * ways (sets = size / (line * ways)).
struct RenderTargetCacheConfig {
  uint32_t size_bytes = 128 * 1024;
  uint32_t line_bytes = 64;
  uint32_t ways = 16;
};

struct ImrAttachmentTraffic {
  uint64_t bytes_read = 0;      // line fills (Load contents, depth test, blend reads, write
                                // allocation) and the resolve's read of all samples
  uint64_t bytes_written = 0;   // clears, write-backs of dirty lines, the resolve's write
  uint64_t bytes_resolved = 0;  // the part of bytes_written that the resolve wrote
};

struct ImrTraffic {
  uint64_t cache_hits = 0, cache_misses = 0;  // per cache-line access
  std::vector<ImrAttachmentTraffic> attachments;  // per attachment of the pass
};

// `traces` are the pass's tile traces with fragments recorded (one per tile, tile-index order,
// each tile's fragments in submission order). The cache starts empty for every pass. The rules
// (surface layout, load/store/resolve actions, access order) are documented in imr_model.cpp.
// Throws ontile::Error for an invalid cache configuration or inconsistent traces.
ImrTraffic simulate_imr_pass(const PassMemoryDesc& pass, const std::vector<TileTrace>& traces,
                             const RenderTargetCacheConfig& config);

}  // namespace ontile
