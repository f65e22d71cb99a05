// What a TBDR pass's attachment loads, stores and resolves cost in external memory: every tile
// moves its whole area of each attachment, uncompressed, or (with AFBC on) at the compressed
// size of the 16x16 superblocks an eligible surface holds (memory/afbc.h). Fills the pass
// report's attachments and each tile's share.
#pragma once
#include <cstdint>
#include <vector>

#include "tiler/detail/parameter_buffer.h"
#include "tiler/pass_report.h"
#include "tiler/render_pass.h"

namespace ontile {

class AttachmentPricing {
 public:
  // Before the tiles run: with afbc, loaded surfaces are measured now (their contents before the
  // pass).
  AttachmentPricing(const RenderPassDesc& pass, bool afbc);
  // After the tiles ran: fills report.attachments (one per pass attachment) and adds each
  // tile's loaded and stored bytes to report.tile_stats (a superblock is charged to the tile
  // holding its top-left pixel, so the shares sum to the pass's figures); charge_tiles false
  // leaves the tiles' shares alone (the IMR model, which has no tile memory, re-prices them).
  void price(const TileGrid& grid, PassReport& report, bool charge_tiles) const;

 private:
  struct Measured {
    std::vector<uint64_t> block_bytes;  // empty: not compressed
  };
  const RenderPassDesc& pass_;
  bool afbc_;
  std::vector<Measured> loads_;  // per attachment
};

}  // namespace ontile
