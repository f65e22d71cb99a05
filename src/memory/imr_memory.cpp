// The immediate-mode memory model (see imr_memory.h); the rules are in imr_model.cpp.
#include "memory/imr_memory.h"

namespace ontile {

ImrMemory::ImrMemory(const MemoryConfig& config) : MemoryModel(config) {}

void ImrMemory::fragments(const std::vector<TileTrace>& traces) {
  traffic_ = simulate_imr_pass(pass_, traces, config_.render_target_cache);
}

PassAttachmentTraffic ImrMemory::end_pass() {
  PassAttachmentTraffic out;
  out.architecture = "imr";
  out.tile_bytes_loaded.assign(static_cast<size_t>(pass_.tile_count()), 0);
  out.tile_bytes_stored.assign(static_cast<size_t>(pass_.tile_count()), 0);
  out.render_target_cache_hits = traffic_.cache_hits;
  out.render_target_cache_misses = traffic_.cache_misses;
  for (size_t a = 0; a < pass_.attachments.size(); ++a) {
    const AttachmentMemory& d = pass_.attachments[a];
    AttachmentTraffic t;
    t.name = d.name;
    t.format = d.format;
    t.transient = false;  // an IMR keeps every attachment in memory
    t.bytes_loaded = traffic_.attachments[a].bytes_read;
    t.bytes_stored = traffic_.attachments[a].bytes_written - traffic_.attachments[a].bytes_resolved;
    t.bytes_resolved = traffic_.attachments[a].bytes_resolved;
    out.attachments.push_back(t);
  }
  return out;
}

}  // namespace ontile
