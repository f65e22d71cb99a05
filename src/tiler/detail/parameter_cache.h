// An optional cache model for the fragment phase's parameter-buffer reads (a GPU's L2 in front
// of the tile lists and post-transform vertex data): every tile's reads replayed in tile-index
// order through a set-associative LRU, so a triangle listed in neighbouring tiles is fetched
// from DRAM once while it stays cached. Off by default (every read goes to DRAM).
#pragma once
#include <cstdint>

#include "tiler/detail/parameter_buffer.h"
#include "tiler/detail/texture_cache.h"

namespace ontile {

struct ParameterCacheConfig {
  uint32_t size_bytes = 0;  // 0: no cache, every tile-list read is charged in full
  uint32_t ways = 16;       // 64-byte lines
};

// The parameter buffer's simulated layout: the tile lists (4-byte entries, CSR order) from
// address 0, then the primitive records (12 bytes per set-up triangle, in chunk order), then
// each draw's post-transform vertices (16 + 4 per varying bytes each, 2 with fp16 varyings, by vertex index: the
// vertices binning wrote, shared by the triangles that index them), then the vertices clipping
// created, chunk by chunk; every region 64-byte aligned. Returns the lookups of the 64-byte granules each tile reads; bytes_read =
// misses x 64. Throws ontile::Error for an invalid cache geometry.
TextureTraffic replay_parameter_reads(const ParameterBuffer& params, const RenderPassDesc& pass,
                                      const ParameterCacheConfig& config);

}  // namespace ontile
