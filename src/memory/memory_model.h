// The seam between the tiler and external memory: one interface that sees everything a frame
// moves (tile loads and stores, texel accesses, parameter-buffer writes and reads, fragments)
// and prices it. TBDR and IMR are two implementations (tbdr_memory.cpp, imr_memory.cpp); the
// tiler calls the same methods for both and never asks which one it has.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "memory/imr_model.h"
#include "memory/pass_memory.h"
#include "memory/texture_cache.h"
#include "memory/texture_replay_stream.h"
#include "memory/tile_trace.h"
#include "memory/transaction_elimination.h"

namespace ontile {

struct ParameterCacheConfig {
  uint32_t size_bytes = 0;  // 0: no cache, every tile-list read is charged in full
  uint32_t ways = 16;       // 64-byte lines
};

// What binning wrote to the parameter buffer: `bytes` in all, of which the post-transform
// vertices' positions and varyings (the rest are primitive records and tile-list entries).
struct ParameterBufferWrites {
  uint64_t bytes = 0;
  uint64_t position_bytes = 0;
  uint64_t varying_bytes = 0;
};

struct MemoryConfig {
  bool immediate_mode = false;  // the IMR model (imr_model.h) instead of tile memory
  TextureCacheConfig texture_cache;
  ParameterCacheConfig parameter_cache;         // TBDR only; off by default
  RenderTargetCacheConfig render_target_cache;  // IMR only
  bool afbc = false;                            // memory/afbc.h; TBDR only
  // Transaction elimination (transaction_elimination.h): the CRCs of earlier frames' tiles,
  // shared by the frames that compare with them; null: off. TBDR only.
  std::shared_ptr<TileSignatureHistory> transaction_elimination;
};

// One frame's external memory. Pass by pass: begin_pass, then the tile events (from worker
// threads, each tile by one thread; the texel accesses replayed in tile-index order as tiles
// complete), then, after all tiles ran and in tile-index order, the fragments and parameter-buffer
// traffic, then end_pass. The texture cache keeps its contents from pass to pass within the frame.
class MemoryModel {
 public:
  explicit MemoryModel(const MemoryConfig& config);
  virtual ~MemoryModel() = default;

  // Surfaces hold what they held before the pass.
  virtual void begin_pass(const PassMemoryDesc& pass) = 0;
  // Whether tiles must record every fragment's colour and depth accesses (TileTrace::fragments).
  virtual bool records_fragments() const = 0;
  // The tile's load actions ran (tile memory holds the tile's attachments).
  virtual void tile_loaded(int tile, const TileRect& rect) = 0;
  // The tile's store actions ran: the surfaces hold the tile's new contents.
  virtual void tile_stored(int tile, const TileRect& rect) = 0;
  // The fragments the tiles recorded (records_fragments()), tiles in index order.
  virtual void fragments(const std::vector<TileTrace>& traces) = 0;
  // Binning wrote `written` to the parameter buffer; returns the bytes charged.
  virtual ParameterBufferWrites parameter_buffer_written(const ParameterBufferWrites& written) = 0;
  // Whether the parameter-buffer reads are replayed read by read (a cache in front of them):
  // then parameter_read is called for every read, tiles in index order.
  virtual bool replays_parameter_reads() const = 0;
  virtual void parameter_read(uint64_t address, uint64_t bytes) = 0;
  // The tiles read `uncached` bytes of parameter buffer; returns the bytes charged and the
  // cache's lookups (zero without a cache).
  virtual uint64_t parameter_buffer_read(uint64_t uncached, TextureTraffic& cache) = 0;
  // The pass's attachment traffic.
  virtual PassAttachmentTraffic end_pass() = 0;

  // Every tile's texel granules through the frame's texture cache (texture_cache.h), replayed
  // while the tiles run: tile_recorded as each tile ends, then finish (texture_replay_stream.h).
  // The tiles' granule buffers go back to their pool (granule_buffer_pool.h) once replayed.
  std::unique_ptr<TextureReplayStream> texel_replay(std::vector<TileTrace>& traces,
                                                    TextureReplayDetail& detail);
  const TextureCacheConfig& texture_cache_config() const { return texture_cache_.config(); }

 protected:
  MemoryConfig config_;
  TextureCache texture_cache_;
};

// The model `config` asks for. Throws ontile::Error for an invalid cache geometry.
std::unique_ptr<MemoryModel> make_memory_model(const MemoryConfig& config);

}  // namespace ontile
