// The texture cache model (see texture_cache.h): config validation and the placement of texture
// regions in the frame's address space.
#include "memory/texture_cache.h"

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

const TextureCacheConfig& validated(const TextureCacheConfig& config) {
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
  return config;
}

}  // namespace

TextureCache::TextureCache(const TextureCacheConfig& config)
    : config_(validated(config)),
      cache_(static_cast<uint32_t>(config.size_bytes / (uint64_t{config.line_bytes} * config.ways)),
             config.ways, std::countr_zero(config.line_bytes / kGranuleBytes)) {}

uint64_t TextureCache::frame_base_granule(uint64_t id) {
  auto it = frame_base_granule_.find(id);
  if (it == frame_base_granule_.end()) {
    // Frame-local placement starts above the id-0 range so the two never overlap.
    if (next_frame_granule_ == 0) next_frame_granule_ = uint64_t{1} << kRegionShiftGranules;
    it = frame_base_granule_.emplace(id, next_frame_granule_).first;
    next_frame_granule_ += (Texture2D::reserved_bytes_of(id) + 63) / 64;
    if (next_frame_granule_ > kFrameGranuleLimit) {
      throw Error("texture regions of one frame exceed " +
                  std::to_string(kFrameGranuleLimit * 64 >> 40) + " TiB");
    }
  }
  return it->second;
}

uint64_t TextureCache::place(uint64_t id) {
  if (id == 0) return 0;
  return frame_base_granule(id) - (id << kRegionShiftGranules);
}

uint64_t TextureCache::placed_offset(uint64_t id) const {
  if (id == 0) return 0;
  const auto it = frame_base_granule_.find(id);
  if (it == frame_base_granule_.end()) {
    throw Error("texture region " + std::to_string(id) + " was never placed in this frame");
  }
  return it->second - (id << kRegionShiftGranules);
}

}  // namespace ontile
