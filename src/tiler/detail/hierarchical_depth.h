// Hierarchical Z for one tile: the minimum and maximum stored depth of every 8x8-pixel cell
// (raster/cell_raster.h), so a triangle whose depth over a cell provably fails the depth test
// at every sample is skipped before any per-sample work (Greene, Kass and Miller, "Hierarchical
// Z-Buffer Visibility", SIGGRAPH 1993; the coarse per-tile Z of tiled GPUs).
#pragma once
#include <algorithm>
#include <vector>

#include "raster/cell_raster.h"
#include "raster/raster_types.h"

namespace ontile {

class HierarchicalDepth {
 public:
  // Covers cells_x x cells_y cells; every cell must be refreshed before use.
  void prepare(int cells_x, int cells_y) {
    cells_x_ = cells_x;
    min_.assign(static_cast<size_t>(cells_x) * cells_y, 0.0f);
    max_.assign(min_.size(), 0.0f);
  }
  // Recomputes cell `cell` from its stored depth: `rows` rows of `count` floats (all samples of
  // the cell's pixels in one row), `stride` floats apart.
  void refresh(int cell, const float* first, int stride, int count, int rows) {
    depth_range(first, stride, count, rows, min_[cell], max_[cell]);
  }
  // Sets cell `cell` from bounds computed as refresh() would (depth_test_cell's range).
  void set(int cell, float lo, float hi) {
    min_[cell] = lo;
    max_[cell] = hi;
  }
  // True when every incoming depth in [incoming_min, incoming_max] fails `op` against every
  // stored depth of the cell. Only the ordering comparisons can be decided from bounds.
  bool rejects(int cell, CompareOp op, float incoming_min, float incoming_max) const {
    switch (op) {
      case CompareOp::Less: return incoming_min >= max_[cell];
      case CompareOp::LessEqual: return incoming_min > max_[cell];
      case CompareOp::Greater: return incoming_max <= min_[cell];
      case CompareOp::GreaterEqual: return incoming_max < min_[cell];
      default: return false;
    }
  }
  static bool usable(CompareOp op) {
    return op == CompareOp::Less || op == CompareOp::LessEqual || op == CompareOp::Greater ||
           op == CompareOp::GreaterEqual;
  }
  int cells_x() const { return cells_x_; }

 private:
  int cells_x_ = 0;
  std::vector<float> min_, max_;
};

}  // namespace ontile
