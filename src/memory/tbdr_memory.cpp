// The tile-based (TBDR) memory model: every tile moves its whole area of each loaded, stored or
// resolved attachment, uncompressed, or (with AFBC) at the compressed size of the 16x16
// superblocks the surface holds (afbc.h); with transaction elimination a tile write whose CRC
// equals the previous frame's costs nothing (transaction_elimination.h). The parameter buffer is
// written by binning and read by the tiles, optionally through a read cache (the GPU's L2).
#include <algorithm>
#include <numeric>
#include <string>

#include "memory/afbc.h"
#include "memory/memory_model.h"
#include "memory/set_associative_cache.h"
#include "memory/tbdr_memory.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr uint64_t kParameterLineBytes = 64;

uint64_t sum(const std::vector<uint64_t>& v) { return std::accumulate(v.begin(), v.end(), uint64_t{0}); }

// The superblock sizes of `surface` when AFBC compresses it, else empty.
std::vector<uint64_t> measure(const SurfaceBytes& surface, bool afbc) {
  if (!afbc || !surface || !afbc_compresses(surface.format, surface.samples)) return {};
  return afbc_block_bytes(surface.format, surface.bytes, surface.width, surface.height, surface.row_bytes);
}

uint64_t tile_pixels(const TileRect& rect) {
  return static_cast<uint64_t>(rect.width) * static_cast<uint64_t>(rect.height);
}

}  // namespace

TbdrMemory::TbdrMemory(const MemoryConfig& config) : MemoryModel(config) {
  const ParameterCacheConfig& c = config.parameter_cache;
  if (c.size_bytes > 0 && (c.ways == 0 || c.size_bytes % (kParameterLineBytes * c.ways) != 0)) {
    throw Error("parameter cache: size_bytes " + std::to_string(c.size_bytes) +
                " must be a positive multiple of 64-byte lines x ways (" + std::to_string(c.ways) + ")");
  }
}

void TbdrMemory::begin_pass(const PassMemoryDesc& pass) {
  pass_ = pass;
  ++pass_ordinal_;
  const size_t attachments = pass.attachments.size();
  const auto tiles = static_cast<size_t>(pass.tile_count());
  writes_.assign(attachments, {});
  load_blocks_.assign(attachments, {});
  tile_loaded_.assign(attachments, std::vector<uint64_t>(tiles, 0));
  // TE compares 16x16 tiles only (panfrost, pan_select_crc_rt): a pass whose tiles the colour
  // budget made smaller writes every tile.
  te_active_ = config_.transaction_elimination && pass.tile_width_px == kTransactionEliminationTilePx &&
               pass.tile_height_px == kTransactionEliminationTilePx;
  std::vector<CrcCandidate> crc_candidates;  // attachment order, as the descriptor's render targets
  for (size_t a = 0; a < attachments; ++a) {
    const AttachmentMemory& d = pass.attachments[a];
    // AFBC prices loads at the size of the surfaces' contents before the pass.
    if (d.loads) load_blocks_[a] = measure(d.surface, config_.afbc);
    for (int kind = 0; kind < 2; ++kind) {
      const bool resolve = kind == 1;
      const SurfaceBytes& target = resolve ? d.resolve_surface : d.surface;
      if (!(resolve ? d.resolves && d.resolve_surface : d.stores)) continue;
      Write& w = writes_[a][kind];
      w.active = true;
      w.bytes_per_px = static_cast<uint64_t>(target.samples) * bytes_per_pixel(d.format);
      w.tile_bytes.assign(tiles, 0);
      w.eliminated.assign(tiles, 0);
      // Like Mali, TE covers single-sample colour writes.
      if (te_active_ && !d.is_depth && target.samples == 1) {
        crc_candidates.push_back({&w, std::to_string(pass_ordinal_) + "/" + pass.name + "/" + d.name +
                                          (resolve ? "/resolve" : "/store")});
      }
    }
  }
  if (!crc_candidates.empty()) choose_crc_writes(crc_candidates);
  parameter_traffic_ = TextureTraffic{};
  parameter_cache_.reset();
  if (config_.parameter_cache.size_bytes > 0) {
    const uint32_t ways = config_.parameter_cache.ways;
    parameter_cache_ = std::make_unique<SetAssociativeCache>(
        static_cast<uint32_t>(config_.parameter_cache.size_bytes / (kParameterLineBytes * ways)), ways, 0);
  }
}

void TbdrMemory::choose_crc_writes(const std::vector<CrcCandidate>& candidates) {
  TileSignatureHistory& history = *config_.transaction_elimination;
  std::vector<bool> chosen(candidates.size(), false);
  switch (history.targets()) {
    case CrcTargets::EveryTarget:
      chosen.assign(candidates.size(), true);
      break;
    case CrcTargets::SingleTargetPasses: {
      // PAN_ARCH <= 6: CRCs only when the framebuffer has one colour render target.
      int color_attachments = 0;
      for (const AttachmentMemory& d : pass_.attachments) color_attachments += d.is_depth ? 0 : 1;
      if (color_attachments == 1) chosen.assign(candidates.size(), true);
      break;
    }
    case CrcTargets::OnePerPass: {
      // PAN_ARCH >= 7: the first render target whose CRCs are valid, else the first one (every
      // ontile pass renders its whole framebuffer, the descriptor's other condition).
      size_t pick = 0;
      for (size_t i = 0; i < candidates.size(); ++i) {
        if (history.valid(candidates[i].key)) {
          pick = i;
          break;
        }
      }
      chosen[pick] = true;  // candidates is never empty here
      break;
    }
  }
  const int tiles = pass_.tile_count();
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (chosen[i]) {
      candidates[i].write->signatures = &history.table(candidates[i].key, tiles);
    } else {
      history.invalidate(candidates[i].key);  // written without CRCs: the old ones are stale
    }
  }
}

