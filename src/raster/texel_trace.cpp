// Thread-local texel trace sink (see texel_trace.h).
#include "raster/texel_trace.h"

namespace ontile {
namespace texel_trace_detail {
constinit thread_local std::vector<uint64_t>* sink = nullptr;
constinit thread_local uint64_t last_granule = ~uint64_t{0};
}  // namespace texel_trace_detail

TexelTraceScope::TexelTraceScope(std::vector<uint64_t>* granules)
    : previous_(texel_trace_detail::sink), previous_last_(texel_trace_detail::last_granule) {
  texel_trace_detail::sink = granules;
  texel_trace_detail::last_granule = ~uint64_t{0};
}

TexelTraceScope::~TexelTraceScope() {
  texel_trace_detail::sink = previous_;
  texel_trace_detail::last_granule = previous_last_;
}

}  // namespace ontile
