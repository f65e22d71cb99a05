// Batch texel fetches (see texel_fetch_batch.h).
#include "raster/texel_fetch_batch.h"

#include <bit>

#include "raster/texel_trace.h"

namespace ontile {

bool batch_fetch_view(const Texture2D& texture, Texture2D::TexelView& view) {
  if (texture.compression() != TextureCompression::None) return false;
  view = texture.texel_view(0);
  // load_texels indexes float channels as 32-bit integers (4 * texel).
  return int64_t{view.width} * view.height < (int64_t{1} << 29);
}

void trace_fetches(const Texture2D::TexelView* views, int texture_count, const int32_t* x, const int32_t* y,
                   int fragment_count, const uint64_t* fetched) {
  std::vector<uint64_t>* const sink = texel_trace_detail::sink;
  if (!sink) return;
  uint64_t any = 0;
  for (int k = 0; k < texture_count; ++k) any |= fetched[k];
  if (fragment_count < 64) any &= (uint64_t{1} << fragment_count) - 1;
  // record_texel_address per fetch, staged and appended a few hundred granules at a time.
  constexpr int kCapacity = 256;
  uint64_t granules[kCapacity];
  int count = 0;
  uint64_t last = texel_trace_detail::last_granule;
  for (uint64_t rest = any; rest != 0; rest &= rest - 1) {
    const int f = std::countr_zero(rest);
    if (count + texture_count > kCapacity) {
      sink->insert(sink->end(), granules, granules + count);
      count = 0;
    }
    for (int k = 0; k < texture_count; ++k) {
      if (!((fetched[k] >> f) & 1u)) continue;
      const Texture2D::TexelView& view = views[k];
      const uint64_t index = static_cast<uint64_t>(y[f]) * static_cast<uint64_t>(view.width) +
                             static_cast<uint64_t>(x[f]);
      const uint64_t granule = (view.address + index * view.memory_bytes_per_texel) >> 6;
      granules[count] = granule;
      count += granule != last;
      last = granule;
    }
  }
  sink->insert(sink->end(), granules, granules + count);
  texel_trace_detail::last_granule = last;
}

}  // namespace ontile
