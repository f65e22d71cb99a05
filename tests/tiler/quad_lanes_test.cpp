// The quad lane helpers of the batcher: lanes_of (a lane is covered when any of its sample bits
// is) and lane_count, against the plain per-lane definitions.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

#include "tiler/detail/quad_batcher.h"

namespace ontile {
namespace {

uint8_t lanes_by_loop(QuadCoverage coverage) {
  uint8_t lanes = 0;
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    if (lane_coverage(coverage, lane)) lanes |= static_cast<uint8_t>(1u << lane);
  }
  return lanes;
}

TEST(QuadLanes, LanesOfMatchesThePerLaneDefinition) {
  // Every single and double sample bit, then a stride through all 2^32 coverages.
  for (int a = 0; a < 32; ++a) {
    for (int b = 0; b < 32; ++b) {
      const QuadCoverage c = (QuadCoverage{1} << a) | (QuadCoverage{1} << b);
      ASSERT_EQ(lanes_of(c), lanes_by_loop(c)) << c;
    }
  }
  for (uint64_t c = 0; c <= 0xFFFFFFFFu; c += 65521) {
    ASSERT_EQ(lanes_of(static_cast<QuadCoverage>(c)), lanes_by_loop(static_cast<QuadCoverage>(c)));
  }
  EXPECT_EQ(lanes_of(0), 0);
  EXPECT_EQ(lanes_of(0xFFFFFFFFu), 0xF);
}

TEST(QuadLanes, LaneCountIsThePopulationCount) {
  for (unsigned lanes = 0; lanes < 16; ++lanes) {
    EXPECT_EQ(lane_count(static_cast<uint8_t>(lanes)), std::popcount(lanes)) << lanes;
  }
}

}  // namespace
}  // namespace ontile
