// Tile load and store (see tile_load_store.h). Byte counting is done analytically by the pass
// executor; this file moves the data.
#include "tiler/tile_load_store.h"

namespace ontile {

void load_tile(const RenderPassDesc& pass, const TileRect& rect, TileMemory& memory) {
  const int samples = memory.samples();
  for (size_t a = 0; a < pass.attachments.size(); ++a) {
    const AttachmentDesc& desc = pass.attachments[a];
    const bool is_depth = static_cast<int>(a) == pass.depth_index;
    // DontCare leaves undefined contents; we define them as the clear value so that images
    // stay deterministic (a pipeline that reads them has a bug the validation cannot see).
    const bool from_memory = desc.load == LoadAction::Load && desc.surface != nullptr;
    for (int ly = 0; ly < rect.height; ++ly) {
      for (int lx = 0; lx < rect.width; ++lx) {
        for (int s = 0; s < samples; ++s) {
          const size_t i = memory.index(lx, ly, s);
          glm::vec4 v = from_memory ? desc.surface->read(rect.x0 + lx, rect.y0 + ly, s)
                                    : desc.clear_value;
          if (!from_memory) v = quantize_pixel(desc.format, v);
          if (is_depth) {
            memory.depth_plane()[i] = v.x;
          } else {
            memory.color_plane(static_cast<int>(a))[i] = v;
          }
        }
      }
    }
  }
}

void store_tile(const RenderPassDesc& pass, const TileRect& rect, const TileMemory& memory) {
  const int samples = memory.samples();
  for (size_t a = 0; a < pass.attachments.size(); ++a) {
    const AttachmentDesc& desc = pass.attachments[a];
    const bool is_depth = static_cast<int>(a) == pass.depth_index;
    const bool store = (desc.store == StoreAction::Store ||
                        desc.store == StoreAction::StoreAndResolve) && desc.surface != nullptr;
    const bool resolve = (desc.store == StoreAction::Resolve ||
                          desc.store == StoreAction::StoreAndResolve) &&
                         desc.resolve_surface != nullptr;
    if (!store && !resolve) continue;
    for (int ly = 0; ly < rect.height; ++ly) {
      for (int lx = 0; lx < rect.width; ++lx) {
        glm::vec4 sum(0.0f);
        for (int s = 0; s < samples; ++s) {
          const size_t i = memory.index(lx, ly, s);
          const glm::vec4 v = is_depth ? glm::vec4(memory.depth_plane()[i], 0.0f, 0.0f, 1.0f)
                                       : memory.color_plane(static_cast<int>(a))[i];
          if (store) desc.surface->write(rect.x0 + lx, rect.y0 + ly, s, v);
          sum += v;
        }
        // Resolve averages the samples (Vulkan's resolve for float/UNORM formats), summed in a
        // fixed sample order so the result is deterministic.
        if (resolve) {
          desc.resolve_surface->write(rect.x0 + lx, rect.y0 + ly, 0,
                                      sum / static_cast<float>(samples));
        }
      }
    }
  }
}

}  // namespace ontile
