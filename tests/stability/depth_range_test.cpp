// Depth range: near/far up to 1e6, standard and reversed Z, D32F/D24S8/D16. Where
// support/depth_precision.h says a gap is resolvable the renderer orders both surfaces at every
// pixel in both draw orders; coplanar surfaces are decided by the compare op alone.
#include <gtest/gtest.h>

#include <algorithm>

#include "support/depth_precision.h"
#include "support/raster_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 32, kH = 24;
constexpr double kYFov = 0.8;

// Perspective projection of camera_matrices.cpp (Vulkan depth [0, 1]); Reversed swaps near
// and far, and an infinite far plane gives z = near (the limit).
glm::dmat4 projection(const DepthSetup& s) {
  const double f = 1.0 / std::tan(kYFov / 2);
  glm::dmat4 m(0.0);
  m[0][0] = f * kH / kW;
  m[1][1] = f;
  m[2][3] = -1.0;
  if (s.convention == DepthConvention::Reversed) {
    m[2][2] = std::isinf(s.far) ? 0.0 : s.near / (s.far - s.near);
    m[3][2] = std::isinf(s.far) ? s.near : s.near * s.far / (s.far - s.near);
  } else {
    m[2][2] = s.far / (s.near - s.far);
    m[3][2] = s.near * s.far / (s.near - s.far);
  }
  return m;
}

struct Plane {
  double distance;  // view-space distance, perpendicular to the view direction
  float id;         // written to the colour target
  int cells = 1;    // tessellation: cells x cells quads
};

// Draws the planes in order into a cleared depth buffer of the setup's format with `op`;
// returns the id visible at each pixel.
std::vector<float> draw_planes(const DepthSetup& s, const std::vector<Plane>& planes, CompareOp op) {
  std::vector<glm::vec4> positions;
  std::vector<float> varyings;
  std::vector<std::vector<uint32_t>> indices(planes.size());
  const glm::dmat4 p = projection(s);
  for (size_t k = 0; k < planes.size(); ++k) {
    const Plane& pl = planes[k];
    // Larger than the view at that distance (aspect < 1.5), so it covers every pixel.
    const double half = 1.5 * pl.distance * std::tan(kYFov / 2) * kW / kH;
    const uint32_t base = static_cast<uint32_t>(positions.size());
    for (int j = 0; j <= pl.cells; ++j) {
      for (int i = 0; i <= pl.cells; ++i) {
        const glm::dvec4 view(-half + 2.0 * half * i / pl.cells, -half + 2.0 * half * j / pl.cells, -pl.distance, 1.0);
        positions.push_back(glm::vec4(p * view));
        varyings.insert(varyings.end(), {pl.id, 0.0f, 0.0f, 1.0f});
      }
    }
    for (int j = 0; j < pl.cells; ++j) {
      for (int i = 0; i < pl.cells; ++i) {
        const uint32_t a = base + j * (pl.cells + 1) + i, b = a + 1, c = a + pl.cells + 1, d = c + 1;
        indices[k].insert(indices[k].end(), {a, b, d, a, d, c});
      }
    }
  }
  ContextConfig cfg;
  cfg.threads = 2;
  RenderContext ctx(cfg);
  Surface* color = ctx.create_surface("id", PixelFormat::R32_FLOAT, kW, kH);
  ClipSpaceVertexShader vs(positions, varyings, 4);
  VaryingsShader fs;
  const float clear_depth = s.convention == DepthConvention::Reversed ? 0.0f : 1.0f;
  ctx.begin_render_pass("planes", kW, kH, 1,
                        {{"id", PixelFormat::R32_FLOAT, LoadAction::Clear, StoreAction::Store, glm::vec4(0.0f), color, nullptr},
                         {"depth", s.format, LoadAction::Clear, StoreAction::DontCare, glm::vec4(clear_depth), nullptr, nullptr}},
                        1);
  ctx.begin_subpass({0});
  for (const std::vector<uint32_t>& idx : indices) {
    DrawCall d = unculled_draw(vs, fs, idx);
    d.raster.depth_test = true;
    d.raster.depth_compare = op;
    ctx.draw(d);
  }
  ctx.end_subpass();
  ctx.end_render_pass();
  ctx.submit();
  std::vector<float> ids;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) ids.push_back(color->read(x, y).x);
  return ids;
}

// Ids are compared after rounding: the tile executor interpolates even a constant varying as
// w0 * v0 + w1 * v1 + w2 * v2 in float, so 1.0 can arrive as 0.99999994.
int count_id(const std::vector<float>& ids, float id) {
  return static_cast<int>(std::count_if(ids.begin(), ids.end(), [id](float v) { return std::lround(v) == std::lround(id); }));
}

CompareOp strict_op(const DepthSetup& s) {
  return s.convention == DepthConvention::Reversed ? CompareOp::Greater : CompareOp::Less;
}

