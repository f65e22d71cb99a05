// D16 and D24S8 depth is quantised to the attachment format before the depth test, as hardware
// converts it: two view-perpendicular planes are ordered exactly when support/depth_precision.h
// calls the gap Resolvable, and when both planes can only store the same code (Unresolvable)
// the compare op alone decides, at every pixel: a strict op keeps whichever plane came first.
#include <gtest/gtest.h>

#include "support/depth_precision.h"
#include "support/raster_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 32, kH = 24;

class ConstantIdShader final : public FragmentShader {
 public:
  explicit ConstantIdShader(float id) : id_(id) {}
  void shade(const QuadFragment&, QuadOutput& out) const override {
    for (int lane = 0; lane < kQuadLanes; ++lane) out.color[0][lane] = glm::vec4(id_, 0.0f, 0.0f, 1.0f);
  }

 private:
  float id_;
};

struct Plane {
  double distance;  // view distance, perpendicular to the view direction
  float id;
};

// Draws the planes in order (each a quad covering the target, clip z and w as a double
// projection gives them) into a cleared depth buffer; returns how many pixels show `id`.
int pixels_showing(const DepthSetup& s, const std::vector<Plane>& planes, CompareOp op, float id) {
  std::vector<glm::vec4> positions;
  for (const Plane& p : planes) {
    double z = 0.0, w = 0.0;
    clip_z_w(s, p.distance, z, w);
    for (auto [x, y] : {std::pair{-1.5, -1.5}, {1.5, -1.5}, {1.5, 1.5}, {-1.5, 1.5}}) {
      positions.push_back(glm::vec4(static_cast<float>(x * w), static_cast<float>(y * w), static_cast<float>(z),
                                    static_cast<float>(w)));
    }
  }
  ContextConfig cfg;
  cfg.threads = 2;
  RenderContext ctx(cfg);
  Surface* color = ctx.create_surface("id", PixelFormat::R32_FLOAT, kW, kH);
  ClipSpaceVertexShader vs(positions, {}, 0);
  std::vector<ConstantIdShader> shaders;
  for (const Plane& p : planes) shaders.emplace_back(p.id);
  std::vector<std::vector<uint32_t>> indices;
  for (uint32_t k = 0; k < planes.size(); ++k) indices.push_back({4 * k, 4 * k + 1, 4 * k + 2, 4 * k, 4 * k + 2, 4 * k + 3});
  const float clear = s.convention == DepthConvention::Reversed ? 0.0f : 1.0f;
  ctx.begin_render_pass("planes", kW, kH, 1,
                        {{"id", PixelFormat::R32_FLOAT, LoadAction::Clear, StoreAction::Store, glm::vec4(0.0f), color, nullptr},
                         {"depth", s.format, LoadAction::Clear, StoreAction::DontCare, glm::vec4(clear), nullptr, nullptr}},
                        1);
  ctx.begin_subpass({0});
  for (size_t k = 0; k < planes.size(); ++k) {
    DrawCall d;
    d.vertex_shader = &vs;
    d.fragment_shader = &shaders[k];
    d.vertex_count = vs.vertex_count();
    d.indices = indices[k].data();
    d.index_count = 6;
    d.raster.cull = CullMode::None;
    d.raster.depth_compare = op;
    ctx.draw(d);
  }
  ctx.end_subpass();
  ctx.end_render_pass();
  ctx.submit();
  int count = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) count += color->read(x, y).x == id;
  return count;
}

CompareOp strict_op(const DepthSetup& s) {
  return s.convention == DepthConvention::Reversed ? CompareOp::Greater : CompareOp::Less;
}
CompareOp or_equal_op(const DepthSetup& s) {
  return s.convention == DepthConvention::Reversed ? CompareOp::GreaterEqual : CompareOp::LessEqual;
}

TEST(DepthQuantization, UnormDepthResolvesExactlyWhatItsCodesAllow) {
  int resolvable = 0, unresolvable = 0;
  const int all = kW * kH;
  for (PixelFormat format : {PixelFormat::D16_UNORM, PixelFormat::D24S8}) {
    for (DepthConvention convention : {DepthConvention::Standard, DepthConvention::Reversed}) {
      for (double ratio : {1e2, 1e3, 1e4}) {
        const DepthSetup s{0.01, 0.01 * ratio, convention, format};
        for (double d_over_near : {3.0, 50.0, 700.0, 0.4 * ratio}) {
          const double d = d_over_near * s.near;
          for (double relative : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
            const double gap = relative * d;
            if (d + gap >= s.far) continue;
            const Plane nearer{d, 1.0f}, farther{d + gap, 2.0f};
            const std::string what = std::string(format_name(format)) +
                                     (convention == DepthConvention::Reversed ? " reversed" : " standard") +
                                     " far " + std::to_string(s.far) + " d " + std::to_string(d) +
                                     " gap " + std::to_string(gap);
            switch (classify_separation(s, d, gap)) {
              case DepthVerdict::Resolvable:
                ++resolvable;
                EXPECT_EQ(pixels_showing(s, {farther, nearer}, strict_op(s), 1.0f), all) << what;
                EXPECT_EQ(pixels_showing(s, {nearer, farther}, strict_op(s), 1.0f), all) << what;
                break;
              case DepthVerdict::Unresolvable:
                // One code for both: the strict op keeps the first, the or-equal op the second.
                ++unresolvable;
                EXPECT_EQ(pixels_showing(s, {farther, nearer}, strict_op(s), 2.0f), all) << what;
                EXPECT_EQ(pixels_showing(s, {nearer, farther}, strict_op(s), 1.0f), all) << what;
                EXPECT_EQ(pixels_showing(s, {nearer, farther}, or_equal_op(s), 2.0f), all) << what;
                break;
              case DepthVerdict::Marginal:
                break;
            }
          }
        }
      }
    }
  }
  // Both sides of the precision limit are exercised.
  EXPECT_GT(resolvable, 40);
  EXPECT_GT(unresolvable, 40);
}

// The same gap that D16 cannot store is resolved by D32F, which keeps floats (no quantisation).
TEST(DepthQuantization, FloatDepthIsNotQuantised) {
  const DepthSetup d16{0.01, 100.0, DepthConvention::Standard, PixelFormat::D16_UNORM};
  const DepthSetup d32{0.01, 100.0, DepthConvention::Standard, PixelFormat::D32_FLOAT};
  const double d = 20.0, gap = 0.1;  // 2.5e-6 in depth: 1/6 of a D16 step
  ASSERT_EQ(classify_separation(d16, d, gap), DepthVerdict::Unresolvable);
  ASSERT_EQ(classify_separation(d32, d, gap), DepthVerdict::Resolvable);
  const Plane nearer{d, 1.0f}, farther{d + gap, 2.0f};
  EXPECT_EQ(pixels_showing(d16, {farther, nearer}, CompareOp::Less, 2.0f), kW * kH);
  EXPECT_EQ(pixels_showing(d32, {farther, nearer}, CompareOp::Less, 1.0f), kW * kH);
}

}  // namespace
}  // namespace ontile::test
