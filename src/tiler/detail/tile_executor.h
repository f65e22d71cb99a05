// Runs one screen tile of a render pass: loads its attachments into tile memory, replays the
// tile's primitive list through rasterization, depth test, shading and blending, then stores.
#pragma once
#include <cstdint>
#include <vector>

#include "memory/memory_model.h"
#include "tiler/detail/parameter_buffer.h"
#include "tiler/render_pass.h"
#include "tiler/detail/tile_memory.h"
#include "memory/tile_trace.h"

namespace ontile {

// Texture fetches are traced: appended to trace.texture_granules (the tile's own). The external
// memory model hears of the tile's loads and stores, and when it records fragments every
// fragment's colour/depth accesses go to trace.fragments. hierarchical_z lets early-Z draws skip
// cells proven occluded (same results, less work).
void execute_tile(const RenderPassDesc& pass, const ParameterBuffer& params, int tile_index,
                  TileMemory& memory, TileCounters& counters, TileTrace& trace,
                  MemoryModel& external, bool hierarchical_z = true);

// Whole covered quad rows (both pixel rows of a cell's quad row covered and passing at one
// sample per pixel: full-screen triangles, large triangles) are queued as whole quads without
// per-quad coverage work. On by default; tests turn it off to compare with the per-quad walk
// (same images and counters). Set between frames only.
void set_whole_quad_rows(bool enabled);

// Triangles covering a whole tile at one sample, every pixel passing early depth (full-screen
// passes), are shaded in whole batches straight from the tile's quad grid
// (QuadBatcher::add_whole_rect) rather than queued quad by quad. Needs whole quad rows; on by
// default; tests turn it off to compare (same images and counters). Set between frames only.
void set_whole_tiles(bool enabled);
// How many times (since the process started) a triangle's tile took that path, so tests can
// tell that a frame exercised it.
uint64_t whole_tiles_shaded();

}  // namespace ontile
