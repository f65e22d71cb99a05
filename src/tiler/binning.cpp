// Geometry phase of a pass (see parameter_buffer.h): vertex shading, assembly, clipping, setup
// and binning, in parallel chunks whose outputs are concatenated in submission order.
#include <algorithm>
#include <atomic>
#include <cmath>

#include <tbb/parallel_for.h>

#include "raster/clip.h"
#include "tiler/parameter_buffer.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr uint32_t kVertexGrain = 2048;

struct ShadedDraw {
  int varying_count = 0;
  std::vector<glm::vec4> positions;
  std::vector<float> varyings;
};

ShadedDraw shade_vertices(const DrawCall& draw, GeometryCounters& counters) {
  ShadedDraw shaded;
  shaded.varying_count = draw.vertex_shader->varying_count();
  if (shaded.varying_count < 0 || shaded.varying_count > kMaxVaryings) {
    throw Error("vertex shader declares " + std::to_string(shaded.varying_count) +
                " varyings (at most " + std::to_string(kMaxVaryings) + ")");
  }
  const int n = shaded.varying_count;
  shaded.positions.resize(draw.vertex_count);
  shaded.varyings.resize(static_cast<size_t>(draw.vertex_count) * n);
  std::atomic<uint64_t> sanitized{0};
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, draw.vertex_count, kVertexGrain),
                    [&](const tbb::blocked_range<uint32_t>& r) {
    float* var = shaded.varyings.data() + static_cast<size_t>(r.begin()) * n;
    draw.vertex_shader->shade(r.begin(), r.size(), shaded.positions.data() + r.begin(), var);
    // A NaN/Inf varying would poison every pixel it touches; replace it and count it.
    uint64_t bad = 0;
    for (size_t i = 0; i < r.size() * n; ++i) {
      if (!std::isfinite(var[i])) { var[i] = 0.0f; ++bad; }
    }
    if (bad) sanitized += bad;
  });
  counters.vertices_shaded += draw.vertex_count;
  counters.varyings_sanitized += sanitized.load();
  return shaded;
}

// Unique vertices the index buffer references: what a vertex fetch reads from memory.
uint64_t count_unique_vertices(const DrawCall& draw) {
  std::vector<uint8_t> seen(draw.vertex_count, 0);
  uint64_t unique = 0;
  for (uint32_t i = 0; i < draw.index_count; ++i) {
    const uint32_t v = draw.indices[i];
    if (v < draw.vertex_count && !seen[v]) { seen[v] = 1; ++unique; }
  }
  return unique;
}

struct Chunk {
  uint32_t subpass = 0, draw = 0;
  uint32_t first_triangle = 0, triangle_count = 0;
  // Outputs.
  std::vector<BinnedTriangle>& triangles;
  std::vector<float>& varyings;
  std::vector<uint32_t> entry_tile;      // tile of each (tile, triangle) pair
  std::vector<uint32_t> entry_triangle;  // chunk-local triangle of each pair
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
                    Chunk& chunk) {
  const int tx0 = t.min_x / grid.tile_width_px, tx1 = t.max_x / grid.tile_width_px;
  const int ty0 = t.min_y / grid.tile_height_px, ty1 = t.max_y / grid.tile_height_px;
  const bool single_tile = tx0 == tx1 && ty0 == ty1;
  for (int ty = ty0; ty <= ty1; ++ty) {
    for (int tx = tx0; tx <= tx1; ++tx) {
      if (!single_tile) {
        const int64_t x0 = int64_t{tx} * grid.tile_width_px * kSubpixelScale;
        const int64_t y0 = int64_t{ty} * grid.tile_height_px * kSubpixelScale;
        const int64_t x1 = std::min<int64_t>((tx + 1) * grid.tile_width_px, grid.width_px) *
                               kSubpixelScale - 1;
        const int64_t y1 = std::min<int64_t>((ty + 1) * grid.tile_height_px, grid.height_px) *
                               kSubpixelScale - 1;
        if (!triangle_touches_tile(t, x0, y0, x1, y1)) continue;
      }
      chunk.entry_tile.push_back(static_cast<uint32_t>(ty * grid.tiles_x() + tx));
      chunk.entry_triangle.push_back(local_index);
    }
  }
}

void emit_triangle(const TriangleSetup& setup, const float* const vertex_varyings[3],
                   const uint32_t vertex_ids[3], int varying_count, uint32_t primitive_id,
                   const TileGrid& grid, Chunk& chunk) {
  BinnedTriangle bt;
  bt.setup = setup;
  for (int k = 0; k < 3; ++k) bt.vertex[k] = vertex_ids[k];
  bt.subpass = chunk.subpass;
  bt.draw = chunk.draw;
  bt.primitive_id = primitive_id;
  bt.varying_offset = static_cast<uint32_t>(chunk.varyings.size());
  for (int slot = 0; slot < 3; ++slot) {
    const float* src = vertex_varyings[setup.vertex_order[slot]];
    chunk.varyings.insert(chunk.varyings.end(), src, src + varying_count);
  }
  const uint32_t local_index = static_cast<uint32_t>(chunk.triangles.size());
  chunk.triangles.push_back(bt);
  bin_into_tiles(setup, local_index, grid, chunk);
}

