// Attachment pictures: file names, the 8-bit views of colour and depth formats, downscaling and
// the tile grid.
#include <gtest/gtest.h>

#include "report/attachment_images.h"

namespace ontile {
namespace {

TEST(AttachmentImages, FileNamesSayPassAttachmentAndFormat) {
  EXPECT_EQ(attachment_file_name(3, "blit toon/edges", "final", PixelFormat::RGBA8_SRGB), "3-blit_toon_edges-final.png");
  EXPECT_EQ(attachment_file_name(0, "gbuffer", "depth", PixelFormat::D32_FLOAT), "0-gbuffer-depth.exr");
  EXPECT_EQ(attachment_file_name(1, "light", "hdr", PixelFormat::RGBA16_FLOAT), "1-light-hdr.exr");
}

TEST(AttachmentImages, ViewsShowColourAsStoredAndDepthNearBright) {
  Surface color("c", PixelFormat::RGBA8_UNORM, 2, 1);
  color.write(0, 0, 0, {1.0f, 0.0f, 0.2f, 0.0f});
  const Rgba8Image c = display_image(color);
  EXPECT_EQ(std::vector<uint8_t>(c.rgba.begin(), c.rgba.begin() + 4), (std::vector<uint8_t>{255, 0, 51, 255}));

  Surface depth("d", PixelFormat::D32_FLOAT, 3, 1);
  depth.write(0, 0, 0, glm::vec4(0.25f));
  depth.write(1, 0, 0, glm::vec4(0.75f));
  depth.write(2, 0, 0, glm::vec4(1.0f));  // cleared
  const Rgba8Image d = display_image(depth);
  EXPECT_EQ(d.rgba[0], 255);           // nearest drawn: brightest
  EXPECT_LT(d.rgba[4], d.rgba[0]);     // farther: darker
  EXPECT_GT(d.rgba[4], 0);
  EXPECT_EQ(d.rgba[8], 0);             // cleared: black
  EXPECT_EQ(d.rgba[11], 255);

  Surface hdr("h", PixelFormat::RGBA16_FLOAT, 1, 1);
  hdr.write(0, 0, 0, {4.0f, 0.5f, -1.0f, 1.0f});
  const Rgba8Image h = display_image(hdr);
  EXPECT_EQ(h.rgba[0], 255);  // clamped
  EXPECT_EQ(h.rgba[1], linear_to_srgb8(0.5f));
  EXPECT_EQ(h.rgba[2], 0);
}

TEST(AttachmentImages, DownscaleAveragesAndTheGridIsMagenta) {
  Rgba8Image image{4, 2, std::vector<uint8_t>(4 * 2 * 4, 0)};
  for (int i = 0; i < 4; ++i) image.rgba[i * 4] = static_cast<uint8_t>(i * 60);  // top row: red 0, 60, 120, 180
  const Rgba8Image half = downscale(image, 2);
  ASSERT_EQ(half.width, 2);
  ASSERT_EQ(half.height, 1);
  EXPECT_EQ(half.rgba[0], (0 + 60 + 0 + 0 + 2) / 4);  // a 2x2 box, rounded
  EXPECT_EQ(half.rgba[4], (120 + 180 + 0 + 0 + 2) / 4);
  EXPECT_EQ(downscale(image, 8).rgba, image.rgba);

  Rgba8Image grid{5, 5, std::vector<uint8_t>(5 * 5 * 4, 0)};
  draw_tile_grid(grid, 4, 4);
  auto magenta = [&](int x, int y) {
    const uint8_t* p = &grid.rgba[(static_cast<size_t>(y) * 5 + x) * 4];
    return p[0] == 255 && p[1] == 0 && p[2] == 255;
  };
  EXPECT_TRUE(magenta(0, 3));
  EXPECT_TRUE(magenta(4, 1));
  EXPECT_TRUE(magenta(2, 4));
  EXPECT_FALSE(magenta(1, 1));
  EXPECT_FALSE(magenta(3, 3));
}

}  // namespace
}  // namespace ontile
