// interpolate_whole_quads (the whole-tile path's interpolation from per-quad cell origins) gives
// bit for bit what interpolate_fragments gives for the same fragments described one by one, on
// every SIMD target, and interpolate_fragments' bits do not depend on how a run is split.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "raster/cell_raster.h"

namespace ontile {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

constexpr int kMaxQuads = 40;
constexpr int kStride = 4 * kMaxQuads;

// Random planes, vertex values and quads (offsets inside an 8x8 cell at even positions).
struct Case {
  float l1_dx, l1_dy, l2_dx, l2_dy, z_dx, z_dy, inv_w[3];
  std::vector<float> vertex[3];
  int varyings;
  int32_t ox[kMaxQuads + kQuadOriginsPadding] = {}, oy[kMaxQuads + kQuadOriginsPadding] = {};
  float l1[kMaxQuads + kQuadOriginsPadding] = {}, l2[kMaxQuads + kQuadOriginsPadding] = {},
        z[kMaxQuads + kQuadOriginsPadding] = {};
  InterpolationInput input() const {
    return {nullptr, nullptr, nullptr, nullptr, nullptr, l1_dx, l1_dy, l2_dx, l2_dy, z_dx, z_dy,
            {inv_w[0], inv_w[1], inv_w[2]}, {vertex[0].data(), vertex[1].data(), vertex[2].data()},
            varyings};
  }
};

Case random_case(std::mt19937& rng) {
  std::uniform_real_distribution<float> gradient(-0.01f, 0.01f), origin(-0.2f, 1.2f),
      w(0.05f, 20.0f), value(-100.0f, 100.0f);
  Case c;
  c.l1_dx = gradient(rng);
  c.l1_dy = gradient(rng);
  c.l2_dx = gradient(rng);
  c.l2_dy = gradient(rng);
  c.z_dx = gradient(rng);
  c.z_dy = gradient(rng);
  for (float& x : c.inv_w) x = 1.0f / w(rng);
  c.varyings = std::uniform_int_distribution<int>(0, kMaxVaryings)(rng);
  for (auto& v : c.vertex) {
    v.resize(kMaxVaryings);
    for (float& x : v) x = value(rng);
  }
  for (int q = 0; q < kMaxQuads; ++q) {
    c.ox[q] = 2 * std::uniform_int_distribution<int>(0, 3)(rng);
    c.oy[q] = 2 * std::uniform_int_distribution<int>(0, 3)(rng);
    c.l1[q] = origin(rng);
    c.l2[q] = origin(rng);
    c.z[q] = origin(rng);
  }
  return c;
}

struct Result {
  std::vector<float> depth, varyings;
  bool operator==(const Result& o) const {
    // Bits, not values: -0 and NaN payloads count.
    return depth.size() == o.depth.size() && varyings.size() == o.varyings.size() &&
           std::memcmp(depth.data(), o.depth.data(), depth.size() * sizeof(float)) == 0 &&
           std::memcmp(varyings.data(), o.varyings.data(), varyings.size() * sizeof(float)) == 0;
  }
};

Result whole_quads(const Case& c, int quads) {
  Result r{std::vector<float>(4 * quads), std::vector<float>(size_t{kMaxVaryings} * kStride)};
  interpolate_whole_quads(c.input(), QuadOrigins{c.ox, c.oy, c.l1, c.l2, c.z}, quads,
                          r.depth.data(), r.varyings.data(), kStride);
  return r;
}

// The same fragments as per-fragment inputs, interpolated in runs of `run` fragments.
Result per_fragment(const Case& c, int quads, int run) {
  std::vector<float> fx(4 * quads), fy(4 * quads), l1(4 * quads), l2(4 * quads), z(4 * quads);
  for (int f = 0; f < 4 * quads; ++f) {
    const int q = f / 4, lane = f % 4;
    fx[f] = static_cast<float>(c.ox[q] + (lane & 1));
    fy[f] = static_cast<float>(c.oy[q] + (lane >> 1));
    l1[f] = c.l1[q];
    l2[f] = c.l2[q];
    z[f] = c.z[q];
  }
  Result r{std::vector<float>(4 * quads), std::vector<float>(size_t{kMaxVaryings} * kStride)};
  for (int first = 0; first < 4 * quads; first += run) {
    InterpolationInput in = c.input();
    in.fx = fx.data() + first;
    in.fy = fy.data() + first;
    in.l1_origin = l1.data() + first;
    in.l2_origin = l2.data() + first;
    in.z_origin = z.data() + first;
    interpolate_fragments(in, std::min(run, 4 * quads - first), r.depth.data() + first,
                          r.varyings.data() + first, kStride);
  }
  return r;
}

TEST(WholeQuadInterpolation, MatchesPerFragmentInputsBitForBitOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  std::mt19937 rng(20261124);
  std::vector<Case> cases;
  for (int i = 0; i < 12; ++i) cases.push_back(random_case(rng));
  std::vector<std::vector<Result>> first_target;  // [case][quad count]
  const std::vector<std::string> targets = simd_targets();
  for (size_t t = 0; t < targets.size(); ++t) {
    force_simd_target(targets[t]);
    for (size_t i = 0; i < cases.size(); ++i) {
      if (t == 0) first_target.emplace_back();
      for (int quads = 1; quads <= kMaxQuads; ++quads) {
        const Result whole = whole_quads(cases[i], quads);
        const Result reference = per_fragment(cases[i], quads, 4 * quads);
        EXPECT_TRUE(whole == reference) << targets[t] << " case " << i << ", " << quads << " quads";
        if (t == 0) {
          first_target[i].push_back(whole);
        } else {
          EXPECT_TRUE(whole == first_target[i][quads - 1])
              << targets[t] << " differs from " << targets[0] << ", case " << i;
        }
      }
    }
  }
}

// Chunks, vectors and 4-lane remainders inside interpolate_fragments leave no trace in the bits.
TEST(WholeQuadInterpolation, PerFragmentBitsDoNotDependOnTheRun) {
  const AutomaticTargetOnExit restore;
  std::mt19937 rng(7);
  for (const std::string& target : simd_targets()) {
    force_simd_target(target);
    for (int i = 0; i < 6; ++i) {
      const Case c = random_case(rng);
      const Result whole_run = per_fragment(c, kMaxQuads, 4 * kMaxQuads);
      for (int run : {4, 8, 12, 64, 68}) {
        EXPECT_TRUE(per_fragment(c, kMaxQuads, run) == whole_run) << target << " run " << run;
      }
    }
  }
}

}  // namespace
}  // namespace ontile
