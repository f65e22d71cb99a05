// classify_and_snap() must give clip_outcode() and snap_vertex() bit for bit on every SIMD
// target: random vertices inside, across and far outside the guard band, on its planes, behind
// the eye, with NaN/Inf components, in batches of every length (vector tails).
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "raster/cell_raster.h"
#include "tiler/detail/vertex_kernels.h"

namespace ontile {
namespace {

std::vector<glm::vec4> test_vertices(const GuardBand& g, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> kind(0, 9);
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<glm::vec4> v;
  for (int i = 0; i < 200000; ++i) {
    const float w = std::ldexp(std::abs(unit(rng)) + 0.01f, static_cast<int>(unit(rng) * 20));
    glm::vec4 p(unit(rng) * 2.0f * w, unit(rng) * 2.0f * w, (unit(rng) + 0.6f) * w, w);
    switch (kind(rng)) {
      case 0: p.x *= 3000.0f; break;                  // far outside the guard band
      case 1: p.w = -p.w; break;                      // behind the eye
      case 2: p.x = g.x_max * p.w; break;             // on a guard plane
      case 3: p.y = g.y_min * p.w; p.x = p.w; break;  // on a guard and a viewport plane
      case 4: p[i % 4] = (i & 4) ? nan : ((i & 8) ? inf : -inf); break;
      case 5: p.w = (i & 1) ? 0.0f : 1e-21f; break;   // at and below kClipMinW
      case 6: p.z = (i & 1) ? 0.0f : p.w; break;      // on the near or the far plane
      default: break;
    }
    v.push_back(p);
  }
  return v;
}

// Restores automatic target selection however the test exits.
struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

TEST(VertexKernels, ClassifyAndSnapMatchScalarOnEveryTarget) {
  const AutomaticTargetOnExit restore;
  struct Viewport {
    int width, height, bits;
  };
  for (const Viewport vp : {Viewport{1920, 1080, kSubpixelBits}, Viewport{333, 17, kMinSubpixelBits},
                            Viewport{16384, 16384, kSubpixelBits}}) {
    const GuardBand g = GuardBand::for_viewport(vp.width, vp.height);
    const std::vector<glm::vec4> v = test_vertices(g, static_cast<uint32_t>(vp.width));
    std::vector<uint16_t> want_code(v.size());
    uint64_t inside = 0;
    for (size_t i = 0; i < v.size(); ++i) {
      const glm::vec4& p = v[i];
      const bool finite =
          std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
      want_code[i] = finite ? static_cast<uint16_t>(clip_outcode(p, g)) : kNonFiniteVertex;
      inside += (want_code[i] & (kNonFiniteVertex | kClippingPlaneMask)) == 0;
    }
    EXPECT_GT(inside, v.size() / 4);
    for (const std::string& target : simd_targets()) {
      force_simd_target(target);
      std::vector<uint16_t> code(v.size());
      std::vector<SnappedVertex> snapped(v.size());
      // Batches of every length 1..40 exercise partial vectors.
      for (uint32_t first = 0, len = 1; first < v.size(); first += len, len = len % 40 + 1) {
        const uint32_t count = std::min<uint32_t>(len, static_cast<uint32_t>(v.size()) - first);
        classify_and_snap(v.data() + first, count, g, vp.width, vp.height, vp.bits,
                          code.data() + first, snapped.data() + first);
      }
      uint64_t code_mismatches = 0, snap_mismatches = 0;
      for (size_t i = 0; i < v.size(); ++i) {
        code_mismatches += code[i] != want_code[i];
        if ((want_code[i] & (kNonFiniteVertex | kClippingPlaneMask)) != 0) continue;
        const SnappedVertex want = snap_vertex(v[i], vp.width, vp.height, vp.bits);
        snap_mismatches += snapped[i].x_fp != want.x_fp || snapped[i].y_fp != want.y_fp ||
                           std::memcmp(&snapped[i].depth, &want.depth, sizeof(float)) != 0 ||
                           std::memcmp(&snapped[i].inv_w, &want.inv_w, sizeof(float)) != 0;
      }
      EXPECT_EQ(code_mismatches, 0u) << target << " " << vp.width << "x" << vp.height;
      EXPECT_EQ(snap_mismatches, 0u) << target << " " << vp.width << "x" << vp.height;
    }
  }
}

}  // namespace
}  // namespace ontile
