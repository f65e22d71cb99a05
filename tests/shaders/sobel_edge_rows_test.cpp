// find_edges_rows (pixel rows on the lanes) against find_edges (gathered taps): the same edge
// masks and, on edges, the same nearest taps for full-screen 16x4 batches over random decoded
// grids with and without normals, on every SIMD target; other batches are declined.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "raster/cell_raster.h"
#include "shaders_cpp/toon/sobel_edge_kernel.h"

namespace ontile::sobel {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

// A 16x4 batch in quad order at (x0, y0) of an 18x6 grid (taps its neighbours).
void full_screen_taps(int x0, int y0, FragmentTaps& taps) {
  for (int f = 0; f < kBatchFragments; ++f) {
    const int quad = f / 4, lane = f % 4;
    const int x = x0 + 1 + 2 * (quad % 8) + (lane & 1);
    const int y = y0 + 1 + 2 * (quad / 8) + (lane >> 1);
    for (int a = 0; a < kTapsPerAxis; ++a) {
      taps.x[a][f] = x + a - 1;
      taps.y[a][f] = y + a - 1;
    }
    taps.color_x[f] = x;
    taps.color_y[f] = y;
  }
  taps.x0 = x0;
  taps.y0 = y0;
  taps.x1 = x0 + 17;
  taps.y1 = y0 + 5;
}

TEST(SobelEdgeRows, MatchTheGatheringKernel) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const std::vector<std::string> targets = simd_targets();
  const AutomaticTargetOnExit restore;
  int edges_seen = 0, depth_edges_seen = 0;
  for (int trial = 0; trial < 200; ++trial) {
    force_simd_target(targets[trial % targets.size()]);
    NeighbourhoodGrid grid;
    grid.x0 = static_cast<int>(rng() % 100);
    grid.y0 = static_cast<int>(rng() % 100);
    grid.width = 18;
    grid.height = 6;
    // Surfaces at a few depths with steps between them, normals from a few directions.
    const float base = 1.0f + 20.0f * unit(rng);
    for (int cell = 0; cell < grid.width * grid.height; ++cell) {
      const float step = rng() % 6 == 0 ? 0.5f * unit(rng) : 0.0f;
      grid.depth[cell] = 0.9f + 0.05f * unit(rng) + step;
      grid.linear_z[cell] = base * (1.0f + step) + 0.01f * unit(rng);
      const float tilt = rng() % 5 == 0 ? unit(rng) : 0.05f * unit(rng);
      grid.normal[0][cell] = tilt;
      grid.normal[1][cell] = trial % 7 == 0 ? 0.0f : 0.3f * tilt;
      grid.normal[2][cell] = trial % 11 == 0 ? 0.0f : 1.0f - tilt;
    }
    FragmentTaps taps;
    full_screen_taps(grid.x0, grid.y0, taps);
    float u[kBatchFragments], v[kBatchFragments];
    for (int f = 0; f < kBatchFragments; ++f) {
      u[f] = unit(rng);
      v[f] = unit(rng);
    }
    EdgeTest test;
    test.depth_limit_scale = 0.2f * unit(rng);
    test.has_normal = trial % 3 != 0;
    test.normal_threshold = 0.5f + 2.0f * unit(rng);
    test.view_ray_scale = {unit(rng), unit(rng)};
    test.min_grazing_cosine = 0.1f;
    FragmentEdges expected, got;
    find_edges(u, v, kBatchFragments, taps, grid, test, expected);
    ASSERT_TRUE(find_edges_rows(u, v, kBatchFragments, ~uint64_t{0}, taps, grid, test, got))
        << "trial " << trial;
    ASSERT_EQ(got.depth_edge, expected.depth_edge) << "trial " << trial;
    ASSERT_EQ(got.edge, expected.edge) << "trial " << trial;
    for (uint64_t rest = expected.edge; rest != 0; rest &= rest - 1) {
      const int f = std::countr_zero(rest);
      ASSERT_EQ(got.nearest_tap[f], expected.nearest_tap[f]) << "trial " << trial << " f " << f;
    }
    edges_seen += std::popcount(expected.edge & ~expected.depth_edge);
    depth_edges_seen += std::popcount(expected.depth_edge);
  }
  EXPECT_GT(edges_seen, 200);        // normal edges
  EXPECT_GT(depth_edges_seen, 200);  // depth edges
  EXPECT_LT(depth_edges_seen, 200 * 60);
}

TEST(SobelEdgeRows, DeclineOtherBatches) {
  NeighbourhoodGrid grid;
  grid.x0 = 4;
  grid.y0 = 8;
  grid.width = 18;
  grid.height = 6;
  for (int cell = 0; cell < grid.width * grid.height; ++cell) {
    grid.depth[cell] = grid.linear_z[cell] = 1.0f;
    grid.normal[0][cell] = grid.normal[1][cell] = 0.0f;
    grid.normal[2][cell] = 1.0f;
  }
  FragmentTaps taps;
  full_screen_taps(grid.x0, grid.y0, taps);
  float u[kBatchFragments] = {}, v[kBatchFragments] = {};
  EdgeTest test;
  FragmentEdges edges;
  EXPECT_TRUE(find_edges_rows(u, v, kBatchFragments, ~uint64_t{0}, taps, grid, test, edges));
  EXPECT_FALSE(find_edges_rows(u, v, kBatchFragments, ~uint64_t{0} >> 1, taps, grid, test, edges));
  EXPECT_FALSE(find_edges_rows(u, v, 48, ~uint64_t{0} >> 16, taps, grid, test, edges));
  FragmentTaps clamped = taps;
  clamped.y[0][5] = clamped.y[1][5];  // a top row clamped to the texture
  EXPECT_FALSE(find_edges_rows(u, v, kBatchFragments, ~uint64_t{0}, clamped, grid, test, edges));
  FragmentTaps thick = taps;
  thick.x[2][9] += 1;  // taps two texels apart
  EXPECT_FALSE(find_edges_rows(u, v, kBatchFragments, ~uint64_t{0}, thick, grid, test, edges));
  FragmentTaps moved = taps;
  std::swap(moved.x[1][0], moved.x[1][1]);  // not in quad order
  EXPECT_FALSE(find_edges_rows(u, v, kBatchFragments, ~uint64_t{0}, moved, grid, test, edges));
}

}  // namespace
}  // namespace ontile::sobel
