// SIMD stages of the screen-space Sobel edge pass (sobel_edge_shader.h) over a batch's
// fragments: tap texel coordinates, the neighbourhood's depth and normals decoded once per
// texel, and the edge tests. Highway, one build per target; IEEE add, multiply, divide, sqrt and
// compare only (no fused multiply-add), so every target gives the bits of the scalar code.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"
#include "shaders_cpp/toon/toon_outputs.h"

namespace ontile::sobel {

constexpr int kTapsPerAxis = 3;
constexpr int kTaps = kTapsPerAxis * kTapsPerAxis;
constexpr int kCentreTap = 4;
// The largest neighbourhood decoded at once; a batch whose taps span more texels (scattered
// uvs, very thick lines) is shaded fragment by fragment instead. A full-screen batch of a
// 16x16 tile spans (16 + 2 t) x (4 + 2 t) texels at thickness t.
constexpr int kMaxGridTexels = 1024;

// Where the taps of each fragment land: tap (a, b) of fragment f (column a, row b, offsets
// a - 1 and b - 1 steps) reads texel (x[a][f], y[b][f]) of the depth grid; the colour sample
// reads (color_x[f], color_y[f]) of the colour texture. Each is sample_lod's nearest,
// clamp-to-edge texel of level 0, operation for operation (see nearest_clamped_texel).
struct FragmentTaps {
  alignas(64) int32_t x[kTapsPerAxis][kBatchFragments];
  alignas(64) int32_t y[kTapsPerAxis][kBatchFragments];
  alignas(64) int32_t color_x[kBatchFragments];
  alignas(64) int32_t color_y[kBatchFragments];
  // The texels the active fragments' taps span (inclusive); empty (x0 > x1) without any.
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
};

struct TapLayout {
  float offset_u[kTapsPerAxis], offset_v[kTapsPerAxis];  // (a - 1) * step, rounded as a float
  int grid_width = 0, grid_height = 0;                   // depth (= normal, border) size
  int color_width = 0, color_height = 0;
};

// Fills taps for fragments [0, count) (count a multiple of 16, at most kBatchFragments) from
// their uv, and the box of the fragments whose bit is set in active.
void tap_texels(const float* u, const float* v, int count, uint64_t active,
                const TapLayout& layout, FragmentTaps& taps);

// Depth to view distance (linearize_depth) with its constants folded: the same operations.
struct DepthDecode {
  enum Mode : int32_t { Perspective, InfinitePerspective, Orthographic } mode = Perspective;
  float near_plane = 0.0f;
  float far_times_near = 0.0f;  // f * n
  float far_minus_near = 0.0f;  // f - n
};

// Texels [x0, x0 + width) x [y0, y0 + height) of the depth (and normal) buffer, decoded:
// cell (x - x0) + (y - y0) * width holds the stored depth, its view distance and the decoded
// view normal (zero when there is no normal buffer).
struct NeighbourhoodGrid {
  int x0 = 0, y0 = 0, width = 0, height = 0;
  alignas(64) float depth[kMaxGridTexels];
  alignas(64) float linear_z[kMaxGridTexels];
  alignas(64) float normal[3][kMaxGridTexels];
};

// Decodes the grid whose origin and size are set (width * height <= kMaxGridTexels).
void decode_grid(const Texture2D::TexelView& depth, const Texture2D::TexelView* normal,
                 NormalEncoding encoding, const DepthDecode& decode, NeighbourhoodGrid& grid);

struct EdgeTest {
  float depth_limit_scale = 0.0f;  // depth_threshold * depth_sensitivity
  bool has_normal = false;
  float normal_threshold = 0.0f;
  glm::vec2 view_ray_scale{0.0f};
  float min_grazing_cosine = 0.0f;
};

// Per fragment: whether depth, or else the normals, found an edge, and on an edge the tap of
// the smallest depth (elsewhere it may be the centre tap: only edges read it). Bit f of the
// masks is fragment f.
struct FragmentEdges {
  alignas(64) int32_t nearest_tap[kBatchFragments];
  uint64_t depth_edge = 0;
  uint64_t edge = 0;
};

// The edge tests of fragments [0, count) whose taps lie in the grid (others read clamped
// cells and get meaningless results).
void find_edges(const float* u, const float* v, int count, const FragmentTaps& taps,
                const NeighbourhoodGrid& grid, const EdgeTest& test, FragmentEdges& edges);

// find_edges for a whole batch (count kBatchFragments, every fragment active) of 16x4 pixels
// in quad order whose taps are each pixel's neighbours in a grid of 18x6 texels (a full-screen
// batch inside the texture): the same results, with pixel rows on the lanes (taps loaded, not
// gathered). Returns false, doing nothing, for any other batch.
bool find_edges_rows(const float* u, const float* v, int count, uint64_t active,
                     const FragmentTaps& taps, const NeighbourhoodGrid& grid,
                     const EdgeTest& test, FragmentEdges& edges);

}  // namespace ontile::sobel
