// Pareto front (see pareto_front.h): sort by cost, then sweep keeping strictly falling error.
#include "analysis/pareto_front.h"

#include <algorithm>
#include <cmath>

namespace ontile {

std::vector<size_t> pareto_front(const std::vector<ParetoPoint>& points) {
  std::vector<size_t> order;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!std::isnan(points[i].cost) && !std::isnan(points[i].error)) order.push_back(i);
  }
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
    if (points[a].error != points[b].error) return points[a].error < points[b].error;
    return a < b;
  });
  // In cost order a point is on the front iff its error is below every error seen at a lower
  // cost, or it equals the last front point exactly (an identical copy).
  std::vector<size_t> front;
  for (size_t i : order) {
    if (front.empty()) {
      front.push_back(i);
      continue;
    }
    const ParetoPoint& last = points[front.back()];
    const ParetoPoint& p = points[i];
    if (p.error < last.error || (p.error == last.error && p.cost == last.cost)) front.push_back(i);
  }
  return front;
}

}  // namespace ontile
