// Binning classifies and snaps each vertex once per draw and reuses the results for every
// triangle sharing it. This checks the parameter buffer against the per-triangle path written
// plainly (clip_triangle + setup_triangle for every triangle, every tile tested): the same
// triangles, set-ups, varyings, vertex references, counters and tile lists, in the same order,
// on meshes with shared vertices inside, across and far outside the guard band, behind the eye,
// crossing the near plane and with NaN positions.
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "raster/clip.h"
#include "support/raster_harness.h"
#include "tiler/detail/parameter_buffer.h"

namespace ontile {
namespace {

struct Expected {
  std::vector<BinnedTriangle> triangles;
  std::vector<std::vector<float>> varyings;  // per triangle, in setup slot order
  std::vector<std::vector<uint32_t>> tiles;  // per tile, flat triangle indices
  GeometryCounters counters;
};

bool touches(const TriangleSetup& t, const TileGrid& g, int tx, int ty) {
  const int tx0 = t.min_x / g.tile_width_px, tx1 = t.max_x / g.tile_width_px;
  const int ty0 = t.min_y / g.tile_height_px, ty1 = t.max_y / g.tile_height_px;
  if (tx < tx0 || tx > tx1 || ty < ty0 || ty > ty1) return false;
  if (tx0 == tx1 && ty0 == ty1) return true;
  const int64_t x0 = int64_t{tx} * g.tile_width_px * kSubpixelScale;
  const int64_t y0 = int64_t{ty} * g.tile_height_px * kSubpixelScale;
  const int64_t x1 = std::min((tx + 1) * g.tile_width_px, g.width_px) * kSubpixelScale - 1;
  const int64_t y1 = std::min((ty + 1) * g.tile_height_px, g.height_px) * kSubpixelScale - 1;
  for (const EdgeFunction& e : t.edge) {
    if (e.at(e.a >= 0 ? x1 : x0, e.b >= 0 ? y1 : y0) + e.bias < 0) return false;
  }
  return true;
}

void add_triangle(const TriangleSetup& s, const float* const var[3], int n, const uint32_t ids[3],
                  uint32_t primitive_id, const TileGrid& g, Expected& e) {
  BinnedTriangle bt;
  bt.setup = s;
  bt.primitive_id = primitive_id;
  std::vector<float> v;
  for (int k = 0; k < 3; ++k) {
    bt.vertex[k] = ids[k];
    v.insert(v.end(), var[s.vertex_order[k]], var[s.vertex_order[k]] + n);
  }
  const uint32_t index = static_cast<uint32_t>(e.triangles.size());
  e.triangles.push_back(bt);
  e.varyings.push_back(v);
  for (int ty = 0; ty < g.tiles_y(); ++ty) {
    for (int tx = 0; tx < g.tiles_x(); ++tx) {
      if (touches(s, g, tx, ty)) e.tiles[ty * g.tiles_x() + tx].push_back(index);
    }
  }
}

// One draw, one subpass, every triangle classified and set up on its own.
Expected bin_per_triangle(const std::vector<glm::vec4>& pos, const std::vector<float>& var,
                          int n, const std::vector<uint32_t>& indices, CullMode cull,
                          const TileGrid& g) {
  Expected e;
  e.tiles.resize(g.tile_count());
  const GuardBand guard = GuardBand::for_viewport(g.width_px, g.height_px);
  ClipPolygon polygon;
  uint32_t clipped_vertices = 0;
  for (uint32_t tri = 0; tri < indices.size() / 3; ++tri) {
    if (tri % kTrianglesPerChunk == 0) clipped_vertices = 0;
    ++e.counters.triangles_submitted;
    const uint32_t* ids = &indices[3 * tri];
    const glm::vec4 p[3] = {pos[ids[0]], pos[ids[1]], pos[ids[2]]};
    const float* v[3] = {&var[ids[0] * n], &var[ids[1] * n], &var[ids[2] * n]};
    bool finite = true;
    for (const glm::vec4& q : p) {
      for (int k = 0; k < 4; ++k) finite = finite && std::isfinite(q[k]);
    }
    if (!finite) { ++e.counters.triangles_non_finite; continue; }
    const ClipOutcome outcome = clip_triangle(p, v, n, guard, polygon);
    if (outcome == ClipOutcome::Outside) { ++e.counters.triangles_outside; continue; }
    TriangleSetup s;
    if (outcome == ClipOutcome::Inside) {
      const SetupResult r = setup_triangle(p, g.width_px, g.height_px, cull,
                                           FrontFace::CounterClockwise, s, g.subpixel_bits);
      if (r == SetupResult::Ok) add_triangle(s, v, n, ids, tri, g, e);
      if (r == SetupResult::Culled) ++e.counters.triangles_culled;
      if (r == SetupResult::ZeroArea) ++e.counters.triangles_zero_area;
      if (r == SetupResult::OutsideViewport) ++e.counters.triangles_outside;
      continue;
    }
    ++e.counters.triangles_clipped;
    bool emitted = false, culled = false;
    for (int i = 1; i + 1 < polygon.count; ++i) {
      const glm::vec4 fp[3] = {polygon.position[0], polygon.position[i], polygon.position[i + 1]};
      const float* fv[3] = {polygon.varyings[0], polygon.varyings[i], polygon.varyings[i + 1]};
      const SetupResult r = setup_triangle(fp, g.width_px, g.height_px, cull,
                                           FrontFace::CounterClockwise, s, g.subpixel_bits);
      const uint32_t base = kClippedVertex | clipped_vertices;
      const uint32_t fan_ids[3] = {base, base + i, base + i + 1};
      if (r == SetupResult::Ok) add_triangle(s, fv, n, fan_ids, tri, g, e);
      emitted = emitted || r == SetupResult::Ok;
      culled = culled || r == SetupResult::Culled;
    }
    clipped_vertices += polygon.count;
    if (!emitted) ++(culled ? e.counters.triangles_culled : e.counters.triangles_outside);
  }
  e.counters.triangles_binned = e.triangles.size();
  return e;
}

// Vertices on a jittered grid spanning the viewport, the guard band and beyond, shared by
// several triangles each; some behind the eye, some across the near plane, a few NaN.
void make_mesh(uint32_t seed, std::vector<glm::vec4>& pos, std::vector<float>& var, int n,
               std::vector<uint32_t>& indices) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const int side = 60;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const float u = (x + 0.8f * unit(rng)) / side, v = (y + 0.8f * unit(rng)) / side;
      float w = 0.5f + 4.0f * unit(rng);
      float reach = 1.3f;
      if (unit(rng) < 0.05f) reach = 3000.0f;  // far beyond the guard band
      if (unit(rng) < 0.03f) w = -w;           // behind the eye
      float z = (unit(rng) < 0.05f ? -0.3f : 0.6f) * w;
      glm::vec4 p((2.0f * u - 1.0f) * reach * w, (2.0f * v - 1.0f) * reach * w, z, w);
      if (unit(rng) < 0.002f) p.y = std::nanf("");
      pos.push_back(p);
      for (int k = 0; k < n; ++k) var.push_back(unit(rng));
    }
  }
  for (int y = 0; y + 1 < side; ++y) {
    for (int x = 0; x + 1 < side; ++x) {
      const uint32_t a = y * side + x, b = a + 1, c = a + side, d = c + 1;
      indices.insert(indices.end(), {a, b, d, a, d, c});
    }
  }
  std::uniform_int_distribution<uint32_t> any(0, side * side - 1);
  for (int i = 0; i < 600; ++i) indices.push_back(any(rng));  // long slivers across the mesh
}

