// The batcher's whole-tile path (see QuadBatcher::add_whole_rect): a triangle covering a whole
// tile (full-screen passes) is shaded batch by batch straight from the tile's quad grid, with
// no per-quad queue entries, lane masks, slots or per-fragment interpolation inputs, and written
// back without per-quad checks. Every value and counter is the one flush() would produce for the
// same quads queued by add().
#include <algorithm>
#include <bit>
#include <cstring>

#include "raster/pixel_quantize_simd.h"
#include "tiler/detail/quad_batcher.h"
#include "tiler/detail/quad_store_simd.h"
#include "tiler/detail/texel_copy_rect.h"

namespace ontile {

bool QuadBatcher::add_whole_rect(const TileRect& rect, int first_cell_x, int first_cell_y,
                                 int cells_x) {
  const TriangleContext& ctx = *ctx_;
  if (queued_ != 0 || ctx.pattern.count != 1 || !ctx.whole_quads_pass_as_covered() ||
      ctx.per_sample || ctx.fragments ||
      !opaque_writes_ || !ctx.draw.fragment_shader || (rect.x0 | rect.y0 | rect.width | rect.height) & 1) {
    return false;
  }
  const int quads_x = rect.width / 2;
  const int quads = quads_x * (rect.height / 2);
  const int whole_batches = quads / kBatchQuads;
  int qx = rect.x0, qy = rect.y0;
  const std::vector<int>& outputs = ctx.subpass.color_outputs;
  TexelCopyRows copy_rows;
  if (whole_batches > 0 && outputs.size() == 1 &&
      texel_copy_rows_of(*ctx.draw.fragment_shader, ctx.pass.attachments[outputs[0]].format,
                         ctx.pass.width_px, ctx.pass.height_px, copy_rows)) {
    // A declared texel copy: the whole batches' quads as shade_whole_batch would write and
    // count them (every lane active and written), the texels moved rather than shaded.
    const int copied = whole_batches * kBatchQuads;
    if (memory_->holds_codes(outputs[0])) {
      copy_texel_quads(copy_rows, rect, copied, memory_->code_plane(outputs[0]), memory_->width());
    } else {
      copy_texel_quads(copy_rows, rect, copied, memory_->color_plane(outputs[0]), memory_->width());
    }
    counters_->fragments_shaded += static_cast<uint64_t>(copied) * kQuadLanes;
    counters_->samples_written += static_cast<uint64_t>(copied) * kQuadLanes;
    qx = rect.x0 + 2 * (copied % quads_x);
    qy = rect.y0 + 2 * (copied / quads_x);
  } else {
    for (int batch = 0; batch < whole_batches; ++batch) {
      shade_whole_batch(rect, qx, qy, first_cell_x, first_cell_y, cells_x);
    }
  }
  // The rest is what add() would leave queued at the triangle's end.
  for (int q = whole_batches * kBatchQuads; q < quads; ++q) {
    const int ci = (qx - first_cell_x) / kCellSizePx, cj = (qy - first_cell_y) / kCellSizePx;
    add(qx, qy, cj * cells_x + ci, first_cell_x + ci * kCellSizePx, first_cell_y + cj * kCellSizePx,
        kWholeQuadSample0, kWholeQuadSample0);
    qx += 2;
    if (qx == rect.x0 + rect.width) {
      qx = rect.x0;
      qy += 2;
    }
  }
  return true;
}

// shade_invocation and write_back_single_sample for kBatchQuads whole quads of the open
// triangle (triangles_[0], whose planes are still in the cells): every lane active and passing.
void QuadBatcher::shade_whole_batch(const TileRect& rect, int& qx, int& qy, int first_cell_x,
                                    int first_cell_y, int cells_x) {
  const TriangleContext& ctx = *ctx_;
  const BatchTriangle& t = triangles_[0];
  FragmentBatch& b = *batch_;
  BatchOutput& out = *outputs_[0];
  const uint32_t primitive_id = t.tri->primitive_id;
  // Locals, not the members or the references: the stores below are ints and floats too.
  const int x0 = rect.x0, row_end = rect.x0 + rect.width, width = memory_->width();
  const CellState* const cells = cells_;
  // What every quad of a whole batch shares (the queued path and discards overwrite these).
  for (int i = 0; i < kBatchQuads; ++i) {
    b.lane_mask[i] = 0xF;
    b.quad_primitive_id[i] = primitive_id;
    full_first_fragment_[i] = i * kQuadLanes;
  }
  // The batch's quads row segment by row segment: within a quad row x, the tile pixel and the
  // offset in the cell advance by 2 per quad, and every 4 quads share a cell's planes.
  int x = qx, y = qy;
  // The row segments: first batch quad, quads, tile pixel of the first quad's top left.
  int32_t segment_first[kBatchQuads], segment_quads[kBatchQuads];
  uint32_t segment_pixel[kBatchQuads];
  int segments = 0;
  for (int i = 0; i < kBatchQuads;) {
    const int quads = std::min(kBatchQuads - i, (row_end - x) / 2);
    // x from the cells' left edge (at or left of the tile); the row's first cell; the quad row
    // inside its cell.
    const unsigned lx = static_cast<unsigned>(x - first_cell_x);
    const int cell_row = (y - first_cell_y) / kCellSizePx * cells_x;
    const int oy = (y - first_cell_y) % kCellSizePx;
    const uint32_t pixel = static_cast<uint32_t>((y - rect.y0) * width + (x - x0));
    segment_first[segments] = i;
    segment_quads[segments] = quads;
    segment_pixel[segments++] = pixel;
    // Cell by cell (lx is even: the rect's x0 is): its planes read once for its quads; a whole
    // cell row (4 quads) as 4-value blocks built in registers.
    for (int k = 0; k < quads;) {
      const unsigned cell_lx = lx + 2u * static_cast<unsigned>(k);
      const CellPlane* planes = cells[cell_row + cell_lx / kCellSizePx].planes;
      const float l1 = planes[0].origin, l2 = planes[1].origin, z = planes[2].origin;
      const int j = i + k;
      if (cell_lx % kCellSizePx == 0 && k + 4 <= quads) {
        const int32_t xs[4] = {x + 2 * k, x + 2 * k + 2, x + 2 * k + 4, x + 2 * k + 6};
        const int32_t ys[4] = {y, y, y, y}, oxs[4] = {0, 2, 4, 6}, oys[4] = {oy, oy, oy, oy};
        const uint32_t p = pixel + 2u * static_cast<uint32_t>(k);
        const uint32_t pixels[4] = {p, p + 2, p + 4, p + 6};
        const float l1s[4] = {l1, l1, l1, l1}, l2s[4] = {l2, l2, l2, l2}, zs[4] = {z, z, z, z};
        std::memcpy(b.quad_x_px + j, xs, sizeof(xs));
        std::memcpy(b.quad_y_px + j, ys, sizeof(ys));
        std::memcpy(quad_ox_ + j, oxs, sizeof(oxs));
        std::memcpy(quad_oy_ + j, oys, sizeof(oys));
        std::memcpy(full_pixel_ + j, pixels, sizeof(pixels));
        std::memcpy(quad_l1_ + j, l1s, sizeof(l1s));
        std::memcpy(quad_l2_ + j, l2s, sizeof(l2s));
        std::memcpy(quad_z_ + j, zs, sizeof(zs));
        k += 4;
        continue;
      }
      const int cell_end = std::min(quads, k + static_cast<int>((kCellSizePx - cell_lx % kCellSizePx) / 2));
      for (; k < cell_end; ++k) {
        b.quad_x_px[i + k] = x + 2 * k;
        b.quad_y_px[i + k] = y;
        quad_ox_[i + k] = static_cast<int32_t>((lx + 2u * k) % kCellSizePx);
        quad_oy_[i + k] = oy;
        full_pixel_[i + k] = pixel + 2u * k;
        quad_l1_[i + k] = l1;
        quad_l2_[i + k] = l2;
        quad_z_[i + k] = z;
      }
    }
    i += quads;
    x += 2 * quads;
    if (x == row_end) {  // the next quad row: two pixel rows down
      x = x0;
      y += 2;
    }
  }
  qx = x;
  qy = y;
  const int n = ctx.varying_count;
  const InterpolationInput in{nullptr, nullptr, nullptr, nullptr, nullptr,
                              t.l1_dx, t.l1_dy, t.l2_dx, t.l2_dy, t.z_dx, t.z_dy,
                              {t.tri->setup.inv_w[0], t.tri->setup.inv_w[1], t.tri->setup.inv_w[2]},
                              {t.varyings, t.varyings + n, t.varyings + 2 * n},
                              n, varyings_read_};
  interpolate_whole_quads(in, QuadOrigins{quad_ox_, quad_oy_, quad_l1_, quad_l2_, quad_z_},
                          kBatchQuads, b.depth, &b.varyings[0][0], kBatchFragments);
  b.quad_count = kBatchQuads;
  b.varying_count = n;
  b.color_output_count = static_cast<int>(ctx.subpass.color_outputs.size());
  b.front_facing = ctx.tri.setup.front_facing;
  b.primitive_id = primitive_id;
  b.sample = -1;
  b.fetch = ctx.fetch;
  // As shade_invocation: unwritten outputs are zero (those the functor always writes in full
  // need no clearing: every lane of a whole batch is active); opaque outputs quantised per batch.
  for (int k = ctx.draw.fragment_shader->outputs_always_written(); k < b.color_output_count; ++k) {
    std::memset(out.color[k], 0, sizeof(out.color[k]));
  }
  out.discard_mask = 0;
  out.output0_codes_of.reset();
  out.uniform_outputs = 0;
  ctx.draw.fragment_shader->shade_batch(b, out);
  const std::vector<int>& outputs = ctx.subpass.color_outputs;
  for (int k = 0; k < b.color_output_count; ++k) {
    const PixelFormat format = ctx.pass.attachments[outputs[k]].format;
    if (TileMemory::holds_codes(format)) {  // decoded codes give their own codes back
      const bool srgb = format == PixelFormat::RGBA8_SRGB;
      if ((out.uniform_outputs >> k) & 1u) {
        quantize_rgba8_codes_simd(out.color[k][0], out.color[k][1], out.color[k][2], out.color[k][3], 1,
                                  srgb, codes_[0][k]);
        std::fill_n(codes_[0][k] + 1, kBatchFragments - 1, codes_[0][k][0]);
        continue;
      }
      const auto codes_of = k == 0 && out.output0_codes_of == format ? rgba8_codes_of_decoded_simd
                                                                     : quantize_rgba8_codes_simd;
      codes_of(out.color[k][0], out.color[k][1], out.color[k][2], out.color[k][3], kBatchFragments,
               srgb, codes_[0][k]);
      continue;
    }
    if (k == 0 && out.output0_codes_of == format) continue;  // already quantised
    if ((out.uniform_outputs >> k) & 1u) {
      // Quantising is per value: one pixel's result is every pixel's.
      quantize_pixels(format, out.color[k][0], out.color[k][1], out.color[k][2], out.color[k][3], 1);
      for (int c = 0; c < 4; ++c) std::fill_n(out.color[k][c] + 1, kBatchFragments - 1, out.color[k][c][0]);
      continue;
    }
    quantize_pixels(format, out.color[k][0], out.color[k][1], out.color[k][2], out.color[k][3],
                    kBatchFragments);
  }
  counters_->fragments_shaded += kBatchFragments;
  // Discarded lanes lose their writes, as in write_back_single_sample (a late-Z functor here has
  // no depth test or write, so nothing else of a lane depends on it); whole quads are stored on
  // SIMD lanes, the others lane by lane.
  int full_quads = kBatchQuads;
  if (out.discard_mask == 0) {
    counters_->samples_written += kBatchFragments;
  } else {
    full_quads = 0;
    for (int i = 0; i < kBatchQuads; ++i) {
      const uint8_t lanes = static_cast<uint8_t>(~(out.discard_mask >> (i * kQuadLanes)) & 0xFu);
      counters_->samples_written += static_cast<uint64_t>(lane_count(lanes));
      if (lanes == 0xF) {
        full_first_fragment_[full_quads] = full_first_fragment_[i];
        full_pixel_[full_quads++] = full_pixel_[i];
        continue;
      }
      for (int lane = 0; lane < kQuadLanes; ++lane) {
        if (!((lanes >> lane) & 1u)) continue;
        const size_t p = full_pixel_[i] + static_cast<size_t>(lane >> 1) * memory_->width() + (lane & 1);
        const int f = i * kQuadLanes + lane;
        for (size_t k = 0; k < outputs.size(); ++k) {
          if (memory_->holds_codes(outputs[k])) {
            memory_->code_plane(outputs[k])[p] = codes_[0][k][f];
            continue;
          }
          memory_->color_plane(outputs[k])[p] = {out.color[k][0][f], out.color[k][1][f],
                                                 out.color[k][2][f], out.color[k][3][f]};
        }
      }
    }
  }
  for (size_t k = 0; k < outputs.size(); ++k) {
    if (memory_->holds_codes(outputs[k])) {
      uint32_t* const plane = memory_->code_plane(outputs[k]);
      if (full_quads < kBatchQuads) {
        store_full_quad_codes(codes_[0][k], full_first_fragment_, full_pixel_, full_quads, width, plane);
        continue;
      }
      store_quad_rows_codes(codes_[0][k], segment_first, segment_quads, segment_pixel, segments, width,
                            plane);  // every quad: row segment by row segment
      continue;
    }
    const float* const channels[4] = {out.color[k][0], out.color[k][1], out.color[k][2],
                                      out.color[k][3]};
    store_full_quads(channels, full_first_fragment_, full_pixel_, full_quads, memory_->width(),
                     memory_->color_plane(outputs[k]));
  }
}

}  // namespace ontile
