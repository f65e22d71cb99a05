// Moves one tile's attachments between external surfaces and tile memory according to the
// Vulkan load and store operations (VkAttachmentLoadOp / VkAttachmentStoreOp).
#pragma once
#include "tiler/render_pass.h"
#include "tiler/detail/tile_memory.h"

namespace ontile {

struct TileRect {
  int x0 = 0, y0 = 0;          // top-left pixel of the tile
  int width = 0, height = 0;   // clipped to the render target
};

void load_tile(const RenderPassDesc& pass, const TileRect& rect, TileMemory& memory);
void store_tile(const RenderPassDesc& pass, const TileRect& rect, const TileMemory& memory);

}  // namespace ontile
