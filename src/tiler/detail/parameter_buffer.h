// The per-pass parameter buffer a tiler writes while binning and every tile reads: set-up
// triangles with their varyings, and a primitive list per screen tile (CSR layout, each list
// in submission order so tiles replay draws exactly as recorded).
#pragma once
#include <cstdint>
#include <vector>

#include "raster/triangle_setup.h"
#include "tiler/pass_report.h"
#include "tiler/render_pass.h"
#include "util/uninitialized_vector.h"

namespace ontile {

struct BinnedTriangle {
  TriangleSetup setup;
  uint32_t varying_offset = 0;  // into its chunk's varyings: 3 * varying_count floats, in
                                // setup slot order
  uint32_t subpass = 0;
  uint32_t draw = 0;            // index into the subpass's draws
  uint32_t primitive_id = 0;
  // The post-transform vertices the record references (for the parameter-cache layout): an
  // index into the draw's shaded vertices, or kClippedVertex | a chunk-local index of the
  // vertices clipping created.
  uint32_t vertex[3] = {0, 0, 0};
};
constexpr uint32_t kClippedVertex = 0x80000000u;

struct TileGrid {
  int width_px = 0, height_px = 0;
  int tile_width_px = 16, tile_height_px = 16;
  int subpixel_bits = kSubpixelBits;  // vertex snapping precision (TilerConfig::subpixel_bits)
  int tiles_x() const { return (width_px + tile_width_px - 1) / tile_width_px; }
  int tiles_y() const { return (height_px + tile_height_px - 1) / tile_height_px; }
  int tile_count() const { return tiles_x() * tiles_y(); }
};

// Bytes the memory model charges for parameter-buffer records (see docs/memory-model.md).
constexpr uint32_t kPositionBytes = 16;         // post-transform x, y, z, w as float32
constexpr uint32_t kPrimitiveRecordBytes = 12;  // three 32-bit vertex references
constexpr uint32_t kTileListEntryBytes = 4;     // one 32-bit primitive reference per tile
// varying_component_bytes: 4 for fp32 varyings, 2 for fp16 (TilerConfig::varying_precision).
inline uint32_t post_transform_vertex_bytes(int varying_count, uint32_t varying_component_bytes = 4) {
  return kPositionBytes + varying_component_bytes * static_cast<uint32_t>(varying_count);
}

// How binning writes post-transform vertices (TilerConfig::idvs and varying_precision). With
// index-driven vertex shading (Mali Bifrost/Valhall) positions are written for every vertex the
// indices reference, varyings only for the vertices a binned triangle record references; without
// it every referenced vertex is written whole. Varyings are stored at varying_component_bytes
// each; ontile still interpolates them in fp32 (the model prices storage, not precision).
struct VertexOutputModel {
  bool idvs = false;
  uint32_t varying_component_bytes = 4;
};

// The triangles set up from one run of consecutive input triangles of a draw. Binning works
// chunk by chunk in parallel and the chunks stay where they were built (no merge copy).
struct TriangleChunk {
  // Grown one record at a time and then written in full, so neither is zero-filled first.
  UninitializedVector<BinnedTriangle> triangles;
  UninitializedVector<float> varyings;
  uint32_t clipped_vertices = 0;  // post-transform vertices clipping added
};

// A tile-list entry names a triangle as (chunk << kChunkLocalBits) | index within the chunk.
// A chunk holds at most kTrianglesPerChunk inputs, each clipped into at most
// ClipPolygon::kMaxVertices - 2 triangles, which stays below 2^kChunkLocalBits.
constexpr uint32_t kChunkLocalBits = 16;
constexpr uint32_t kTrianglesPerChunk = 4096;

struct ParameterBuffer {
  TileGrid grid;
  std::vector<TriangleChunk> chunks;
  std::vector<uint32_t> tile_offsets;  // tile_count + 1 entries
  UninitializedVector<uint32_t> tile_entries;  // triangle references, per tile in submission order
  GeometryCounters counters;
  VertexOutputModel vertex_output;

  const BinnedTriangle& triangle(uint32_t ref) const {
    return chunks[ref >> kChunkLocalBits].triangles[ref & ((1u << kChunkLocalBits) - 1)];
  }
  const float* varyings(uint32_t ref, const BinnedTriangle& t) const {
    return chunks[ref >> kChunkLocalBits].varyings.data() + t.varying_offset;
  }
};

// Runs the geometry phase of a pass: vertex shading, primitive assembly, NaN/Inf rejection,
// clipping, setup, culling and binning into the tiles whose area each triangle's edges touch.
// Runs in parallel on the current oneTBB arena; the result does not depend on thread count.
ParameterBuffer bin_triangles(const RenderPassDesc& pass, const TileGrid& grid,
                              const VertexOutputModel& vertex_output = {});

}  // namespace ontile
