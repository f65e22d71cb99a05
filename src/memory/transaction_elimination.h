// Transaction elimination (Arm Mali): at the end of a tile the GPU computes a CRC of each colour
// tile it is about to write and skips the write when the CRC equals the one stored for the same
// tile of the same surface in the previous frame (the surface in memory already holds those
// pixels). Like panfrost (pan_select_crc_rt, src/panfrost/lib/pan_desc.c) it needs 16x16 tiles.
// This file keeps the CRCs from frame to frame.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "memory/pass_memory.h"

namespace ontile {

constexpr int kTransactionEliminationTilePx = 16;  // the CRC tile (Arm; panfrost)

// The CRC of every tile of every written surface, by a key naming the write (the pass's position
// in its frame, the pass, the attachment and store or resolve), carried from one frame to the
// next. Not thread-safe: tables are looked up between passes; during a pass each tile's slot is
// written by the one thread that runs the tile.
class TileSignatureHistory {
 public:
  struct Table {
    std::vector<uint32_t> crc;
    std::vector<uint8_t> valid;  // 0 until a frame wrote the tile
  };
  // The table of `key` with `tiles` slots (emptied when the tile count changed).
  Table& table(const std::string& key, int tiles);
  size_t size() const { return tables_.size(); }

 private:
  std::map<std::string, Table> tables_;
};

// zlib's CRC-32 of the tile's bytes in `surface`, row by row (all samples of each pixel).
uint32_t tile_crc(const SurfaceBytes& surface, const TileRect& rect);

// Compares the tile's CRC with the previous frame's and records the new one; true when equal
// (the write is eliminated).
bool eliminate_tile_write(TileSignatureHistory::Table& table, int tile, uint32_t crc);

}  // namespace ontile
