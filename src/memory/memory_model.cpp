// The memory-model seam (see memory_model.h): the parts both models share, and the factory.
#include "memory/memory_model.h"

#include <algorithm>

#include "memory/imr_memory.h"
#include "memory/tbdr_memory.h"

namespace ontile {

void TextureTraffic::add(const TextureTraffic& o) {
  accesses += o.accesses;
  hits += o.hits;
  misses += o.misses;
  bytes_read += o.bytes_read;
}

TileRect PassMemoryDesc::tile_rect(int tile) const {
  TileRect rect;
  rect.x0 = (tile % tiles_x()) * tile_width_px;
  rect.y0 = (tile / tiles_x()) * tile_height_px;
  rect.width = std::min(tile_width_px, width_px - rect.x0);
  rect.height = std::min(tile_height_px, height_px - rect.y0);
  return rect;
}

MemoryModel::MemoryModel(const MemoryConfig& config) : config_(config), texture_cache_(config.texture_cache) {}

std::unique_ptr<TextureReplayStream> MemoryModel::texel_replay(std::vector<TileTrace>& traces,
                                                               TextureReplayDetail& detail) {
  return std::make_unique<TextureReplayStream>(texture_cache_, traces, detail,
                                               TextureReplayStream::GiveBackBuffers{});
}

std::unique_ptr<MemoryModel> make_memory_model(const MemoryConfig& config) {
  if (config.immediate_mode) return std::make_unique<ImrMemory>(config);
  return std::make_unique<TbdrMemory>(config);
}

}  // namespace ontile
