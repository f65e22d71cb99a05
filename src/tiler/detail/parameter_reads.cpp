// The parameter buffer's reads in tile order (see parameter_reads.h).
#include "tiler/detail/parameter_reads.h"

#include <vector>

namespace ontile {
namespace {

constexpr uint64_t kLineBytes = 64;

uint64_t align_up(uint64_t bytes) { return (bytes + kLineBytes - 1) / kLineBytes * kLineBytes; }

}  // namespace

void replay_parameter_reads(const ParameterBuffer& params, const RenderPassDesc& pass, MemoryModel& memory) {
  const uint32_t component_bytes = params.vertex_output.varying_component_bytes;
  // Where each draw's post-transform vertices and each chunk's clipped vertices start, after
  // the tile lists and primitive records.
  uint64_t triangle_total = 0;
  std::vector<uint64_t> first_triangle(params.chunks.size(), 0);
  for (size_t c = 0; c < params.chunks.size(); ++c) {
    first_triangle[c] = triangle_total;
    triangle_total += params.chunks[c].triangles.size();
  }
  const uint64_t records_base = align_up(uint64_t{kTileListEntryBytes} * params.tile_entries.size());
  uint64_t next = align_up(records_base + uint64_t{kPrimitiveRecordBytes} * triangle_total);
  std::vector<std::vector<uint64_t>> draw_vertex_base(pass.subpasses.size());
  for (size_t s = 0; s < pass.subpasses.size(); ++s) {
    for (const DrawCall& d : pass.subpasses[s].draws) {
      draw_vertex_base[s].push_back(next);
      next = align_up(next + uint64_t{d.vertex_count} * post_transform_vertex_bytes(d.vertex_shader->varying_count(), component_bytes));
    }
  }
  std::vector<uint64_t> clipped_base(params.chunks.size(), 0);
  for (size_t c = 0; c < params.chunks.size(); ++c) {
    if (params.chunks[c].triangles.empty()) continue;
    const BinnedTriangle& t = params.chunks[c].triangles.front();  // a chunk holds one draw
    clipped_base[c] = next;
    const int n = pass.subpasses[t.subpass].draws[t.draw].vertex_shader->varying_count();
    next = align_up(next + uint64_t{params.chunks[c].clipped_vertices} * post_transform_vertex_bytes(n, component_bytes));
  }

  const auto read = [&](uint64_t address, uint64_t bytes) { memory.parameter_read(address, bytes); };
  const int tiles = params.grid.tile_count();
  for (int tile = 0; tile < tiles; ++tile) {
    for (uint32_t e = params.tile_offsets[tile]; e < params.tile_offsets[tile + 1]; ++e) {
      const uint32_t ref = params.tile_entries[e];
      const uint32_t chunk = ref >> kChunkLocalBits, local = ref & ((1u << kChunkLocalBits) - 1);
      const BinnedTriangle& t = params.chunks[chunk].triangles[local];
      const uint64_t stride = post_transform_vertex_bytes(pass.subpasses[t.subpass].draws[t.draw].vertex_shader->varying_count(), component_bytes);
      read(uint64_t{kTileListEntryBytes} * e, kTileListEntryBytes);
      read(records_base + uint64_t{kPrimitiveRecordBytes} * (first_triangle[chunk] + local), kPrimitiveRecordBytes);
      for (const uint32_t v : t.vertex) {
        const uint64_t base = (v & kClippedVertex) ? clipped_base[chunk] : draw_vertex_base[t.subpass][t.draw];
        read(base + uint64_t{v & ~kClippedVertex} * stride, stride);
      }
    }
  }
}

}  // namespace ontile
