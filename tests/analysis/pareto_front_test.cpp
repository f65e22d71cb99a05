// Pareto front: exact indices on a hand-made set (dominated by cost, by error, by both;
// identical copies; NaN), and agreement with the O(n^2) definition on random sets.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "analysis/pareto_front.h"

namespace ontile {
namespace {

TEST(ParetoFront, HandMadeSet) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<ParetoPoint> points = {
      {1.0, 5.0},   // 0: front
      {2.0, 3.0},   // 1: front
      {2.0, 4.0},   // 2: same cost as 1, more error
      {3.0, 3.0},   // 3: same error as 1, more cost
      {4.0, 1.0},   // 4: front
      {5.0, 1.0},   // 5: dominated by 4
      {4.0, 1.0},   // 6: identical to 4: both stay
      {0.5, 9.0},   // 7: front (cheapest)
      {nan, 0.0},   // 8: never on the front
      {6.0, 0.5},   // 9: front (most accurate)
      {1.0, 6.0},   // 10: same cost as 0, more error
      {7.0, nan},   // 11: never on the front
  };
  EXPECT_EQ(pareto_front(points), (std::vector<size_t>{7, 0, 1, 4, 6, 9}));
  EXPECT_TRUE(pareto_front({}).empty());
  EXPECT_EQ(pareto_front({{3.0, 3.0}}), (std::vector<size_t>{0}));
}

TEST(ParetoFront, MatchesTheDefinitionOnRandomSets) {
  uint32_t seed = 2024u;
  auto next = [&seed] {  // xorshift32, values on a coarse grid so ties happen
    seed ^= seed << 13; seed ^= seed >> 17; seed ^= seed << 5;
    return static_cast<double>(seed % 16);
  };
  for (int set = 0; set < 200; ++set) {
    std::vector<ParetoPoint> points(1 + set % 23);
    for (ParetoPoint& p : points) p = {next(), next()};
    std::vector<size_t> expected;
    for (size_t i = 0; i < points.size(); ++i) {
      bool dominated = false;
      for (size_t j = 0; j < points.size(); ++j) {
        const ParetoPoint &a = points[j], &b = points[i];
        dominated = dominated || (a.cost <= b.cost && a.error <= b.error && (a.cost < b.cost || a.error < b.error));
      }
      if (!dominated) expected.push_back(i);
    }
    std::vector<size_t> front = pareto_front(points);
    std::sort(front.begin(), front.end());
    EXPECT_EQ(front, expected) << "set " << set;
  }
}

}  // namespace
}  // namespace ontile
