// Top-left fill rule and watertightness: meshes whose union covers the whole target must
// cover every pixel exactly once (D3D11 functional spec 3.4.2.1), at many rotations and
// subpixel offsets.
#include <gtest/gtest.h>

#include <numbers>

#include "support/raster_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 96, kH = 64;

// Rotates (x, y) about the target centre by `angle` and shifts by (dx, dy) pixels.
glm::dvec2 place(double x, double y, double angle, double dx, double dy) {
  const double cx = kW / 2.0, cy = kH / 2.0;
  const double c = std::cos(angle), s = std::sin(angle);
  return {cx + (x - cx) * c - (y - cy) * s + dx, cy + (x - cx) * s + (y - cy) * c + dy};
}

void expect_all_exactly_once(const CountResult& r, const std::string& what) {
  int missed = 0, doubled = 0;
  for (float c : r.counts) {
    missed += c == 0.0f;
    doubled += c > 1.0f;
  }
  EXPECT_EQ(missed, 0) << what;
  EXPECT_EQ(doubled, 0) << what;
}

struct Placement {
  double angle, dx, dy;
};
std::vector<Placement> placements() {
  std::vector<Placement> p;
  const double angles_deg[] = {0.0, 90.0, 45.0, 30.0, 17.3, 63.1, 135.0, 180.0, 271.9};
  const double offsets[][2] = {{0.0, 0.0}, {0.5, 0.5}, {0.25, 0.75}, {0.123, 0.877}, {1.0 / 256, 3.0 / 256}};
  for (double a : angles_deg)
    for (const auto& o : offsets) p.push_back({a * std::numbers::pi / 180.0, o[0], o[1]});
  return p;
}

TEST(FillRule, TwoTrianglesSharingAnEdgeCoverEveryPixelOnce) {
  for (const Placement& pl : placements()) {
    // A square much larger than the target, split along a diagonal.
    const double r = 2.0 * kW;
    std::vector<glm::vec4> pos;
    for (auto [x, y] : {std::pair{-r, -r}, {kW + r, -r}, {kW + r, kH + r}, {-r, kH + r}}) {
      const glm::dvec2 p = place(x, y, pl.angle, pl.dx, pl.dy);
      pos.push_back(pixel_to_clip(p.x, p.y, kW, kH));
    }
    const CountResult res = draw_counting(pos, {0, 1, 2, 0, 2, 3}, kW, kH);
    expect_all_exactly_once(res, "angle " + std::to_string(pl.angle));
  }
}

TEST(FillRule, EdgeThroughPixelCentresGoesToExactlyOneTriangle) {
  // The shared edge is vertical and passes exactly through the centres of column 40.
  const double x = 40.5;
  std::vector<glm::vec4> pos = {pixel_to_clip(x, -10, kW, kH), pixel_to_clip(x, kH + 10, kW, kH),
                                pixel_to_clip(-10, kH / 2.0, kW, kH),
                                pixel_to_clip(kW + 10, kH / 2.0, kW, kH)};
  const CountResult left = draw_counting(pos, {0, 1, 2}, kW, kH);
  const CountResult right = draw_counting(pos, {0, 1, 3}, kW, kH);
  for (int y = 0; y < kH; ++y) {
    // Pixel centre on a left edge of the right triangle: it belongs to the right triangle.
    const float l = left.at(40, y, kW), r = right.at(40, y, kW);
    EXPECT_EQ(l + r, 1.0f) << "row " << y;
    if (l + r == 1.0f) {
      EXPECT_EQ(r, 1.0f) << "row " << y << ": a centre on a left edge is inside (top-left rule)";
    }
  }
}

