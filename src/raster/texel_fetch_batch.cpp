// Batch texel fetches (see texel_fetch_batch.h).
#include "raster/texel_fetch_batch.h"

#include <bit>
#include <cstdint>

#include "raster/texel_trace.h"

namespace ontile {

namespace {

// A fetched texture's address terms: granule = (address + texel index * bytes) / 64.
struct FetchPlane {
  uint64_t address = 0, bytes = 0;
};

// trace_fetches' walk for kTextures textures of one width (a G-buffer): the texel index once
// per fragment and the planes and masks in locals, so a fetch costs a multiply, an add, a
// shift, a store and a compare. Returns how many granules it wrote (at most 64 * kTextures).
template <int kTextures>
int fetch_granules(const Texture2D::TexelView* views, const int32_t* x, const int32_t* y, uint64_t any,
                   const uint64_t* fetched, uint64_t* granules, uint64_t& last_granule) {
  FetchPlane planes[kTextures];
  uint64_t masks[kTextures];
  for (int k = 0; k < kTextures; ++k) {
    planes[k] = {views[k].address, views[k].memory_bytes_per_texel};
    masks[k] = fetched[k];
  }
  const uint64_t width = static_cast<uint64_t>(views[0].width);
  // Textures whose granule ranges are pairwise disjoint never repeat a granule from one
  // texture to the next: a fragment fetching every texture compares its first fetch only.
  bool disjoint = true;
  uint64_t first_granule[kTextures], last_granule_of[kTextures];
  for (int k = 0; k < kTextures; ++k) {
    const uint64_t bytes = static_cast<uint64_t>(views[k].width) * static_cast<uint64_t>(views[k].height) *
                           views[k].memory_bytes_per_texel;
    first_granule[k] = views[k].address >> 6;
    last_granule_of[k] = (views[k].address + (bytes == 0 ? 0 : bytes - 1)) >> 6;
    for (int j = 0; j < k; ++j) {
      if (first_granule[k] <= last_granule_of[j] && first_granule[j] <= last_granule_of[k]) disjoint = false;
    }
  }
  uint64_t every = disjoint ? ~uint64_t{0} : 0;  // bit f: fragment f fetches every texture
  for (int k = 0; k < kTextures; ++k) every &= masks[k];
  uint64_t last = last_granule;
  int count = 0;
  for (uint64_t rest = any; rest != 0; rest &= rest - 1) {
    const int f = std::countr_zero(rest);
    const uint64_t index = static_cast<uint64_t>(y[f]) * width + static_cast<uint64_t>(x[f]);
    if ((every >> f) & 1u) {
      const uint64_t first = (planes[0].address + index * planes[0].bytes) >> 6;
      granules[count] = first;
      count += first != last;
      last = first;
      for (int k = 1; k < kTextures; ++k) {
        last = (planes[k].address + index * planes[k].bytes) >> 6;
        granules[count++] = last;
      }
      continue;
    }
    for (int k = 0; k < kTextures; ++k) {
      if (!((masks[k] >> f) & 1u)) continue;
      const uint64_t granule = (planes[k].address + index * planes[k].bytes) >> 6;
      granules[count] = granule;
      count += granule != last;
      last = granule;
    }
  }
  last_granule = last;
  return count;
}

}  // namespace

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
  bool one_width = true;
  for (int k = 1; k < texture_count; ++k) one_width = one_width && views[k].width == views[0].width;
  if (one_width && texture_count >= 1 && texture_count <= 4) {
    // At most 64 fragments (the masks' bits) of up to 4 fetches: the buffer holds them all.
    static_assert(kCapacity >= 4 * 64);
    uint64_t last = texel_trace_detail::last_granule;
    int count = 0;
    switch (texture_count) {
      case 1: count = fetch_granules<1>(views, x, y, any, fetched, granules, last); break;
      case 2: count = fetch_granules<2>(views, x, y, any, fetched, granules, last); break;
      case 3: count = fetch_granules<3>(views, x, y, any, fetched, granules, last); break;
      default: count = fetch_granules<4>(views, x, y, any, fetched, granules, last); break;
    }
    sink->insert(sink->end(), granules, granules + count);
    texel_trace_detail::last_granule = last;
    return;
  }
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
