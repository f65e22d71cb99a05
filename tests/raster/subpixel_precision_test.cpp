// Subpixel precision as a tiler setting: at 4 bits (Vulkan's minimum subPixelPrecisionBits)
// vertices snap to 1/16 px, the top-left fill rule stays exact (every pixel and every MSAA
// sample covered exactly once by a mesh), and any other precision than 4 or 8 is an error.
#include <gtest/gtest.h>

#include <numbers>

#include "support/raster_harness.h"
#include "util/error.h"

namespace ontile::test {
namespace {

constexpr int kW = 96, kH = 64;
constexpr int kCoarseBits = 4;

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
  double angle_deg, dx, dy;
};
// Offsets on and off the 1/16 grid, so snapping moves vertices by up to 1/32 px.
const Placement kPlacements[] = {{0.0, 0.0, 0.0},    {90.0, 0.5, 0.5},  {45.0, 0.25, 0.75},
                                 {30.0, 0.123, 0.877}, {17.3, 1.0 / 256, 3.0 / 256}, {63.1, 0.03, 0.97},
                                 {135.0, 0.0, 0.0},  {271.9, 0.41, 0.06}};

TEST(SubpixelPrecision, FourBitSharedEdgesCoverEveryPixelOnce) {
  for (const Placement& pl : kPlacements) {
    const double a = pl.angle_deg * std::numbers::pi / 180.0;
    const double r = 2.0 * kW;
    std::vector<glm::vec4> square;
    for (auto [x, y] : {std::pair{-r, -r}, {kW + r, -r}, {kW + r, kH + r}, {-r, kH + r}}) {
      const glm::dvec2 p = place(x, y, a, pl.dx, pl.dy);
      square.push_back(pixel_to_clip(p.x, p.y, kW, kH));
    }
    expect_all_exactly_once(draw_counting(square, {0, 1, 2, 0, 2, 3}, kW, kH, 16, 2, 1, kCoarseBits),
                            "square, angle " + std::to_string(pl.angle_deg));

    // A fan of 256 slivers around one vertex: many edges meet at a point snapped to 1/16 px.
    std::vector<glm::vec4> fan;
    const glm::dvec2 centre = place(kW * 0.37, kH * 0.61, a, pl.dx, pl.dy);
    fan.push_back(pixel_to_clip(centre.x, centre.y, kW, kH));
    const int n = 256;
    for (int i = 0; i < n; ++i) {
      const double t = a + 2.0 * std::numbers::pi * i / n;
      fan.push_back(pixel_to_clip(centre.x + 3.0 * kW * std::cos(t), centre.y + 3.0 * kW * std::sin(t), kW, kH));
    }
    std::vector<uint32_t> idx;
    for (int i = 0; i < n; ++i) idx.insert(idx.end(), {0u, 1u + i, 1u + (i + 1) % n});
    expect_all_exactly_once(draw_counting(fan, idx, kW, kH, 16, 2, 1, kCoarseBits),
                            "fan, angle " + std::to_string(pl.angle_deg));
  }
}

TEST(SubpixelPrecision, FourBitJitteredGridCoversEveryPixelOnce) {
  const int cols = 100, rows = 50;
  uint32_t seed = 987654u;
  auto next = [&seed] {  // xorshift32
    seed ^= seed << 13; seed ^= seed >> 17; seed ^= seed << 5;
    return (seed & 0xFFFFFF) / double(0x1000000);
  };
  for (const Placement& pl : {Placement{0.0, 0.0, 0.0}, Placement{17.2, 0.37, 0.11}}) {
    std::vector<glm::vec4> pos;
    const double x0 = -0.5 * kW, y0 = -0.5 * kH, cw = 2.0 * kW / cols, ch = 2.0 * kH / rows;
    for (int j = 0; j <= rows; ++j) {
      for (int i = 0; i <= cols; ++i) {
        double x = x0 + i * cw, y = y0 + j * ch;
        if (i > 0 && i < cols && j > 0 && j < rows) {
          x += (next() - 0.5) * 0.4 * cw;
          y += (next() - 0.5) * 0.4 * ch;
        }
        const glm::dvec2 p = place(x, y, pl.angle_deg * std::numbers::pi / 180.0, pl.dx, pl.dy);
        glm::vec4 clip = pixel_to_clip(p.x, p.y, kW, kH);
        clip.x *= 2.2f;  // the rotated grid must still cover the target
        clip.y *= 2.2f;
        pos.push_back(clip);
      }
    }
    std::vector<uint32_t> idx;
    for (int j = 0; j < rows; ++j) {
      for (int i = 0; i < cols; ++i) {
        const uint32_t a = j * (cols + 1) + i, b = a + 1, c = a + cols + 1, d = c + 1;
        idx.insert(idx.end(), {a, b, d, a, d, c});
      }
    }
    // Cells are about 4 px wide and snapping moves a vertex by at most 1/32 px, so no triangle
    // folds over: the snapped grid is still a tessellation and must cover each pixel once.
    expect_all_exactly_once(draw_counting(pos, idx, kW, kH, 16, 2, 1, kCoarseBits),
                            "grid angle " + std::to_string(pl.angle_deg));
  }
}

TEST(SubpixelPrecision, FourBitSharedEdgeCoversEverySampleOnce) {
  const std::vector<glm::vec4> pos = {pixel_to_clip(-40, -40, 32, 16), pixel_to_clip(32 + 40, -37, 32, 16),
                                      pixel_to_clip(32 + 43, 16 + 40, 32, 16), pixel_to_clip(-38, 16 + 41, 32, 16)};
  for (int samples : {2, 4, 8}) {
    const CountResult r = draw_counting(pos, {0, 1, 2, 0, 2, 3}, 32, 16, 16, 2, samples, kCoarseBits);
    for (float c : r.counts) ASSERT_EQ(c, 1.0f) << samples << " samples";
  }
}

// A vertical shared edge at x = 40.5 + offset. At 8 bits it snaps to 40.5 + round(256 offset) / 256,
// at 4 bits to 40.5 + round(16 offset) / 16. A pixel centre exactly on the edge belongs to the
// right triangle (its left edge, D3D11 3.4.2.1); a centre left of the edge to the left one.
// Returns, for column 40, how many rows the right triangle owns (the left one owns the rest).
int right_triangle_rows_in_column_40(double offset_px, int subpixel_bits) {
  const double x = 40.5 + offset_px;
  const std::vector<glm::vec4> pos = {pixel_to_clip(x, -10, kW, kH), pixel_to_clip(x, kH + 10, kW, kH),
                                      pixel_to_clip(-10, kH / 2.0, kW, kH), pixel_to_clip(kW + 10, kH / 2.0, kW, kH)};
  const CountResult left = draw_counting(pos, {0, 1, 2}, kW, kH, 16, 2, 1, subpixel_bits);
  const CountResult right = draw_counting(pos, {0, 1, 3}, kW, kH, 16, 2, 1, subpixel_bits);
  int right_rows = 0;
  for (int y = 0; y < kH; ++y) {
    EXPECT_EQ(left.at(40, y, kW) + right.at(40, y, kW), 1.0f) << "row " << y;
    right_rows += right.at(40, y, kW) == 1.0f;
  }
  return right_rows;
}

TEST(SubpixelPrecision, VerticesSnapToTheConfiguredGrid) {
  // 0.02 px: 8 bits keep 5/256 (centre left of the edge), 4 bits round it away (centre on it).
  EXPECT_EQ(right_triangle_rows_in_column_40(0.02, 8), 0);
  EXPECT_EQ(right_triangle_rows_in_column_40(0.02, kCoarseBits), kH);
  // 0.04 px: 4 bits give 1/16 (centre left of the edge again).
  EXPECT_EQ(right_triangle_rows_in_column_40(0.04, kCoarseBits), 0);
  // -0.02 px: 8 bits put the edge left of the centres, 4 bits on them; both give the right triangle.
  EXPECT_EQ(right_triangle_rows_in_column_40(-0.02, 8), kH);
  EXPECT_EQ(right_triangle_rows_in_column_40(-0.02, kCoarseBits), kH);
}

TEST(SubpixelPrecision, OtherPrecisionsAreErrorsNamingTheValue) {
  const std::vector<glm::vec4> tri = {pixel_to_clip(1, 1, 8, 8), pixel_to_clip(7, 1, 8, 8), pixel_to_clip(1, 7, 8, 8)};
  for (int bits : {0, 3, 5, 6, 7, 9, 16}) {
    try {
      draw_counting(tri, {0, 1, 2}, 8, 8, 16, 1, 1, bits);
      ADD_FAILURE() << bits << " bits were accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("subpixel precision " + std::to_string(bits) + " bits"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace ontile::test