TEST(FillRule, FanOf256TrianglesAroundOneVertex) {
  for (const Placement& pl : placements()) {
    std::vector<glm::vec4> pos;
    const glm::dvec2 centre = place(kW * 0.37, kH * 0.61, pl.angle, pl.dx, pl.dy);
    pos.push_back(pixel_to_clip(centre.x, centre.y, kW, kH));
    const int n = 256;
    for (int i = 0; i < n; ++i) {
      const double a = pl.angle + 2.0 * std::numbers::pi * i / n;
      const double radius = 3.0 * kW;
      pos.push_back(pixel_to_clip(centre.x + radius * std::cos(a), centre.y + radius * std::sin(a), kW, kH));
    }
    std::vector<uint32_t> idx;
    for (int i = 0; i < n; ++i) {
      idx.insert(idx.end(), {0u, 1u + i, 1u + (i + 1) % n});
    }
    expect_all_exactly_once(draw_counting(pos, idx, kW, kH), "fan angle " + std::to_string(pl.angle));
  }
}

TEST(FillRule, JitteredGridOfTenThousandTriangles) {
  // 100 x 50 cells, 2 triangles each; interior vertices jittered by up to 0.2 cell so edges
  // run at arbitrary slopes while every cell stays convex (no folded, overlapping triangles);
  // the grid extends beyond the target on every side.
  const int cols = 100, rows = 50;
  uint32_t seed = 12345u;
  auto next = [&seed] {  // xorshift32: deterministic across platforms
    seed ^= seed << 13; seed ^= seed >> 17; seed ^= seed << 5;
    return (seed & 0xFFFFFF) / double(0x1000000);
  };
  for (const Placement& pl : {Placement{0.0, 0.0, 0.0}, Placement{0.3, 0.37, 0.11}, Placement{1.9, 0.5, 0.5}}) {
    std::vector<glm::vec4> pos;
    const double x0 = -0.5 * kW, y0 = -0.5 * kH, cw = 2.0 * kW / cols, ch = 2.0 * kH / rows;
    for (int j = 0; j <= rows; ++j) {
      for (int i = 0; i <= cols; ++i) {
        double x = x0 + i * cw, y = y0 + j * ch;
        if (i > 0 && i < cols && j > 0 && j < rows) {
          x += (next() - 0.5) * 0.4 * cw;
          y += (next() - 0.5) * 0.4 * ch;
        }
        const glm::dvec2 p = place(x, y, pl.angle, pl.dx, pl.dy);
        pos.push_back(pixel_to_clip(p.x, p.y, kW, kH));
      }
    }
    std::vector<uint32_t> idx;
    for (int j = 0; j < rows; ++j) {
      for (int i = 0; i < cols; ++i) {
        const uint32_t a = j * (cols + 1) + i, b = a + 1, c = a + cols + 1, d = c + 1;
        idx.insert(idx.end(), {a, b, d, a, d, c});
      }
    }
    ASSERT_GE(idx.size() / 3, 10000u);
    // A valid tessellation: every triangle has the same winding.
    for (size_t t = 0; t < idx.size(); t += 3) {
      const glm::vec4 &a = pos[idx[t]], &b = pos[idx[t + 1]], &c = pos[idx[t + 2]];
      ASSERT_LT((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y), 0.0f) << "triangle " << t / 3;
    }
    const double s = 2.2;  // the rotated grid must still cover the target: enlarge about the centre
    for (auto& p : pos) { p.x *= s; p.y *= s; }
    const CountResult res = draw_counting(pos, idx, kW, kH);
    expect_all_exactly_once(res, "grid angle " + std::to_string(pl.angle));
  }
}

TEST(FillRule, ResultDoesNotDependOnTileSize) {
  std::vector<glm::vec4> pos = {pixel_to_clip(3.3, 2.1, kW, kH), pixel_to_clip(90.7, 13.9, kW, kH),
                                pixel_to_clip(20.2, 61.5, kW, kH)};
  const CountResult a = draw_counting(pos, {0, 1, 2}, kW, kH, 16);
  for (int tile : {4, 8, 32, 64}) {
    EXPECT_EQ(a.counts, draw_counting(pos, {0, 1, 2}, kW, kH, tile).counts) << "tile " << tile;
  }
}

}  // namespace
}  // namespace ontile::test
