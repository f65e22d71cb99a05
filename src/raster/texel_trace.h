// Where texture fetches report the memory they touch: a thread-local sink that the tile
// executor points at the current tile's trace, so shaders need no extra parameter and a
// disabled trace costs one branch per texel.
#pragma once
#include <cstdint>
#include <vector>

namespace ontile {

// While alive, texel fetches on this thread append their 64-byte granule ids (byte address / 64)
// to `granules`, skipping a repeat of the last one. Nests (restores the previous sink).
class TexelTraceScope {
 public:
  explicit TexelTraceScope(std::vector<uint64_t>* granules);
  ~TexelTraceScope();
  TexelTraceScope(const TexelTraceScope&) = delete;
  TexelTraceScope& operator=(const TexelTraceScope&) = delete;

 private:
  std::vector<uint64_t>* previous_;
  uint64_t previous_last_;
};

namespace texel_trace_detail {
// constinit: no dynamic initialisation, so reads need no TLS wrapper call per texel.
extern thread_local constinit std::vector<uint64_t>* sink;
extern thread_local constinit uint64_t last_granule;
}  // namespace texel_trace_detail

// Records the texel at `byte_address` (called by Texture2D for every texel it reads).
inline void record_texel_address(uint64_t byte_address) {
  using namespace texel_trace_detail;
  if (!sink) return;
  const uint64_t granule = byte_address >> 6;
  if (granule != last_granule) {
    sink->push_back(granule);
    last_granule = granule;
  }
}

}  // namespace ontile
