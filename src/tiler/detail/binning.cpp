// Geometry phase of a pass (see parameter_buffer.h): vertex shading, assembly, clipping, setup
// and binning, in parallel chunks whose outputs are concatenated in submission order.
#include <algorithm>
#include <atomic>
#include <bit>

#include "raster/clip.h"
#include "tiler/detail/parameter_buffer.h"
#include "tiler/detail/vertex_stage.h"
#include "util/error.h"
#include "util/parallel_for.h"

namespace ontile {
namespace {

// One (tile, triangle) pair of a chunk, in submission order.
struct TileEntry {
  uint32_t tile;
  uint32_t triangle;  // chunk-local
};

// Pixel to tile column/row. Tile sizes are powers of two (the executor requires it and tile-size
// reduction halves them), which makes this a shift; other sizes still divide correctly.
struct TileIndexer {
  int width_px, height_px, shift_x, shift_y, tiles_x;
  explicit TileIndexer(const TileGrid& g)
      : width_px(g.tile_width_px), height_px(g.tile_height_px),
        shift_x(std::has_single_bit(static_cast<unsigned>(g.tile_width_px))
                    ? std::countr_zero(static_cast<unsigned>(g.tile_width_px)) : -1),
        shift_y(std::has_single_bit(static_cast<unsigned>(g.tile_height_px))
                    ? std::countr_zero(static_cast<unsigned>(g.tile_height_px)) : -1),
        tiles_x(g.tiles_x()) {}
  // px >= 0, so the shift equals the division.
  int column(int px) const { return shift_x >= 0 ? px >> shift_x : px / width_px; }
  int row(int py) const { return shift_y >= 0 ? py >> shift_y : py / height_px; }
};

struct Chunk {
  uint32_t subpass = 0, draw = 0;
  uint32_t first_triangle = 0, triangle_count = 0;
  // Outputs.
  UninitializedVector<BinnedTriangle>& triangles;
  UninitializedVector<float>& varyings;
  UninitializedVector<TileEntry> entries;
  uint32_t clipped_vertices = 0;
  GeometryCounters counters;
};

// True when the triangle's edges leave some sample position of the tile inside: for each edge
// the tile corner that maximises the edge function must not be outside.
bool triangle_touches_tile(const TriangleSetup& t, int64_t x0_fp, int64_t y0_fp, int64_t x1_fp,
                           int64_t y1_fp) {
  for (const EdgeFunction& e : t.edge) {
    const int64_t px = e.a >= 0 ? x1_fp : x0_fp;
    const int64_t py = e.b >= 0 ? y1_fp : y0_fp;
    if (e.at(px, py) + e.bias < 0) return false;
  }
  return true;
}

void bin_into_tiles(const TriangleSetup& t, uint32_t local_index, const TileGrid& grid,
                    const TileIndexer& tiles, Chunk& chunk) {
  const int tx0 = tiles.column(t.min_x), tx1 = tiles.column(t.max_x);
  const int ty0 = tiles.row(t.min_y), ty1 = tiles.row(t.max_y);
  const int tiles_x = tiles.tiles_x;
  if (tx0 == tx1 && ty0 == ty1) {  // most triangles: no edge tests needed
    chunk.entries.push_back({static_cast<uint32_t>(ty0 * tiles_x + tx0), local_index});
    return;
  }
  for (int ty = ty0; ty <= ty1; ++ty) {
    for (int tx = tx0; tx <= tx1; ++tx) {
      const int64_t x0 = int64_t{tx} * grid.tile_width_px * kSubpixelScale;
      const int64_t y0 = int64_t{ty} * grid.tile_height_px * kSubpixelScale;
      const int64_t x1 = std::min<int64_t>((tx + 1) * grid.tile_width_px, grid.width_px) *
                             kSubpixelScale - 1;
      const int64_t y1 = std::min<int64_t>((ty + 1) * grid.tile_height_px, grid.height_px) *
                             kSubpixelScale - 1;
      if (!triangle_touches_tile(t, x0, y0, x1, y1)) continue;
      chunk.entries.push_back({static_cast<uint32_t>(ty * tiles_x + tx), local_index});
    }
  }
}

// Set-up records are written in place: setup() opens a record at the end of the chunk (or
// returns the one still open) for setup to fill, and emit() completes it (setup leaves no field
// of an Ok triangle unset). A failed setup leaves the open record to the next triangle, and
// finish() drops it if no triangle used it.
class RecordSlot {
 public:
  explicit RecordSlot(Chunk& chunk) : chunk_(chunk) {}
  TriangleSetup& setup() {
    if (!open_) {
      chunk_.triangles.emplace_back();
      open_ = true;
    }
    return chunk_.triangles.back().setup;
  }
  void emit(const float* const vertex_varyings[3], const uint32_t vertex_ids[3],
            int varying_count, uint32_t primitive_id, const TileGrid& grid,
            const TileIndexer& tiles) {
    BinnedTriangle& bt = chunk_.triangles.back();
    for (int k = 0; k < 3; ++k) bt.vertex[k] = vertex_ids[k];
    bt.subpass = chunk_.subpass;
    bt.draw = chunk_.draw;
    bt.primitive_id = primitive_id;
    const size_t offset = chunk_.varyings.size();
    bt.varying_offset = static_cast<uint32_t>(offset);
    chunk_.varyings.resize(offset + 3 * static_cast<size_t>(varying_count));
    float* dst = chunk_.varyings.data() + offset;
    for (int slot = 0; slot < 3; ++slot, dst += varying_count) {
      const float* src = vertex_varyings[bt.setup.vertex_order[slot]];
      for (int a = 0; a < varying_count; ++a) dst[a] = src[a];
    }
    open_ = false;
    bin_into_tiles(bt.setup, static_cast<uint32_t>(chunk_.triangles.size() - 1), grid, tiles,
                   chunk_);
  }
  void finish() {
    if (open_) chunk_.triangles.pop_back();
    open_ = false;
  }