void process_chunk(const DrawCall& draw, const ShadedDraw& shaded, const TileGrid& grid,
                   const GuardBand& guard, Chunk& chunk) {
  const int n = shaded.varying_count;
  const uint32_t vertex_bytes = post_transform_vertex_bytes(n);
  GeometryCounters& c = chunk.counters;
  chunk.triangles.reserve(chunk.triangle_count);
  chunk.varyings.reserve(static_cast<size_t>(chunk.triangle_count) * 3 * n);
  chunk.entry_tile.reserve(chunk.triangle_count * 2);
  chunk.entry_triangle.reserve(chunk.triangle_count * 2);
  ClipPolygon polygon;
  for (uint32_t tri = chunk.first_triangle; tri < chunk.first_triangle + chunk.triangle_count;
       ++tri) {
    ++c.triangles_submitted;
    glm::vec4 pos[3];
    const float* var[3];
    bool finite = true;
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = draw.indices[3 * tri + k];
      if (v >= draw.vertex_count) {
        throw Error("draw index " + std::to_string(v) + " out of range (vertex count " +
                    std::to_string(draw.vertex_count) + ")");
      }
      pos[k] = shaded.positions[v];
      var[k] = shaded.varyings.data() + static_cast<size_t>(v) * n;
      finite = finite && std::isfinite(pos[k].x) && std::isfinite(pos[k].y) &&
               std::isfinite(pos[k].z) && std::isfinite(pos[k].w);
    }
    if (!finite) { ++c.triangles_non_finite; continue; }
    const uint32_t primitive_id = draw.primitive_id_base + tri;
    const ClipOutcome outcome = clip_triangle(pos, var, n, guard, polygon);
    if (outcome == ClipOutcome::Outside) { ++c.triangles_outside; continue; }

    TriangleSetup setup;
    if (outcome == ClipOutcome::Inside) {
      const SetupResult r = setup_triangle(pos, grid.width_px, grid.height_px, draw.raster.cull,
                                           draw.raster.front_face, setup, grid.subpixel_bits);
      if (r == SetupResult::Ok) {
        const uint32_t ids[3] = {draw.indices[3 * tri], draw.indices[3 * tri + 1], draw.indices[3 * tri + 2]};
        emit_triangle(setup, var, ids, n, primitive_id, grid, chunk);
      } else if (r == SetupResult::Culled) {
        ++c.triangles_culled;
      } else if (r == SetupResult::ZeroArea) {
        ++c.triangles_zero_area;
      } else {
        ++c.triangles_outside;
      }
      continue;
    }
    // Clipped: the polygon's vertices are new post-transform vertices; draw it as a fan.
    ++c.triangles_clipped;
    c.parameter_bytes_written += uint64_t{vertex_bytes} * polygon.count;
    bool any_emitted = false, any_culled = false;
    for (int i = 1; i + 1 < polygon.count; ++i) {
      const glm::vec4 fan_pos[3] = {polygon.position[0], polygon.position[i],
                                    polygon.position[i + 1]};
      const float* fan_var[3] = {polygon.varyings[0], polygon.varyings[i],
                                 polygon.varyings[i + 1]};
      const SetupResult r = setup_triangle(fan_pos, grid.width_px, grid.height_px,
                                           draw.raster.cull, draw.raster.front_face, setup,
                                           grid.subpixel_bits);
      if (r == SetupResult::Ok) {
        const uint32_t base = kClippedVertex | chunk.clipped_vertices;
        const uint32_t ids[3] = {base, base + static_cast<uint32_t>(i), base + static_cast<uint32_t>(i + 1)};
        emit_triangle(setup, fan_var, ids, n, primitive_id, grid, chunk);
        any_emitted = true;
      }
      any_culled = any_culled || r == SetupResult::Culled;
    }
    chunk.clipped_vertices += static_cast<uint32_t>(polygon.count);
    if (!any_emitted) ++(any_culled ? c.triangles_culled : c.triangles_outside);
  }
  c.triangles_binned += chunk.triangles.size();
  c.tile_list_entries += chunk.entry_tile.size();
  c.parameter_bytes_written += uint64_t{kPrimitiveRecordBytes} * chunk.triangles.size() +
                               uint64_t{kTileListEntryBytes} * chunk.entry_tile.size();
}

}  // namespace

ParameterBuffer bin_triangles(const RenderPassDesc& pass, const TileGrid& grid) {
  ParameterBuffer pb;
  pb.grid = grid;
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
      shaded[s].push_back(shade_vertices(draw, pb.counters));
      const uint64_t unique = count_unique_vertices(draw);
      pb.counters.index_bytes_read += uint64_t{draw.index_bytes} * draw.index_count;
      pb.counters.vertex_bytes_read += unique * draw.input_vertex_bytes;
      pb.counters.parameter_bytes_written +=
          unique * post_transform_vertex_bytes(shaded[s].back().varying_count);
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
  tbb::parallel_for(size_t{0}, chunks.size(), [&](size_t i) {
    Chunk& c = chunks[i];
    process_chunk(pass.subpasses[c.subpass].draws[c.draw], shaded[c.subpass][c.draw], grid, guard,
                  c);
  });
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
    for (uint32_t tile : c.entry_tile) ++pb.tile_offsets[tile + 1];
  }
  for (int t = 0; t < tile_count; ++t) pb.tile_offsets[t + 1] += pb.tile_offsets[t];
  pb.tile_entries.resize(pb.tile_offsets.back());
  std::vector<uint32_t> cursor(pb.tile_offsets.begin(), pb.tile_offsets.end() - 1);
  for (size_t i = 0; i < chunks.size(); ++i) {
    const Chunk& c = chunks[i];
    const uint32_t chunk_bits = static_cast<uint32_t>(i) << kChunkLocalBits;
    for (size_t e = 0; e < c.entry_tile.size(); ++e) {
      pb.tile_entries[cursor[c.entry_tile[e]]++] = chunk_bits | c.entry_triangle[e];
    }
  }
  return pb;
}

}  // namespace ontile
