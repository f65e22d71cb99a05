// Framebuffer fetch from a tile's own memory (Vulkan subpassLoad, input attachments), the
// FramebufferFetch a subpass's functors get while its tile runs (tile_executor.cpp).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "memory/pass_memory.h"
#include "raster/shader_interface.h"
#include "tiler/detail/tile_memory.h"

namespace ontile {

// Framebuffer fetch from this tile's memory (Vulkan subpassLoad): the quad passes its own
// pixel coordinates, so only the current pixel is reachable. One per subpass and tile, so a
// batch shaded after later triangles were rasterized still holds a live one.
class TileFetch final : public FramebufferFetch {
 public:
  TileFetch(const TileMemory& memory, const TileRect& rect, const std::vector<int>& inputs,
            int depth_index)
      : memory_(memory), rect_(rect), inputs_(inputs), depth_index_(depth_index) {}
  glm::vec4 load(int input_slot, int x_px, int y_px, int sample) const override;
  // The quads' two rows are adjacent pixels of tile memory: one index per quad; single-sample
  // colour planes through the SIMD transpose (quad_store_simd.h).
  void load_quads(int input_slot, const int32_t* quad_x_px, const int32_t* quad_y_px, int quad_count, int sample,
                  float* const channel[4]) const override;

 private:
  // The attachment index of input slot `input_slot` (throws ontile::Error if the subpass has none).
  int attachment_of(int input_slot) const;

  const TileMemory& memory_;
  const TileRect& rect_;
  const std::vector<int>& inputs_;
  int depth_index_;
};

}  // namespace ontile
