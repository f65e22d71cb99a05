// The tile-based memory model (tbdr_memory.cpp): attachments move tile by tile between tile
// memory and external surfaces (with AFBC and transaction elimination when configured), and the
// parameter buffer is written by binning and read by the tiles.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "memory/memory_model.h"
#include "memory/set_associative_cache.h"

namespace ontile {

class TbdrMemory final : public MemoryModel {
 public:
  explicit TbdrMemory(const MemoryConfig& config);
  void begin_pass(const PassMemoryDesc& pass) override;
  bool records_fragments() const override { return false; }
  void tile_loaded(int tile, const TileRect& rect) override;
  void tile_stored(int tile, const TileRect& rect) override;
  void fragments(const std::vector<TileTrace>& traces) override;
  ParameterBufferWrites parameter_buffer_written(const ParameterBufferWrites& written) override;
  bool replays_parameter_reads() const override;
  void parameter_read(uint64_t address, uint64_t bytes) override;
  uint64_t parameter_buffer_read(uint64_t uncached, TextureTraffic& cache) override;
  PassAttachmentTraffic end_pass() override;

 private:
  // One surface an attachment writes (its store or its resolve), tile by tile.
  struct Write {
    bool active = false;
    uint64_t bytes_per_px = 0;           // all samples
    std::vector<uint64_t> tile_bytes;    // uncompressed, per tile
    std::vector<uint8_t> eliminated;     // per tile: TE skipped the write
    TileSignatureHistory::Table* signatures = nullptr;  // null: no TE for this write
  };
  // A colour write that could keep CRCs, and its key in the history.
  struct CrcCandidate {
    Write* write;
    std::string key;
  };
  // Gives the writes the pass's CRC rule picks (TileSignatureHistory::targets()) their tables.
  void choose_crc_writes(const std::vector<CrcCandidate>& candidates);

  PassMemoryDesc pass_;
  int pass_ordinal_ = 0;  // passes begun in this frame
  bool te_active_ = false;
  std::vector<std::array<Write, 2>> writes_;             // per attachment: store, resolve
  std::vector<std::vector<uint64_t>> load_blocks_;       // per attachment: AFBC superblocks loaded
  std::vector<std::vector<uint64_t>> tile_loaded_;       // per attachment, per tile: uncompressed
  std::unique_ptr<SetAssociativeCache> parameter_cache_;  // null: reads charged in full
  TextureTraffic parameter_traffic_;
};

}  // namespace ontile
