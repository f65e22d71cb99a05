// Moves one tile's attachments between external surfaces and tile memory according to the
// Vulkan load and store operations (VkAttachmentLoadOp / VkAttachmentStoreOp).
#pragma once
#include "memory/pass_memory.h"
#include "tiler/render_pass.h"
#include "tiler/detail/tile_memory.h"

namespace ontile {

void load_tile(const RenderPassDesc& pass, const TileRect& rect, TileMemory& memory);
void store_tile(const RenderPassDesc& pass, const TileRect& rect, const TileMemory& memory);

}  // namespace ontile
