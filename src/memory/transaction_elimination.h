// Transaction elimination (Arm Mali): at the end of a tile the GPU computes a CRC of each colour
// tile it is about to write and skips the write when the CRC equals the one stored for the same
// tile of the same surface in the previous frame (the surface in memory already holds those
// pixels). Like panfrost (pan_select_crc_rt, src/panfrost/lib/pan_desc.c) it needs 16x16 tiles.
// This file keeps the CRCs from frame to frame and says which of a pass's writes carry one.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "memory/pass_memory.h"

namespace ontile {

constexpr int kTransactionEliminationTilePx = 16;  // the CRC tile (Arm; panfrost)

// Which colour writes of a pass keep CRCs. A Mali framebuffer descriptor has one CRC buffer
// (MALI_ZS_CRC_EXTENSION: crc_base, crc_row_stride and, from Bifrost v7, crc_render_target), so
// the hardware compares one render target per pass; Mesa's pan_select_crc_rt chooses it.
enum class CrcTargets {
  // Bifrost v7 and later (Mali-G76, G52, G31): the first single-sample colour write of the pass,
  // preferring one whose CRCs the previous frame left valid (pan_select_crc_rt, PAN_ARCH >= 7).
  OnePerPass,
  // Bifrost v6 and Midgard (Mali-G71, G72): only a pass with exactly one colour attachment
  // (pan_select_crc_rt, PAN_ARCH <= 6: rt_count == 1).
  SingleTargetPasses,
  // Every single-sample colour write (Arm's description of the feature, not a real descriptor).
  EveryTarget,
};

// The CLI's names: "on" (OnePerPass), "single-target-passes", "every-target"; nullptr when unknown.
const char* crc_targets_name(CrcTargets targets);
const CrcTargets* parse_crc_targets(const std::string& name);
std::vector<std::string> crc_targets_names();  // in the order of the enum

// The CRC of every tile of every written surface, by a key naming the write (the pass's position
// in its frame, the pass, the attachment and store or resolve), carried from one frame to the
// next. Not thread-safe: tables are looked up between passes; during a pass each tile's slot is
// written by the one thread that runs the tile.
class TileSignatureHistory {
 public:
  explicit TileSignatureHistory(CrcTargets targets = CrcTargets::OnePerPass) : targets_(targets) {}
  CrcTargets targets() const { return targets_; }

  struct Table {
    std::vector<uint32_t> crc;
    std::vector<uint8_t> valid;  // 0 until a frame wrote the tile
  };
  // The table of `key` with `tiles` slots (emptied when the tile count changed).
  Table& table(const std::string& key, int tiles);
  // Whether a frame left valid CRCs for `key` (the descriptor's crc_valid).
  bool valid(const std::string& key) const;
  // The write of `key` went to memory without CRCs: the ones kept are stale.
  void invalidate(const std::string& key);
  size_t size() const { return tables_.size(); }

 private:
  CrcTargets targets_;
  std::map<std::string, Table> tables_;
};

// zlib's CRC-32 of the tile's bytes in `surface`, row by row (all samples of each pixel).
uint32_t tile_crc(const SurfaceBytes& surface, const TileRect& rect);

// Compares the tile's CRC with the previous frame's and records the new one; true when equal
// (the write is eliminated).
bool eliminate_tile_write(TileSignatureHistory::Table& table, int tile, uint32_t crc);

}  // namespace ontile