TEST(DepthRange, RendererResolvesEveryPairTheHelperCallsResolvable) {
  const PixelFormat formats[] = {PixelFormat::D32_FLOAT, PixelFormat::D24S8, PixelFormat::D16_UNORM};
  int resolvable = 0, not_resolvable = 0;
  for (double ratio : {1e3, 1e4, 1e5, 1e6}) {
    for (DepthConvention convention : {DepthConvention::Standard, DepthConvention::Reversed}) {
      for (PixelFormat format : formats) {
        const DepthSetup s{0.01, 0.01 * ratio, convention, format};
        for (double d_over_near : {3.0, 50.0, 700.0, 9000.0, 0.4 * ratio}) {
          const double distance = d_over_near * s.near;
          for (double relative : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
            const double separation = relative * distance;
            if (distance + separation >= s.far) continue;
            if (classify_separation(s, distance, separation) != DepthVerdict::Resolvable) {
              ++not_resolvable;
              continue;
            }
            ++resolvable;
            const Plane nearer{distance, 1.0f}, farther{distance + separation, 2.0f};
            const std::string what = "ratio " + std::to_string(ratio) + " " + format_name(format) +
                                     (convention == DepthConvention::Reversed ? " reversed" : " standard") +
                                     " d " + std::to_string(distance) + " s " + std::to_string(separation);
            EXPECT_EQ(count_id(draw_planes(s, {farther, nearer}, strict_op(s)), 1.0f), kW * kH) << what;
            EXPECT_EQ(count_id(draw_planes(s, {nearer, farther}, strict_op(s)), 1.0f), kW * kH) << what;
          }
        }
      }
    }
  }
  // The sweep reaches both sides of the precision limit.
  EXPECT_GT(resolvable, 60);
  EXPECT_GT(not_resolvable, 30);
}

// At near/far = 1e6 (0.01 .. 1e4) and 1000 units, a 1-unit gap changes standard depth by about
// near * s / d^2 = 1e-8 next to 1.0, below both the float spacing there (6e-8) and a D24 step;
// reversed Z puts the same gap next to 1e-5 where floats are 1e-12 apart.
TEST(DepthRange, ReversedFloatDepthResolvesWhatStandardDepthCannot) {
  const double near = 0.01, far = 1e4, d = 1000.0, s = 1.0;
  const DepthSetup reversed_d32{near, far, DepthConvention::Reversed, PixelFormat::D32_FLOAT};
  const DepthSetup reversed_infinite{near, std::numeric_limits<double>::infinity(), DepthConvention::Reversed,
                                     PixelFormat::D32_FLOAT};
  const DepthSetup standard_d32{near, far, DepthConvention::Standard, PixelFormat::D32_FLOAT};
  const DepthSetup standard_d24{near, far, DepthConvention::Standard, PixelFormat::D24S8};
  const DepthSetup reversed_d16{near, far, DepthConvention::Reversed, PixelFormat::D16_UNORM};
  EXPECT_EQ(classify_separation(reversed_d32, d, s), DepthVerdict::Resolvable);
  EXPECT_EQ(classify_separation(reversed_infinite, d, s), DepthVerdict::Resolvable);
  EXPECT_NE(classify_separation(standard_d32, d, s), DepthVerdict::Resolvable);
  EXPECT_NE(classify_separation(standard_d24, d, s), DepthVerdict::Resolvable);
  EXPECT_EQ(classify_separation(reversed_d16, d, s), DepthVerdict::Unresolvable);
  for (const DepthSetup& setup : {reversed_d32, reversed_infinite}) {
    const Plane nearer{d, 1.0f, 3}, farther{d + s, 2.0f, 5};
    EXPECT_EQ(count_id(draw_planes(setup, {farther, nearer}, CompareOp::Greater), 1.0f), kW * kH);
    EXPECT_EQ(count_id(draw_planes(setup, {nearer, farther}, CompareOp::Greater), 1.0f), kW * kH);
  }
}

// Two coplanar surfaces with different tessellations have bit-identical depth at every pixel
// (depth is constant over a view-perpendicular plane), so the compare op alone decides:
// Greater keeps the first, GreaterEqual takes the second, everywhere.
TEST(DepthRange, CoplanarSurfacesAreDecidedByTheCompareOpWithoutSpeckle) {
  for (double ratio : {1e3, 1e6}) {
    const DepthSetup s{0.01, 0.01 * ratio, DepthConvention::Reversed, PixelFormat::D32_FLOAT};
    for (double distance : {0.05, 3.0, 0.3 * s.far}) {
      const Plane first{distance, 1.0f, 1}, second{distance, 2.0f, 7};
      EXPECT_EQ(count_id(draw_planes(s, {first, second}, CompareOp::Greater), 1.0f), kW * kH) << distance;
      EXPECT_EQ(count_id(draw_planes(s, {first, second}, CompareOp::GreaterEqual), 2.0f), kW * kH) << distance;
    }
  }
}

}  // namespace
}  // namespace ontile::test
