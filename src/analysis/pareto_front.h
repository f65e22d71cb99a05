// Pareto front of (cost, error) points: the settings no other setting beats on both at once.
#pragma once
#include <cstddef>
#include <vector>

namespace ontile {

struct ParetoPoint {
  double cost = 0.0;   // e.g. milliseconds or bytes per frame; lower is better
  double error = 0.0;  // lower is better
};

// Indices of the non-dominated points, sorted by cost (ties by error, then index). A point is
// dominated when another has cost <= and error <= with at least one strictly lower; identical
// points dominate neither each other, so all copies stay on the front. Points with a NaN
// coordinate are never on the front and never dominate.
std::vector<size_t> pareto_front(const std::vector<ParetoPoint>& points);

}  // namespace ontile
