// The texture cache model (see texture_cache.h): config validation, set-associative LRU lookup,
// and the replay of the tiles' texture granules in tile-index order.
#include "tiler/texture_cache.h"

#include "raster/texture.h"

#include <bit>
#include <string>

#include "util/error.h"

static_assert(ontile::TextureCache::kRegionShiftGranules == ontile::Texture2D::kTextureIdShift - 6);

namespace ontile {
namespace {

// The trace records 64-byte granules (raster/texel_trace.h), so a line holds a whole number
// of them.
constexpr uint32_t kGranuleBytes = 64;
constexpr uint64_t kEmptyWay = ~uint64_t{0};

void validate(const TextureCacheConfig& config) {
  const std::string where = "texture cache config: ";
  if (config.line_bytes < kGranuleBytes || !std::has_single_bit(config.line_bytes)) {
    throw Error(where + "line_bytes " + std::to_string(config.line_bytes) +
                " must be a power of two >= 64");
  }
  if (config.ways < 1) throw Error(where + "ways must be >= 1 (got 0)");
  const uint64_t set_bytes = uint64_t{config.line_bytes} * config.ways;
  if (config.size_bytes == 0 || config.size_bytes % set_bytes != 0) {
    throw Error(where + "size_bytes " + std::to_string(config.size_bytes) +
                " must be a positive multiple of line_bytes x ways (" +
                std::to_string(set_bytes) + ")");
  }
}

}  // namespace

void TextureTraffic::add(const TextureTraffic& o) {
  accesses += o.accesses;
  hits += o.hits;
  misses += o.misses;
  bytes_read += o.bytes_read;
}

TextureCache::TextureCache(const TextureCacheConfig& config) : config_(config) {
  validate(config_);
  sets_ = static_cast<uint32_t>(config_.size_bytes / (uint64_t{config_.line_bytes} * config_.ways));
  tags_.assign(static_cast<size_t>(sets_) * config_.ways, kEmptyWay);
}

// Mapping (plain modulo, no hashing, so tests can place lines in sets by hand):
//   line = granule / (line_bytes / 64), set = line % sets, tag = line.
// Keeping the whole line number as the tag makes a hit unambiguous whatever the set count.
// Replacement is LRU: each set keeps its lines ordered from most to least recently used, so a
// hit moves its line to the front and a miss drops the last (least recent or empty) way. Hits
// are found after a few compares, since texture streams reuse the lines they just touched.
bool TextureCache::access(uint64_t granule) {
  const uint64_t line = granule >> std::countr_zero(config_.line_bytes / kGranuleBytes);
  uint64_t* set = tags_.data() + static_cast<size_t>(line % sets_) * config_.ways;
  const uint32_t ways = config_.ways;
  uint32_t position = 0;
  while (position < ways && set[position] != line) ++position;
  const bool hit = position < ways;
  if (!hit) position = ways - 1;  // evict the least recently used (or an empty) way
  for (uint32_t i = position; i > 0; --i) set[i] = set[i - 1];
  set[0] = line;
  return hit;
}

uint64_t TextureCache::frame_base_granule(uint64_t id) {
  if (id == last_id_) return last_base_granule_;
  auto it = frame_base_granule_.find(id);
  if (it == frame_base_granule_.end()) {
    // Frame-local placement starts above the id-0 range so the two never overlap.
    if (next_frame_granule_ == 0) next_frame_granule_ = uint64_t{1} << kRegionShiftGranules;
    it = frame_base_granule_.emplace(id, next_frame_granule_).first;
    next_frame_granule_ += (Texture2D::reserved_bytes_of(id) + 63) / 64;
  }
  last_id_ = id;
  last_base_granule_ = it->second;
  return it->second;
}

uint64_t TextureCache::frame_granule(uint64_t traced_granule) {
  const uint64_t id = traced_granule >> kRegionShiftGranules;
  if (id == 0) return traced_granule;
  return frame_base_granule(id) + (traced_granule & ((uint64_t{1} << kRegionShiftGranules) - 1));
}

uint32_t TextureCache::set_of(uint64_t frame_granule) const {
  const uint64_t line = frame_granule >> std::countr_zero(config_.line_bytes / kGranuleBytes);
  return static_cast<uint32_t>(line % sets_);
}

}  // namespace ontile
