// Renderer-feature ordering (see renderer_feature.h).
#include "pipelines/universal/renderer_feature.h"

#include <algorithm>
#include <numeric>

namespace ontile {

std::vector<size_t> feature_run_order(const std::vector<std::unique_ptr<RendererFeature>>& features) {
  std::vector<size_t> order(features.size());
  std::iota(order.begin(), order.end(), size_t{0});
  // Stable: features at the same event keep the order they were added in (URP sorts its
  // render passes with a stable sort by renderPassEvent for the same reason).
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return features[a]->event() < features[b]->event(); });
  return order;
}

}  // namespace ontile
