// Whole-tile texel copies (see texel_copy_rect.h).
#include "tiler/detail/texel_copy_rect.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <vector>

#include "raster/pixel_format_simd.h"
#include "raster/texel_trace.h"
#include "raster/texture.h"
#include "raster/texture_batch_simd.h"
#include "tiler/detail/tile_memory.h"

namespace ontile {
namespace {

std::atomic<bool> pass_through{true};
std::atomic<uint64_t> quads_passed_through{0};

// record_texel_address for the 4 lanes of `quads` quads of one quad row: `top` is the address
// of the first quad's top-left texel, `below` the distance to the row under it, `step` a
// texel's. A granule equal to the one before is written and not counted (the branch-free form
// of the repeat test). Returns the new end of `out` (room for 4 granules per quad).
uint64_t* trace_quad_row(uint64_t top, uint64_t below, uint64_t step, int quads, uint64_t& last,
                         uint64_t* out) {
  for (int q = 0; q < quads; ++q, top += 2 * step) {
    const uint64_t lanes[4] = {top >> 6, (top + step) >> 6, (top + below) >> 6, (top + below + step) >> 6};
    for (const uint64_t granule : lanes) {
      *out = granule;
      out += granule != last;
      last = granule;
    }
  }
  return out;
}

// True when every quad after a row's first traces exactly two granules, its top pair's and its
// bottom pair's: a quad's two texels of a row share a granule (pairs of texels tile the
// granules and start on pair boundaries: x is even) and each granule differs from the one
// before it (the bottom row lies at least a granule and a pair beyond the top one, so neither
// the quad's bottom granule repeats its top one nor the next quad's top granule its bottom one).
bool traces_granule_pairs(const TexelCopyRows& rows) {
  const uint64_t pair = 2 * rows.bytes_per_texel;
  const uint64_t row = static_cast<uint64_t>(rows.width) * rows.bytes_per_texel;
  return pair != 0 && pair <= 64 && 64 % pair == 0 && rows.address % pair == 0 && row % pair == 0 &&
         row >= 64 + pair;
}

}  // namespace

bool texel_copy_rows_of(const FragmentShader& shader, PixelFormat target_format, int width_px,
                        int height_px, TexelCopyRows& rows) {
  const Texture2D* source = shader.texel_copy_source();
  if (!source || !pass_through.load(std::memory_order_relaxed) ||
      source->compression() != TextureCompression::None) {
    return false;
  }
  const Texture2D::TexelView view = source->texel_view(0);
  if (view.width < width_px || view.height < height_px) return false;
  rows.format = target_format;
  rows.width = view.width;
  rows.height = view.height;
  rows.address = view.address;
  rows.bytes_per_texel = view.memory_bytes_per_texel;
  // A view whose fetched values are the decodes of its stored RGBA8 codes of the target's
  // format: the shaded path turns exactly those back into the same codes.
  if (TileMemory::holds_codes(target_format)) {
    rows.bytes = view.surface_bytes ? view.surface_bytes : view.texels8;
    return rgba8_codes_format(view) == target_format && rows.bytes != nullptr;
  }
  // A render target of the target's float format, sampled in place: its texels decode as the
  // tile's stored values do (load_surface_texel, decode_pixel), then quantise as shaded outputs.
  rows.bytes = view.surface_bytes;
  return rows.bytes != nullptr && view.surface_format == target_format &&
         target_format == PixelFormat::RGBA16_FLOAT;
}

namespace {

// Pixel rows [ly, ly + rows) of the rect, `pixels` wide from its left edge: the source's bytes
// into the plane, row by row; the tile widths of the tile size rules (16, 32, 64 pixels) as
// fixed-size copies the compiler inlines rather than a library call per row.
template <size_t kBytes>
void copy_fixed_rows(const uint8_t* src, size_t src_step, uint32_t* dst, size_t dst_step, int rows) {
  for (int y = 0; y < rows; ++y, src += src_step, dst += dst_step) std::memcpy(dst, src, kBytes);
}
void copy_code_rows(const uint8_t* src, size_t src_step, uint32_t* dst, size_t dst_step, int pixels,
                    int rows) {
  switch (pixels) {
    case 16: return copy_fixed_rows<64>(src, src_step, dst, dst_step, rows);
    case 32: return copy_fixed_rows<128>(src, src_step, dst, dst_step, rows);
    case 64: return copy_fixed_rows<256>(src, src_step, dst, dst_step, rows);
    default:
      for (int y = 0; y < rows; ++y, src += src_step, dst += dst_step) {
        std::memcpy(dst, src, sizeof(uint32_t) * static_cast<size_t>(pixels));
      }
  }
}

// The granules of quads [0, quad_count) of the rect appended to `sink`, `last` the granule
// before them (updated).
void trace_texel_quads(const TexelCopyRows& rows, const TileRect& rect, int quad_count,
                       std::vector<uint64_t>& sink, uint64_t& last) {
  const int quads_x = rect.width / 2;
  const uint64_t step = rows.bytes_per_texel, pair = 2 * step;
  const uint64_t row_step = static_cast<uint64_t>(rows.width) * step;
  const uint64_t first_top = rows.address + (static_cast<uint64_t>(rect.y0) * rows.width + rect.x0) * step;
  if (traces_granule_pairs(rows)) {
    // Two granules per quad, but for a quad row's first top granule when it repeats the one
    // before it: room for all, then cut to what was kept.
    const size_t at = sink.size();
    sink.resize(at + 2 * static_cast<size_t>(quad_count));
    uint64_t* out = sink.data() + at;
    for (int first = 0; first < quad_count; first += quads_x) {
      const int quads = std::min(quads_x, quad_count - first);
      const uint64_t top = first_top + static_cast<uint64_t>(first / quads_x) * 2 * row_step;
      const uint64_t top_granule = top >> 6;
      *out = top_granule;
      out += top_granule != last;
      *out++ = (top + row_step) >> 6;
      // The top and bottom addresses stepped together (two adds, two shifts, two stores).
      uint64_t quad_top = top + pair, quad_bottom = top + pair + row_step;
      for (int q = 1; q < quads; ++q, quad_top += pair, quad_bottom += pair) {
        out[2 * q - 2] = quad_top >> 6;
        out[2 * q - 1] = quad_bottom >> 6;
      }
      out += 2 * (quads - 1);
      last = out[-1];
    }
    sink.resize(static_cast<size_t>(out - sink.data()));
    return;
  }
  constexpr int kChunkQuads = 64;
  uint64_t granules[4 * kChunkQuads];
  for (int first = 0; first < quad_count; first += quads_x) {
    const int quads = std::min(quads_x, quad_count - first);
    uint64_t top = first_top + static_cast<uint64_t>(first / quads_x) * 2 * row_step;
    for (int done = 0; done < quads; done += kChunkQuads) {
      const int chunk = std::min(kChunkQuads, quads - done);
      uint64_t* const end = trace_quad_row(top, row_step, step, chunk, last, granules);
      sink.insert(sink.end(), granules, end);
      top += pair * static_cast<uint64_t>(chunk);
    }
  }
}

// What the shaded copy stores for each half code: load_surface_texel's table decode, then
// quantize_pixels' per-value rounding (quantize_half_simd), both per value, so a lookup gives
// the same bits (NaN payloads included) at a fraction of the rounding's cost.
const std::vector<float>& quantized_half_table() {
  static const std::vector<float> table = [] {
    std::vector<float> t(half_decode_table(), half_decode_table() + 65536);
    quantize_half_simd(t.data(), static_cast<int>(t.size()));
    return t;
  }();
  return table;
}

// The texels of quads [0, quad_count) traced to the thread's sink; counted as passed through.
void trace(const TexelCopyRows& rows, const TileRect& rect, int quad_count) {
  if (std::vector<uint64_t>* const sink = texel_trace_detail::sink) {
    trace_texel_quads(rows, rect, quad_count, *sink, texel_trace_detail::last_granule);
  }
  quads_passed_through.fetch_add(static_cast<uint64_t>(quad_count), std::memory_order_relaxed);
}

}  // namespace

void copy_texel_quads(const TexelCopyRows& rows, const TileRect& rect, int quad_count, uint32_t* plane,
                      int plane_width) {
  const int quads_x = rect.width / 2;
  const int whole_rows = quad_count / quads_x, rest = quad_count % quads_x;
  const uint8_t* const source = rows.bytes + (static_cast<size_t>(rect.y0) * rows.width + rect.x0) * 4;
  const size_t source_step = static_cast<size_t>(rows.width) * 4;
  copy_code_rows(source, source_step, plane, static_cast<size_t>(plane_width), rect.width, 2 * whole_rows);
  if (rest > 0) {
    const int ly = 2 * whole_rows;
    copy_code_rows(source + source_step * static_cast<size_t>(ly), source_step,
                   plane + static_cast<size_t>(ly) * plane_width, static_cast<size_t>(plane_width),
                   2 * rest, 2);
  }
  trace(rows, rect, quad_count);
}

void copy_texel_quads(const TexelCopyRows& rows, const TileRect& rect, int quad_count, glm::vec4* plane,
                      int plane_width) {
  static_assert(sizeof(glm::vec4) == 4 * sizeof(float), "a row of vec4 is a row of floats");
  const int quads_x = rect.width / 2;
  const float* const half = quantized_half_table().data();
  for (int first = 0; first < quad_count; first += quads_x) {
    const int pixels = 2 * std::min(quads_x, quad_count - first);
    const int ly = 2 * (first / quads_x);
    for (int dy = 0; dy < 2; ++dy) {
      const size_t texel = static_cast<size_t>(rect.y0 + ly + dy) * rows.width + rect.x0;
      float* const out = &plane[static_cast<size_t>(ly + dy) * plane_width].x;
      uint16_t codes[4 * 64];
      for (int done = 0; done < pixels; done += 64) {
        const int n = std::min(64, pixels - done);
        std::memcpy(codes, rows.bytes + (texel + done) * 8, sizeof(uint16_t) * 4 * static_cast<size_t>(n));
        for (int i = 0; i < 4 * n; ++i) out[4 * done + i] = half[codes[i]];
      }
    }
  }
  trace(rows, rect, quad_count);
}

void set_texel_copy_pass_through(bool enabled) { pass_through.store(enabled); }
uint64_t texel_copy_quads_passed_through() { return quads_passed_through.load(); }

}  // namespace ontile
