// Standard sample positions (see sample_pattern.h). The tables are in 1/16 px, as printed in
// the Vulkan spec's "Standard sample locations" table, and scaled to 1/256 px here.
#include "raster/sample_pattern.h"

namespace ontile {
namespace {

constexpr int kSixteenthToSubpixel = static_cast<int>(kSubpixelScale / 16);

SamplePattern make_pattern(int count, const int (*pos16)[2]) {
  SamplePattern p;
  p.count = count;
  for (int i = 0; i < count; ++i) {
    p.x[i] = pos16[i][0] * kSixteenthToSubpixel;
    p.y[i] = pos16[i][1] * kSixteenthToSubpixel;
  }
  return p;
}

constexpr int k1[1][2] = {{8, 8}};
constexpr int k2[2][2] = {{12, 12}, {4, 4}};
constexpr int k4[4][2] = {{6, 2}, {14, 6}, {2, 10}, {10, 14}};
constexpr int k8[8][2] = {{9, 5}, {7, 11}, {13, 7}, {5, 3}, {3, 13}, {1, 7}, {11, 15}, {15, 1}};

}  // namespace

const SamplePattern* standard_sample_pattern(int count) {
  static const SamplePattern p1 = make_pattern(1, k1);
  static const SamplePattern p2 = make_pattern(2, k2);
  static const SamplePattern p4 = make_pattern(4, k4);
  static const SamplePattern p8 = make_pattern(8, k8);
  switch (count) {
    case 1: return &p1;
    case 2: return &p2;
    case 4: return &p4;
    case 8: return &p8;
    default: return nullptr;
  }
}

}  // namespace ontile
