// interpolate_quad_runs (a batch's runs of quads, one triangle each, in one call) gives bit for
// bit what interpolate_whole_quads gives run by run, on every SIMD target: the vectors that run
// on into the next run's quads are overwritten, and nothing past the batch or outside the read
// varyings is written.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "raster/cell_raster.h"
#include "raster/interpolation_runs.h"

namespace ontile {
namespace {

struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

constexpr int kQuads = kMaxRunFragments / 4;
constexpr int kStride = kMaxRunFragments;
constexpr uint32_t kSentinelBits = 0x7fc01234u;  // a NaN the kernels never compute

struct Triangle {
  InterpolationRun run;  // first_quad set per batch
  std::vector<float> vertex[3];
};

Triangle random_triangle(std::mt19937& rng) {
  std::uniform_real_distribution<float> gradient(-0.01f, 0.01f), w(0.05f, 20.0f), value(-100.0f, 100.0f);
  Triangle t;
  for (auto& v : t.vertex) {
    v.resize(kMaxVaryings);
    for (float& x : v) x = value(rng);
  }
  t.run = InterpolationRun{0, gradient(rng), gradient(rng), gradient(rng), gradient(rng), gradient(rng),
                           gradient(rng), {1.0f / w(rng), 1.0f / w(rng), 1.0f / w(rng)},
                           {t.vertex[0].data(), t.vertex[1].data(), t.vertex[2].data()}};
  return t;
}

struct Batch {
  std::vector<Triangle> triangles;
  std::vector<int> first;  // each run's first quad
  int quads = 0, varyings = 0;
  uint32_t read = 0;
  int32_t ox[kQuads + kQuadOriginsPadding] = {}, oy[kQuads + kQuadOriginsPadding] = {};
  float l1[kQuads + kQuadOriginsPadding] = {}, l2[kQuads + kQuadOriginsPadding] = {},
        z[kQuads + kQuadOriginsPadding] = {};
};

Batch random_batch(std::mt19937& rng) {
  std::uniform_real_distribution<float> origin(-0.2f, 1.2f);
  Batch b;
  b.quads = std::uniform_int_distribution<int>(1, kQuads)(rng);
  b.varyings = std::uniform_int_distribution<int>(0, kMaxVaryings)(rng);
  b.read = std::uniform_int_distribution<uint32_t>(0, 0xFFFFFFFFu)(rng);
  for (int q = 0; q < b.quads; ++q) {
    if (q == 0 || std::uniform_int_distribution<int>(0, 2)(rng) == 0) {
      b.first.push_back(q);
      b.triangles.push_back(random_triangle(rng));
    }
  }
  for (int q = 0; q < kQuads + kQuadOriginsPadding; ++q) {
    b.ox[q] = 2 * std::uniform_int_distribution<int>(0, 3)(rng);
    b.oy[q] = 2 * std::uniform_int_distribution<int>(0, 3)(rng);
    b.l1[q] = origin(rng);
    b.l2[q] = origin(rng);
    b.z[q] = origin(rng);
  }
  return b;
}

struct Result {
  std::vector<float> depth, varyings;
  Result() : depth(kMaxRunFragments), varyings(size_t{kMaxVaryings} * kStride) {
    for (float& x : depth) std::memcpy(&x, &kSentinelBits, sizeof(x));
    for (float& x : varyings) std::memcpy(&x, &kSentinelBits, sizeof(x));
  }
  bool operator==(const Result& o) const {  // bits, not values
    return std::memcmp(depth.data(), o.depth.data(), depth.size() * sizeof(float)) == 0 &&
           std::memcmp(varyings.data(), o.varyings.data(), varyings.size() * sizeof(float)) == 0;
  }
};

Result in_one_call(const Batch& b) {
  std::vector<InterpolationRun> runs;
  for (size_t r = 0; r < b.triangles.size(); ++r) {
    runs.push_back(b.triangles[r].run);
    runs.back().first_quad = b.first[r];
  }
  Result out;
  interpolate_quad_runs(runs.data(), static_cast<int>(runs.size()), QuadOrigins{b.ox, b.oy, b.l1, b.l2, b.z},
                        b.quads, b.varyings, b.read, out.depth.data(), out.varyings.data(), kStride);
  return out;
}

Result run_by_run(const Batch& b) {
  Result out;
  for (size_t r = 0; r < b.triangles.size(); ++r) {
    const InterpolationRun& t = b.triangles[r].run;
    const int first = b.first[r];
    const int end = r + 1 < b.first.size() ? b.first[r + 1] : b.quads;
    const InterpolationInput in{nullptr, nullptr, nullptr, nullptr, nullptr,
                                t.l1_dx, t.l1_dy, t.l2_dx, t.l2_dy, t.z_dx, t.z_dy,
                                {t.inv_w[0], t.inv_w[1], t.inv_w[2]},
                                {t.vertex_varyings[0], t.vertex_varyings[1], t.vertex_varyings[2]},
                                b.varyings, b.read};
    interpolate_whole_quads(in, QuadOrigins{b.ox + first, b.oy + first, b.l1 + first, b.l2 + first, b.z + first},
                            end - first, out.depth.data() + 4 * first, out.varyings.data() + 4 * first, kStride);
  }
  return out;
}

TEST(QuadRunInterpolation, MatchesWholeQuadsRunByRunOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  std::mt19937 rng(20261201);
  std::vector<Batch> batches;
  for (int i = 0; i < 200; ++i) batches.push_back(random_batch(rng));
  std::vector<Result> first_target;
  const std::vector<std::string> targets = simd_targets();
  for (size_t t = 0; t < targets.size(); ++t) {
    force_simd_target(targets[t]);
    for (size_t i = 0; i < batches.size(); ++i) {
      const Result one_call = in_one_call(batches[i]);
      EXPECT_TRUE(one_call == run_by_run(batches[i]))
          << targets[t] << " batch " << i << ": " << batches[i].quads << " quads, "
          << batches[i].first.size() << " runs";
      if (t == 0) {
        first_target.push_back(one_call);
      } else {
        EXPECT_TRUE(one_call == first_target[i]) << targets[t] << " differs from " << targets[0] << ", batch " << i;
      }
    }
  }
}

}  // namespace
}  // namespace ontile