void check(const TileGrid& g, CullMode cull, uint32_t seed) {
  const int n = 3;
  std::vector<glm::vec4> pos;
  std::vector<float> var;
  std::vector<uint32_t> indices;
  make_mesh(seed, pos, var, n, indices);
  ASSERT_GT(indices.size() / 3, kTrianglesPerChunk) << "covers more than one chunk";
  test::ClipSpaceVertexShader vs(pos, var, n);
  RenderPassDesc pass;
  pass.width_px = g.width_px;
  pass.height_px = g.height_px;
  DrawCall draw;
  draw.vertex_shader = &vs;
  draw.vertex_count = vs.vertex_count();
  draw.indices = indices.data();
  draw.index_count = static_cast<uint32_t>(indices.size());
  draw.raster.cull = cull;
  pass.subpasses.push_back({{}, {}, false, {draw}});

  const ParameterBuffer pb = bin_triangles(pass, g);
  const Expected e = bin_per_triangle(pos, var, n, indices, cull, g);

  std::vector<uint32_t> chunk_base;  // flat index of each chunk's first triangle
  std::vector<const BinnedTriangle*> got;
  for (const TriangleChunk& c : pb.chunks) {
    chunk_base.push_back(static_cast<uint32_t>(got.size()));
    for (const BinnedTriangle& t : c.triangles) got.push_back(&t);
  }
  ASSERT_EQ(got.size(), e.triangles.size());
  for (size_t i = 0; i < got.size(); ++i) {
    const BinnedTriangle& a = *got[i];
    const BinnedTriangle& b = e.triangles[i];
    const TriangleSetup &s = a.setup, &r = b.setup;
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(s.x_fp[k], r.x_fp[k]) << i;
      ASSERT_EQ(s.y_fp[k], r.y_fp[k]) << i;
      ASSERT_EQ(std::memcmp(&s.depth[k], &r.depth[k], 4), 0) << i;
      ASSERT_EQ(std::memcmp(&s.inv_w[k], &r.inv_w[k], 4), 0) << i;
      ASSERT_EQ(s.edge[k].a, r.edge[k].a) << i;
      ASSERT_EQ(s.edge[k].b, r.edge[k].b) << i;
      ASSERT_EQ(s.edge[k].c, r.edge[k].c) << i;
      ASSERT_EQ(s.edge[k].bias, r.edge[k].bias) << i;
      ASSERT_EQ(s.vertex_order[k], r.vertex_order[k]) << i;
      ASSERT_EQ(a.vertex[k], b.vertex[k]) << i;
    }
    ASSERT_EQ(s.area2, r.area2) << i;
    ASSERT_EQ(s.inv_area2, r.inv_area2) << i;
    ASSERT_EQ(s.front_facing, r.front_facing) << i;
    ASSERT_EQ(s.min_x, r.min_x) << i;
    ASSERT_EQ(s.max_x, r.max_x) << i;
    ASSERT_EQ(s.min_y, r.min_y) << i;
    ASSERT_EQ(s.max_y, r.max_y) << i;
    ASSERT_EQ(a.primitive_id, b.primitive_id) << i;
  }
  uint32_t flat = 0;
  for (const TriangleChunk& c : pb.chunks) {
    for (const BinnedTriangle& t : c.triangles) {
      const std::vector<float> v(c.varyings.data() + t.varying_offset,
                                 c.varyings.data() + t.varying_offset + 3 * n);
      ASSERT_EQ(v, e.varyings[flat]) << flat;
      ++flat;
    }
  }
  for (int tile = 0; tile < g.tile_count(); ++tile) {
    std::vector<uint32_t> list;
    for (uint32_t k = pb.tile_offsets[tile]; k < pb.tile_offsets[tile + 1]; ++k) {
      const uint32_t ref = pb.tile_entries[k];
      list.push_back(chunk_base[ref >> kChunkLocalBits] + (ref & ((1u << kChunkLocalBits) - 1)));
    }
    ASSERT_EQ(list, e.tiles[tile]) << "tile " << tile;
  }
  const GeometryCounters& c = pb.counters;
  EXPECT_EQ(c.triangles_submitted, e.counters.triangles_submitted);
  EXPECT_EQ(c.triangles_non_finite, e.counters.triangles_non_finite);
  EXPECT_EQ(c.triangles_culled, e.counters.triangles_culled);
  EXPECT_EQ(c.triangles_zero_area, e.counters.triangles_zero_area);
  EXPECT_EQ(c.triangles_outside, e.counters.triangles_outside);
  EXPECT_EQ(c.triangles_clipped, e.counters.triangles_clipped);
  EXPECT_EQ(c.triangles_binned, e.counters.triangles_binned);
  // The mesh exercises every path.
  EXPECT_GT(e.counters.triangles_non_finite, 0u);
  EXPECT_GT(e.counters.triangles_outside, 0u);
  EXPECT_GT(e.counters.triangles_clipped, 0u);
  EXPECT_GT(e.counters.triangles_binned, 1000u);
  if (cull != CullMode::None) {
    EXPECT_GT(e.counters.triangles_culled, 0u);
  }
}

TEST(BinningReuse, PerVertexClassificationBinsLikePerTriangleSetup) {
  check(TileGrid{320, 200, 16, 16, kSubpixelBits}, CullMode::Back, 1);
  check(TileGrid{333, 177, 16, 8, kSubpixelBits}, CullMode::None, 2);
  check(TileGrid{320, 200, 32, 32, kMinSubpixelBits}, CullMode::Front, 3);
  check(TileGrid{64, 48, 4, 2, kSubpixelBits}, CullMode::Back, 4);
}

}  // namespace
}  // namespace ontile