void TbdrMemory::tile_loaded(int tile, const TileRect& rect) {
  for (size_t a = 0; a < pass_.attachments.size(); ++a) {
    const AttachmentMemory& d = pass_.attachments[a];
    if (!d.loads) continue;
    tile_loaded_[a][tile] = tile_pixels(rect) * static_cast<uint64_t>(pass_.samples) * bytes_per_pixel(d.format);
  }
}

void TbdrMemory::tile_stored(int tile, const TileRect& rect) {
  for (size_t a = 0; a < pass_.attachments.size(); ++a) {
    const AttachmentMemory& d = pass_.attachments[a];
    for (int kind = 0; kind < 2; ++kind) {
      Write& w = writes_[a][kind];
      if (!w.active) continue;
      w.tile_bytes[tile] = tile_pixels(rect) * w.bytes_per_px;
      if (w.signatures) {
        const SurfaceBytes& target = kind == 1 ? d.resolve_surface : d.surface;
        w.eliminated[tile] = eliminate_tile_write(*w.signatures, tile, tile_crc(target, rect)) ? 1 : 0;
      }
    }
  }
}

void TbdrMemory::fragments(const std::vector<TileTrace>&) {}

ParameterBufferWrites TbdrMemory::parameter_buffer_written(const ParameterBufferWrites& written) {
  return written;
}

bool TbdrMemory::replays_parameter_reads() const { return parameter_cache_ != nullptr; }

void TbdrMemory::parameter_read(uint64_t address, uint64_t bytes) {
  for (uint64_t line = address / kParameterLineBytes; line <= (address + bytes - 1) / kParameterLineBytes; ++line) {
    ++parameter_traffic_.accesses;
    if (parameter_cache_->access_line(line)) {
      ++parameter_traffic_.hits;
    } else {
      ++parameter_traffic_.misses;
    }
  }
}

uint64_t TbdrMemory::parameter_buffer_read(uint64_t uncached, TextureTraffic& cache) {
  if (!parameter_cache_) {
    cache = TextureTraffic{};
    return uncached;
  }
  parameter_traffic_.bytes_read = parameter_traffic_.misses * kParameterLineBytes;
  cache = parameter_traffic_;
  return parameter_traffic_.bytes_read;
}

PassAttachmentTraffic TbdrMemory::end_pass() {
  PassAttachmentTraffic out;
  out.architecture = "tbdr";
  out.transaction_elimination = te_active_;
  const auto tiles = static_cast<size_t>(pass_.tile_count());
  out.tile_bytes_loaded.assign(tiles, 0);
  out.tile_bytes_stored.assign(tiles, 0);
  const uint64_t pixels = static_cast<uint64_t>(pass_.width_px) * pass_.height_px;
  const int blocks_x = (pass_.width_px + kAfbcBlockPx - 1) / kAfbcBlockPx;
  // The tile holding superblock b's top-left pixel.
  const auto tile_of_block = [&](size_t b) {
    const int x = static_cast<int>(b % blocks_x) * kAfbcBlockPx;
    const int y = static_cast<int>(b / blocks_x) * kAfbcBlockPx;
    return static_cast<size_t>((y / pass_.tile_height_px) * pass_.tiles_x() + x / pass_.tile_width_px);
  };
  for (size_t a = 0; a < pass_.attachments.size(); ++a) {
    const AttachmentMemory& d = pass_.attachments[a];
    AttachmentTraffic t;
    t.name = d.name;
    t.format = d.format;
    t.transient = d.transient();
    if (d.loads) {
      const std::vector<uint64_t>& blocks = load_blocks_[a];
      const uint64_t uncompressed = pixels * static_cast<uint64_t>(pass_.samples) * bytes_per_pixel(d.format);
      t.bytes_loaded = blocks.empty() ? uncompressed : sum(blocks);
      t.afbc = !blocks.empty();
      t.afbc_bytes_saved += static_cast<int64_t>(uncompressed) - static_cast<int64_t>(t.bytes_loaded);
      for (size_t b = 0; b < blocks.size(); ++b) out.tile_bytes_loaded[tile_of_block(b)] += blocks[b];
      if (blocks.empty()) {
        for (size_t tile = 0; tile < tiles; ++tile) out.tile_bytes_loaded[tile] += tile_loaded_[a][tile];
      }
    }
    for (int kind = 0; kind < 2; ++kind) {
      const Write& w = writes_[a][kind];
      if (!w.active) continue;
      const std::vector<uint64_t> blocks = measure(kind == 1 ? d.resolve_surface : d.surface, config_.afbc);
      const uint64_t uncompressed = pixels * w.bytes_per_px;
      // A tile's share: its superblocks (TE needs 16x16 tiles, one superblock each) or its area.
      std::vector<uint64_t> share = w.tile_bytes;
      if (!blocks.empty()) {
        std::fill(share.begin(), share.end(), 0);
        for (size_t b = 0; b < blocks.size(); ++b) share[tile_of_block(b)] += blocks[b];
      }
      const uint64_t priced = sum(share);
      uint64_t written = 0;
      for (size_t tile = 0; tile < tiles; ++tile) {
        if (w.eliminated[tile]) {
          ++t.te_tiles_eliminated;
          t.te_bytes_saved += share[tile];
          continue;
        }
        written += share[tile];
        out.tile_bytes_stored[tile] += share[tile];
      }
      t.afbc = t.afbc || !blocks.empty();
      t.afbc_bytes_saved += static_cast<int64_t>(uncompressed) - static_cast<int64_t>(priced);
      (kind == 1 ? t.bytes_resolved : t.bytes_stored) = written;
    }
    out.attachments.push_back(t);
  }
  return out;
}

}  // namespace ontile
