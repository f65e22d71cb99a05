// The parameter buffer's reads, address by address, for a memory model that puts a cache in front
// of them (the GPU's L2; MemoryModel::replays_parameter_reads): every tile's reads replayed in
// tile-index order, so a triangle listed in neighbouring tiles is fetched from DRAM once while it
// stays cached.
#pragma once
#include "memory/memory_model.h"
#include "tiler/detail/parameter_buffer.h"

namespace ontile {

// The parameter buffer's simulated layout: the tile lists (4-byte entries, CSR order) from
// address 0, then the primitive records (12 bytes per set-up triangle, in chunk order), then
// each draw's post-transform vertices (16 bytes of position + 4 per varying, 2 with fp16
// varyings, by vertex index: the vertices binning wrote, shared by the triangles that index
// them), then the vertices clipping created, chunk by chunk; every region 64-byte aligned. Hands each tile's reads (its list
// entries, their records and their three vertices) to memory.parameter_read, tiles in order.
void replay_parameter_reads(const ParameterBuffer& params, const RenderPassDesc& pass, MemoryModel& memory);

}  // namespace ontile
