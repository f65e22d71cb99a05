// Tile load and store (see tile_load_store.h). The memory model (memory/memory_model.h) prices
// what moves; this file moves the data. A tile row (its pixels, samples adjacent) is contiguous in
// tile memory and in the surface, so loads and stores convert whole rows (pixel_format.h row
// functions, SIMD for the hot formats) or, for 8-bit RGBA code planes, copy them, and clears
// are fills of one quantised value (or its code).
#include "tiler/detail/tile_load_store.h"

#include <algorithm>
#include <cstring>

#include "tiler/detail/quad_store_simd.h"

namespace ontile {
namespace {

// Widest tile row in values: 64 px x 8 samples (the largest tile and sample count).
constexpr int kMaxRowValues = 64 * 8;

// Rows wider than the stack buffer (never, with today's tile and sample limits) take the
// per-pixel path.
bool row_fits(const TileRect& rect, int samples) { return rect.width * samples <= kMaxRowValues; }

// `rows` rows of `bytes` bytes, rows src_step and dst_step apart: the pointers stepped rather
// than recomputed, and the common tile widths (16, 32 and 64 RGBA8 pixels) copied by
// fixed-size copies the compiler inlines rather than a library call per row.
template <size_t kBytes>
void copy_fixed_rows(const uint8_t* src, size_t src_step, uint8_t* dst, size_t dst_step, int rows) {
  for (int y = 0; y < rows; ++y, src += src_step, dst += dst_step) std::memcpy(dst, src, kBytes);
}
void copy_rows(const uint8_t* src, size_t src_step, uint8_t* dst, size_t dst_step, size_t bytes, int rows) {
  switch (bytes) {
    case 64: return copy_fixed_rows<64>(src, src_step, dst, dst_step, rows);
    case 128: return copy_fixed_rows<128>(src, src_step, dst, dst_step, rows);
    case 256: return copy_fixed_rows<256>(src, src_step, dst, dst_step, rows);
    default:
      for (int y = 0; y < rows; ++y, src += src_step, dst += dst_step) std::memcpy(dst, src, bytes);
  }
}

void load_attachment_rows(const AttachmentDesc& desc, bool is_depth, const TileRect& rect,
                          int samples, glm::vec4* color, uint32_t* codes, float* depth,
                          const TileMemory& memory) {
  const int n = rect.width * samples;
  if (codes && rect.height > 0) {  // the surface's bytes are the plane's (the formats are equal: validated)
    const uint8_t* first_row = desc.surface->pixel_bytes(rect.x0, rect.y0);
    const size_t pitch = rect.height > 1
        ? static_cast<size_t>(desc.surface->pixel_bytes(rect.x0, rect.y0 + 1) - first_row) : 0;
    copy_rows(first_row, pitch, reinterpret_cast<uint8_t*>(codes), sizeof(uint32_t) * memory.index(0, 1, 0),
              sizeof(uint32_t) * static_cast<size_t>(n), rect.height);
    return;
  }
  glm::vec4 row[kMaxRowValues];
  for (int ly = 0; ly < rect.height; ++ly) {
    const size_t first = memory.index(0, ly, 0);
    const uint8_t* src = desc.surface->pixel_bytes(rect.x0, rect.y0 + ly);
    if (!is_depth) {
      decode_pixels(desc.format, src, n, color + first);
      continue;
    }
    if (desc.format == PixelFormat::D32_FLOAT) {  // the stored bytes are the float's
      std::memcpy(depth + first, src, sizeof(float) * static_cast<size_t>(n));
      continue;
    }
    decode_pixels(desc.format, src, n, row);
    for (int i = 0; i < n; ++i) depth[first + i] = row[i].x;
  }
}

// Stores and/or resolves one attachment row by row: the samples' row encoded as it is, and each
// pixel's samples averaged in sample order (Vulkan's resolve for float/UNORM formats; the sum
// starts at 0 and is divided by the sample count, as the per-pixel path does) and encoded as a row.
void store_attachment_rows(const AttachmentDesc& desc, bool is_depth, const TileRect& rect,
                           int samples, const TileMemory& memory, int attachment, bool store,
                           bool resolve) {
  const int n = rect.width * samples;
  // Colour stores without a resolve: the whole tile in one call (rows of tile memory are
  // memory.width() * samples values apart, the surface's rows its row pitch).
  const bool whole_tile_store = store && !is_depth && !resolve && rect.height > 0;
  const bool codes = !is_depth && memory.holds_codes(attachment);
  if (whole_tile_store) {
    uint8_t* const first_row = desc.surface->pixel_bytes(rect.x0, rect.y0);
    const size_t pitch = rect.height > 1
        ? static_cast<size_t>(desc.surface->pixel_bytes(rect.x0, rect.y0 + 1) - first_row) : 0;
    if (codes) {  // the plane's bytes are the surface's: row copies
      copy_rows(reinterpret_cast<const uint8_t*>(memory.code_plane(attachment)),
                sizeof(uint32_t) * memory.index(0, 1, 0), first_row, pitch,
                sizeof(uint32_t) * static_cast<size_t>(n), rect.height);
      return;
    }
    encode_pixel_rows(desc.surface->format(), memory.color_plane(attachment), memory.index(0, 1, 0),
                      n, rect.height, desc.surface->pixel_bytes(rect.x0, rect.y0), pitch);
    return;
  }
  if (is_depth && desc.format == PixelFormat::D32_FLOAT && store && !resolve) {
    for (int ly = 0; ly < rect.height; ++ly) {  // the stored bytes are the float's
      std::memcpy(desc.surface->pixel_bytes(rect.x0, rect.y0 + ly),
                  memory.depth_plane() + memory.index(0, ly, 0), sizeof(float) * static_cast<size_t>(n));
    }
    return;
  }
  glm::vec4 row[kMaxRowValues];
  glm::vec4 resolved[kMaxRowValues];
  for (int ly = 0; ly < rect.height; ++ly) {
    const size_t first = memory.index(0, ly, 0);
    const glm::vec4* values = codes ? row : memory.color_plane(attachment) + first;
    if (is_depth) {
      for (int i = 0; i < n; ++i) row[i] = glm::vec4(memory.depth_plane()[first + i], 0.0f, 0.0f, 1.0f);
      values = row;
    }
    if (codes) {
      const uint32_t* src = memory.code_plane(attachment) + first;
      if (store) {
        std::memcpy(desc.surface->pixel_bytes(rect.x0, rect.y0 + ly), src, sizeof(uint32_t) * static_cast<size_t>(n));
      }
      if (resolve) decode_pixels(memory.format(attachment), reinterpret_cast<const uint8_t*>(src), n, row);
    } else if (store) {
      encode_pixels(desc.surface->format(), values, n,
                    desc.surface->pixel_bytes(rect.x0, rect.y0 + ly));
    }
    if (!resolve) continue;
    for (int lx = 0; lx < rect.width; ++lx) {
      glm::vec4 sum(0.0f);
      for (int s = 0; s < samples; ++s) sum += values[lx * samples + s];
      resolved[lx] = sum / static_cast<float>(samples);
    }
    encode_pixels(desc.resolve_surface->format(), resolved, rect.width,
                  desc.resolve_surface->pixel_bytes(rect.x0, rect.y0 + ly));
  }
}

}  // namespace

void load_tile(const RenderPassDesc& pass, const TileRect& rect, TileMemory& memory) {
  const int samples = memory.samples();
  for (size_t a = 0; a < pass.attachments.size(); ++a) {
    const AttachmentDesc& desc = pass.attachments[a];
    const bool is_depth = static_cast<int>(a) == pass.depth_index;
    const bool codes = !is_depth && memory.holds_codes(static_cast<int>(a));
    glm::vec4* color = is_depth || codes ? nullptr : memory.color_plane(static_cast<int>(a));
    uint32_t* code_plane = codes ? memory.code_plane(static_cast<int>(a)) : nullptr;
    float* depth = memory.depth_plane();
    // DontCare leaves undefined contents; we define them as the clear value so that images
    // stay deterministic (a pipeline that reads them has a bug the validation cannot see).
    const bool from_memory = desc.load == LoadAction::Load && desc.surface != nullptr;
    if (!from_memory) {
      const glm::vec4 v = quantize_pixel(desc.format, desc.clear_value);
      const size_t n = static_cast<size_t>(memory.width()) * memory.height() * samples;
      if (is_depth) {
        fill_depth(depth, n, v.x);
      } else if (codes) {  // the clear value's code (whose decode is v)
        uint8_t bytes[4];
        encode_pixel(desc.format, desc.clear_value, bytes);
        uint32_t code;
        std::memcpy(&code, bytes, sizeof(code));
        fill_codes(code_plane, n, code);
      } else {
        fill_plane(color, n, v);
      }
      continue;
    }
    if (desc.surface->samples() == samples && row_fits(rect, samples)) {
      load_attachment_rows(desc, is_depth, rect, samples, color, code_plane, depth, memory);
      continue;
    }
    for (int ly = 0; ly < rect.height; ++ly) {
      for (int lx = 0; lx < rect.width; ++lx) {
        for (int s = 0; s < samples; ++s) {
          const size_t i = memory.index(lx, ly, s);
          const glm::vec4 v = desc.surface->read(rect.x0 + lx, rect.y0 + ly, s);
          if (is_depth) {
            depth[i] = v.x;
          } else if (codes) {
            memory.set_color(static_cast<int>(a), i, v);
          } else {
            color[i] = v;
          }
        }
      }
    }
  }
}

namespace {

// What the tile holds of attachment `a`, every sample, into an inspection surface
// (RenderPassDesc::capture_surfaces): a debugging copy, not a store, so it is not counted.
void capture_tile(Surface& capture, bool is_depth, const TileRect& rect, const TileMemory& memory, int a) {
  for (int ly = 0; ly < rect.height; ++ly) {
    for (int lx = 0; lx < rect.width; ++lx) {
      for (int s = 0; s < memory.samples(); ++s) {
        const size_t i = memory.index(lx, ly, s);
        capture.write(rect.x0 + lx, rect.y0 + ly, s,
                      is_depth ? glm::vec4(memory.depth_plane()[i], 0.0f, 0.0f, 1.0f) : memory.color(a, i));
      }
    }
  }
}

}  // namespace

void store_tile(const RenderPassDesc& pass, const TileRect& rect, const TileMemory& memory) {
  const int samples = memory.samples();
  for (size_t a = 0; a < pass.attachments.size(); ++a) {
    const AttachmentDesc& desc = pass.attachments[a];
    const bool is_depth = static_cast<int>(a) == pass.depth_index;
    if (a < pass.capture_surfaces.size() && pass.capture_surfaces[a]) {
      capture_tile(*pass.capture_surfaces[a], is_depth, rect, memory, static_cast<int>(a));
    }
    const bool store = (desc.store == StoreAction::Store ||
                        desc.store == StoreAction::StoreAndResolve) && desc.surface != nullptr;
    const bool resolve = (desc.store == StoreAction::Resolve ||
                          desc.store == StoreAction::StoreAndResolve) &&
                         desc.resolve_surface != nullptr;
    if (!store && !resolve) continue;
    if ((!store || desc.surface->samples() == samples) &&
        (!resolve || desc.resolve_surface->samples() == 1) && row_fits(rect, samples)) {
      store_attachment_rows(desc, is_depth, rect, samples, memory, static_cast<int>(a), store,
                            resolve);
      continue;
    }
    for (int ly = 0; ly < rect.height; ++ly) {
      for (int lx = 0; lx < rect.width; ++lx) {
        glm::vec4 sum(0.0f);
        for (int s = 0; s < samples; ++s) {
          const size_t i = memory.index(lx, ly, s);
          const glm::vec4 v = is_depth ? glm::vec4(memory.depth_plane()[i], 0.0f, 0.0f, 1.0f)
                                       : memory.color(static_cast<int>(a), i);
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