 private:
  Chunk& chunk_;
  bool open_ = false;
};

// Post-transform vertex bytes: positions for every vertex, varyings for every vertex without
// IDVS and, with it, only for those a binned record references (parameter_buffer.h).
void add_vertex_bytes(GeometryCounters& c, uint64_t vertices, uint64_t varying_vertices,
                      uint64_t varying_bytes_per_vertex) {
  const uint64_t positions = uint64_t{kPositionBytes} * vertices;
  const uint64_t varyings = varying_bytes_per_vertex * varying_vertices;
  c.parameter_position_bytes_written += positions;
  c.parameter_varying_bytes_written += varyings;
  c.parameter_bytes_written += positions + varyings;
}

void process_chunk(const DrawCall& draw, ShadedDraw& shaded, const TileGrid& grid,
                   const GuardBand& guard, const VertexOutputModel& model, Chunk& chunk) {
  const int n = shaded.varying_count;
  const uint64_t varying_bytes = uint64_t{model.varying_component_bytes} * static_cast<uint64_t>(n);
  GeometryCounters& c = chunk.counters;
  chunk.triangles.reserve(chunk.triangle_count);
  chunk.varyings.reserve(static_cast<size_t>(chunk.triangle_count) * 3 * n);
  chunk.entries.reserve(chunk.triangle_count * 2);
  const TileIndexer tiles(grid);
  RecordSlot record(chunk);
  ClipPolygon polygon;
  for (uint32_t tri = chunk.first_triangle; tri < chunk.first_triangle + chunk.triangle_count;
       ++tri) {
    ++c.triangles_submitted;
    const uint32_t* ids = draw.indices + size_t{3} * tri;
    for (int k = 0; k < 3; ++k) {
      if (ids[k] >= draw.vertex_count) {
        throw Error("draw index " + std::to_string(ids[k]) + " out of range (vertex count " +
                    std::to_string(draw.vertex_count) + ")");
      }
      shaded.referenced[ids[k]].store(1, std::memory_order_relaxed);
    }
    const unsigned c0 = shaded.outcode[ids[0]], c1 = shaded.outcode[ids[1]],
                   c2 = shaded.outcode[ids[2]];
    if ((c0 | c1 | c2) & kNonFiniteVertex) { ++c.triangles_non_finite; continue; }
    // All on the wrong side of one plane (clip_triangle's trivial rejection).
    if (c0 & c1 & c2) { ++c.triangles_outside; continue; }
    const unsigned planes = (c0 | c1 | c2) & kClippingPlaneMask;
    const uint32_t primitive_id = draw.primitive_id_base + tri;
    const float* var[3];
    for (int k = 0; k < 3; ++k) var[k] = shaded.varyings.data() + static_cast<size_t>(ids[k]) * n;

    if (planes == 0) {
      // Inside every clipping plane: set up from the vertices snapped once per draw.
      const SnappedVertex vertex[3] = {shaded.snapped[ids[0]], shaded.snapped[ids[1]],
                                       shaded.snapped[ids[2]]};
      const SetupResult r = setup_snapped_triangle(vertex, grid.width_px, grid.height_px,
                                                   draw.raster.cull, draw.raster.front_face,
                                                   record.setup());
      if (r == SetupResult::Ok) {
        record.emit(var, ids, n, primitive_id, grid, tiles);
        if (model.idvs) {
          for (int k = 0; k < 3; ++k) shaded.varyings_written[ids[k]].store(1, std::memory_order_relaxed);
        }
      } else if (r == SetupResult::Culled) {
        ++c.triangles_culled;
      } else if (r == SetupResult::ZeroArea) {
        ++c.triangles_zero_area;
      } else {
        ++c.triangles_outside;
      }
      continue;
    }
    const glm::vec4 pos[3] = {shaded.positions[ids[0]], shaded.positions[ids[1]],
                              shaded.positions[ids[2]]};
    if (clip_against_planes(pos, var, n, guard, planes, polygon) == ClipOutcome::Outside) {
      ++c.triangles_outside;
      continue;
    }
    // Clipped: the polygon's vertices are new post-transform vertices; draw it as a fan.
    ++c.triangles_clipped;
    bool any_emitted = false, any_culled = false;
    uint32_t emitted_vertices = 0;  // bit i: polygon vertex i is in an emitted fan triangle
    for (int i = 1; i + 1 < polygon.count; ++i) {
      const glm::vec4 fan_pos[3] = {polygon.position[0], polygon.position[i],
                                    polygon.position[i + 1]};
      const float* fan_var[3] = {polygon.varyings[0], polygon.varyings[i],
                                 polygon.varyings[i + 1]};
      const SetupResult r = setup_triangle(fan_pos, grid.width_px, grid.height_px,
                                           draw.raster.cull, draw.raster.front_face,
                                           record.setup(), grid.subpixel_bits);
      if (r == SetupResult::Ok) {
        const uint32_t base = kClippedVertex | chunk.clipped_vertices;
        const uint32_t fan_ids[3] = {base, base + static_cast<uint32_t>(i),
                                     base + static_cast<uint32_t>(i + 1)};
        record.emit(fan_var, fan_ids, n, primitive_id, grid, tiles);
        any_emitted = true;
        emitted_vertices |= 1u | (1u << i) | (1u << (i + 1));
      }
      any_culled = any_culled || r == SetupResult::Culled;
    }
    add_vertex_bytes(c, static_cast<uint64_t>(polygon.count),
                     model.idvs ? static_cast<uint64_t>(std::popcount(emitted_vertices))
                                : static_cast<uint64_t>(polygon.count),
                     varying_bytes);
    chunk.clipped_vertices += static_cast<uint32_t>(polygon.count);
    if (!any_emitted) ++(any_culled ? c.triangles_culled : c.triangles_outside);
  }
  record.finish();
  c.triangles_binned += chunk.triangles.size();
  c.tile_list_entries += chunk.entries.size();
  c.parameter_bytes_written += uint64_t{kPrimitiveRecordBytes} * chunk.triangles.size() +
                               uint64_t{kTileListEntryBytes} * chunk.entries.size();
}

}  // namespace

ParameterBuffer bin_triangles(const RenderPassDesc& pass, const TileGrid& grid,
                              const VertexOutputModel& vertex_output) {
  ParameterBuffer pb;
  pb.grid = grid;
  pb.vertex_output = vertex_output;
  const GuardBand guard = GuardBand::for_viewport(grid.width_px, grid.height_px);

  // Vertex shading and per-draw fetch traffic.
  std::vector<std::vector<ShadedDraw>> shaded(pass.subpasses.size());
  struct ChunkInput {
    uint32_t subpass, draw, first_triangle, triangle_count;
  };
  std::vector<ChunkInput> inputs;
  for (uint32_t s = 0; s < pass.subpasses.size(); ++s) {
    for (uint32_t d = 0; d < pass.subpasses[s].draws.size(); ++d) {
      const DrawCall& draw = pass.subpasses[s].draws[d];
      if (draw.index_count % 3 != 0) {
        throw Error("pass '" + pass.name + "': draw with " + std::to_string(draw.index_count) +
                    " indices (not a multiple of 3)");
      }
      shaded[s].push_back(shade_draw(draw, grid, guard, pb.counters, vertex_output.idvs));
      pb.counters.index_bytes_read += uint64_t{draw.index_bytes} * draw.index_count;
      const uint32_t triangles = draw.index_count / 3;
      for (uint32_t first = 0; first < triangles; first += kTrianglesPerChunk) {
        inputs.push_back({s, d, first, std::min(kTrianglesPerChunk, triangles - first)});
      }
    }
  }

  if (inputs.size() >= (size_t{1} << (32 - kChunkLocalBits))) {
    throw Error("pass '" + pass.name + "': too many triangles for one parameter buffer");
  }
  pb.chunks.resize(inputs.size());
  std::vector<Chunk> chunks;
  chunks.reserve(inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i) {
    chunks.push_back(Chunk{inputs[i].subpass, inputs[i].draw, inputs[i].first_triangle,
                           inputs[i].triangle_count, pb.chunks[i].triangles,
                           pb.chunks[i].varyings, {}, {}, 0, {}});
  }
  ontile::parallel_for(size_t{0}, chunks.size(), [&](size_t i) {
    Chunk& c = chunks[i];
    process_chunk(pass.subpasses[c.subpass].draws[c.draw], shaded[c.subpass][c.draw], grid, guard,
                  vertex_output, c);
  });
  // Fetch traffic of the unique vertices each draw's indices referenced.
  for (uint32_t s = 0; s < pass.subpasses.size(); ++s) {
    for (uint32_t d = 0; d < pass.subpasses[s].draws.size(); ++d) {
      const ShadedDraw& draw = shaded[s][d];
      const uint64_t unique = count_referenced_vertices(draw);
      pb.counters.vertex_bytes_read += unique * pass.subpasses[s].draws[d].input_vertex_bytes;
      add_vertex_bytes(pb.counters, unique,
                       vertex_output.idvs ? count_varying_vertices(draw) : unique,
                       uint64_t{vertex_output.varying_component_bytes} *
                           static_cast<uint64_t>(draw.varying_count));
    }
  }
  shaded.clear();
  for (size_t i = 0; i < chunks.size(); ++i) {
    pb.counters.add(chunks[i].counters);
    pb.chunks[i].clipped_vertices = chunks[i].clipped_vertices;
  }

  // Per-tile lists (CSR) by a stable counting sort of the (tile, triangle) pairs, which the
  // chunks hold in submission order.
  const int tile_count = grid.tile_count();
  pb.tile_offsets.assign(tile_count + 1, 0);
  for (const Chunk& c : chunks) {
    for (const TileEntry& e : c.entries) ++pb.tile_offsets[e.tile + 1];
  }
  for (int t = 0; t < tile_count; ++t) pb.tile_offsets[t + 1] += pb.tile_offsets[t];
  pb.tile_entries.resize(pb.tile_offsets.back());
  std::vector<uint32_t> cursor(pb.tile_offsets.begin(), pb.tile_offsets.end() - 1);
  for (size_t i = 0; i < chunks.size(); ++i) {
    const Chunk& c = chunks[i];
    const uint32_t chunk_bits = static_cast<uint32_t>(i) << kChunkLocalBits;
    for (const TileEntry& e : c.entries) {
      pb.tile_entries[cursor[e.tile]++] = chunk_bits | e.triangle;
    }
  }
  return pb;
}

}  // namespace ontile
