// Block-compressed texture storage (--texture-compression): the layout of each block format,
// texels mapped to the block that holds them, exact texture-cache misses of a full-screen copy
// (one miss per 64-byte line of the stored level: W x H x bytes per texel / 64), and images that
// do not change (sampling reads the decoded texels).
#include <gtest/gtest.h>

#include <vector>

#include "raster/texture.h"
#include "support/textured_quad.h"

namespace ontile {
namespace {

constexpr int kSize = 256;

std::shared_ptr<const Texture2D> patterned(TextureCompression compression, bool translucent = false) {
  std::vector<uint8_t> rgba(size_t{kSize} * kSize * 4);
  for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<uint8_t>((i * 37u) ^ (i >> 9));
  for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
  if (translucent) rgba[3] = 128;
  return Texture2D::from_rgba8(kSize, kSize, std::move(rgba), true, "patterned", compression);
}

uint64_t reserved_bytes(const Texture2D& t) {
  return Texture2D::reserved_bytes_of(t.base_address() >> Texture2D::kTextureIdShift);
}

TEST(TextureCompression, NamesRoundTrip) {
  for (TextureCompression c : {TextureCompression::None, TextureCompression::Astc4x4,
                               TextureCompression::Astc8x8, TextureCompression::Etc2}) {
    EXPECT_EQ(parse_texture_compression(texture_compression_name(c)), c);
  }
  EXPECT_FALSE(parse_texture_compression("astc6x6").has_value());
}

TEST(TextureCompression, TexelsOfOneBlockShareItsAddressAndLevelsAreBlockSized) {
  const auto astc8 = patterned(TextureCompression::Astc8x8);
  EXPECT_EQ(astc8->texel_address(0, 0, 0), astc8->texel_address(0, 7, 7));
  EXPECT_EQ(astc8->texel_address(0, 8, 0) - astc8->texel_address(0, 0, 0), 16u);
  EXPECT_EQ(astc8->texel_address(0, 0, 8) - astc8->texel_address(0, 0, 0), 32u * 16u);  // 32 blocks a row
  EXPECT_EQ(astc8->level_offset_bytes(1), 32u * 32u * 16u);
  // 256 .. 1 texels: 32^2, 16^2, 8^2, 4^2, 2^2 blocks, then four levels of one block each.
  EXPECT_EQ(reserved_bytes(*astc8), (16384u + 4096u + 1024u + 256u + 64u + 4u * 16u + 4095u) / 4096u * 4096u);

  const auto astc4 = patterned(TextureCompression::Astc4x4);
  EXPECT_EQ(astc4->texel_address(0, 3, 3), astc4->texel_address(0, 0, 0));
  EXPECT_EQ(astc4->texel_address(0, 4, 0) - astc4->texel_address(0, 0, 0), 16u);
  EXPECT_EQ(astc4->level_offset_bytes(1), 64u * 64u * 16u);

  const auto etc2 = patterned(TextureCompression::Etc2);
  const auto etc2_alpha = patterned(TextureCompression::Etc2, true);
  EXPECT_EQ(etc2->texel_address(0, 4, 0) - etc2->texel_address(0, 0, 0), 8u) << "opaque: ETC2 RGB8";
  EXPECT_EQ(etc2_alpha->texel_address(0, 4, 0) - etc2_alpha->texel_address(0, 0, 0), 16u)
      << "alpha below 255: ETC2 RGBA8 (EAC alpha)";

  const auto plain = patterned(TextureCompression::None);
  EXPECT_EQ(plain->texel_address(0, 1, 0) - plain->texel_address(0, 0, 0), 4u);
}

TEST(TextureCompression, AFullScreenCopyMissesEveryStoredLineOnce) {
  // Pixel (x, y) reads texel (x, y) once; tiles run in row-major order and every line a tile
  // touches stays cached while its neighbours use it, so the misses are the level's lines:
  // W x H x bytes per texel / 64.
  const test::TexturedQuadResult none = test::draw_textured_quad(patterned(TextureCompression::None), kSize, 2);
  EXPECT_EQ(none.texture.misses, uint64_t{kSize} * kSize * 4 / 64);
  const struct {
    TextureCompression compression;
    bool translucent;
    uint64_t bytes_per_texel_x4;  // bytes per texel, times 4
  } cases[] = {{TextureCompression::Astc4x4, false, 4},
               {TextureCompression::Astc8x8, false, 1},
               {TextureCompression::Etc2, false, 2},
               {TextureCompression::Etc2, true, 4}};
  for (const auto& c : cases) {
    const test::TexturedQuadResult r =
        test::draw_textured_quad(patterned(c.compression, c.translucent), kSize, 2);
    EXPECT_EQ(r.texture.misses, uint64_t{kSize} * kSize * c.bytes_per_texel_x4 / 4 / 64)
        << texture_compression_name(c.compression) << (c.translucent ? " with alpha" : "");
    EXPECT_EQ(r.texture.bytes_read, r.texture.misses * 64);
    if (!c.translucent) EXPECT_EQ(r.pixels, none.pixels) << "storage only: the decoded texels are sampled";
  }
}

}  // namespace
}  // namespace ontile
