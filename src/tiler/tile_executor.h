// Runs one screen tile of a render pass: loads its attachments into tile memory, replays the
// tile's primitive list through rasterization, depth test, shading and blending, then stores.
#pragma once
#include "tiler/parameter_buffer.h"
#include "tiler/render_pass.h"
#include "tiler/tile_memory.h"
#include "tiler/tile_trace.h"

namespace ontile {

// Texture fetches are traced into trace.texture_granules; with record_fragments every
// fragment's colour/depth accesses go to trace.fragments (for the IMR model). hierarchical_z
// lets early-Z draws skip cells proven occluded (same results, less work).
void execute_tile(const RenderPassDesc& pass, const ParameterBuffer& params, int tile_index,
                  TileMemory& memory, TileCounters& counters, TileTrace& trace,
                  bool record_fragment_accesses, bool hierarchical_z = true);

}  // namespace ontile
