// Attachment traffic of a TBDR pass (see attachment_pricing.h).
#include "tiler/detail/attachment_pricing.h"

#include <algorithm>
#include <numeric>

#include "memory/afbc.h"

namespace ontile {
namespace {

bool loads(const AttachmentDesc& d) { return d.load == LoadAction::Load && d.surface; }
bool stores(const AttachmentDesc& d) {
  return (d.store == StoreAction::Store || d.store == StoreAction::StoreAndResolve) && d.surface;
}
bool resolves(const AttachmentDesc& d) {
  return (d.store == StoreAction::Resolve || d.store == StoreAction::StoreAndResolve) && d.resolve_surface;
}

// The superblock sizes of `surface` when AFBC compresses it, else empty.
std::vector<uint64_t> measure(const Surface* surface, bool afbc) {
  if (!afbc || !surface || !afbc_compresses(surface->format(), surface->samples())) return {};
  return afbc_block_bytes(surface->format(), surface->pixel_bytes(0, 0), surface->width(), surface->height(),
                          static_cast<size_t>(surface->width()) * bytes_per_pixel(surface->format()));
}

uint64_t sum(const std::vector<uint64_t>& v) { return std::accumulate(v.begin(), v.end(), uint64_t{0}); }

// Adds each superblock's bytes to the tile holding its top-left pixel.
void charge_blocks(const std::vector<uint64_t>& blocks, const TileGrid& grid, bool stored, PassReport& report) {
  const int blocks_x = (grid.width_px + kAfbcBlockPx - 1) / kAfbcBlockPx;
  for (size_t b = 0; b < blocks.size(); ++b) {
    const int x = static_cast<int>(b % blocks_x) * kAfbcBlockPx;
    const int y = static_cast<int>(b / blocks_x) * kAfbcBlockPx;
    TileStats& tile = report.tile_stats[(y / grid.tile_height_px) * grid.tiles_x() + x / grid.tile_width_px];
    (stored ? tile.bytes_stored : tile.bytes_loaded) += blocks[b];
  }
}

// Adds `bytes_per_sample_px` times each tile's samples to its loaded or stored bytes.
void charge_area(uint64_t bytes_per_px, const TileGrid& grid, bool stored, PassReport& report) {
  for (int tile = 0; tile < grid.tile_count(); ++tile) {
    const int x0 = (tile % grid.tiles_x()) * grid.tile_width_px;
    const int y0 = (tile / grid.tiles_x()) * grid.tile_height_px;
    const uint64_t pixels = static_cast<uint64_t>(std::min(grid.tile_width_px, grid.width_px - x0)) *
                            static_cast<uint64_t>(std::min(grid.tile_height_px, grid.height_px - y0));
    TileStats& stats = report.tile_stats[tile];
    (stored ? stats.bytes_stored : stats.bytes_loaded) += pixels * bytes_per_px;
  }
}

}  // namespace

AttachmentPricing::AttachmentPricing(const RenderPassDesc& pass, bool afbc) : pass_(pass), afbc_(afbc) {
  loads_.resize(pass.attachments.size());
  for (size_t a = 0; a < pass.attachments.size(); ++a) {
    const AttachmentDesc& d = pass.attachments[a];
    if (loads(d)) loads_[a].block_bytes = measure(d.surface, afbc);
  }
}

void AttachmentPricing::price(const TileGrid& grid, PassReport& report, bool charge_tiles) const {
  const uint64_t pixels = static_cast<uint64_t>(pass_.width_px) * pass_.height_px;
  // One load, store or resolve of `blocks` (compressed) or of `bytes_per_px` per pixel: its
  // bytes, the saving, and the tiles' shares.
  const auto move = [&](const std::vector<uint64_t>& blocks, uint64_t bytes_per_px, bool stored,
                        AttachmentTraffic& t) {
    const uint64_t uncompressed = pixels * bytes_per_px;
    const uint64_t bytes = blocks.empty() ? uncompressed : sum(blocks);
    t.afbc = t.afbc || !blocks.empty();
    t.afbc_bytes_saved += static_cast<int64_t>(uncompressed) - static_cast<int64_t>(bytes);
    if (charge_tiles && blocks.empty()) charge_area(bytes_per_px, grid, stored, report);
    if (charge_tiles && !blocks.empty()) charge_blocks(blocks, grid, stored, report);
    return bytes;
  };
  for (size_t a = 0; a < pass_.attachments.size(); ++a) {
    const AttachmentDesc& d = pass_.attachments[a];
    AttachmentTraffic t;
    t.name = d.name;
    t.format = d.format;
    t.transient = d.surface == nullptr;
    const uint64_t sample_bytes_per_px = static_cast<uint64_t>(pass_.samples) * bytes_per_pixel(d.format);
    if (loads(d)) t.bytes_loaded = move(loads_[a].block_bytes, sample_bytes_per_px, false, t);
    if (stores(d)) t.bytes_stored = move(measure(d.surface, afbc_), sample_bytes_per_px, true, t);
    if (resolves(d)) t.bytes_resolved = move(measure(d.resolve_surface, afbc_), bytes_per_pixel(d.format), true, t);
    report.attachments.push_back(t);
  }
}

}  // namespace ontile
