// Index-driven vertex shading and fp16 varyings (TilerConfig::idvs, varying_precision): the
// parameter buffer's position and varying bytes equal the analytic counts on constructed
// scenes (back-facing, off-screen, shared and clipped vertices), the parameter cache replays
// the fp16 layout, the IMR writes no parameter buffer, and images do not change.
#include <gtest/gtest.h>

#include <cstring>

#include "support/raster_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 100, kH = 60;
constexpr int kVaryings = 4;  // VaryingsShader writes varyings 0-3

struct Drawn {
  PassReport pass;
  std::vector<uint8_t> pixels;
};

// One pass drawing `idx` with back-face culling into an RGBA32F target that holds the first
// varyings, so the image shows interpolated values.
Drawn draw(const std::vector<glm::vec4>& pos, const std::vector<uint32_t>& idx, bool idvs,
           VaryingPrecision precision, Architecture architecture = Architecture::Tbdr,
           uint32_t parameter_cache_bytes = 0) {
  ContextConfig config;
  config.threads = 2;
  config.tiler.idvs = idvs;
  config.tiler.varying_precision = precision;
  config.tiler.architecture = architecture;
  config.tiler.parameter_cache.size_bytes = parameter_cache_bytes;
  RenderContext ctx(config);
  Surface* s = ctx.create_surface("c", PixelFormat::RGBA32_FLOAT, kW, kH);
  std::vector<float> varyings(pos.size() * kVaryings);
  for (size_t i = 0; i < varyings.size(); ++i) varyings[i] = 0.1f + 0.37f * static_cast<float>(i % 7);
  ClipSpaceVertexShader vs(pos, varyings, kVaryings);
  VaryingsShader fs;
  ctx.begin_render_pass("p", kW, kH, 1, {{"c", PixelFormat::RGBA32_FLOAT, LoadAction::Clear,
                                          StoreAction::Store, glm::vec4(0.0f), s, nullptr}}, -1);
  ctx.begin_subpass({0});
  DrawCall d;
  d.vertex_shader = &vs;
  d.fragment_shader = &fs;
  d.vertex_count = static_cast<uint32_t>(pos.size());
  d.indices = idx.data();
  d.index_count = static_cast<uint32_t>(idx.size());
  d.raster.cull = CullMode::Back;
  ctx.draw(d);
  ctx.end_subpass();
  ctx.end_render_pass();
  const FrameReport r = ctx.submit();
  Drawn out{r.passes[0], {}};
  out.pixels = s->bytes();
  return out;
}

// Appends a small triangle with its own three vertices at pixel (x, y); `front` picks the
// winding that survives back-face culling.
void add_triangle(std::vector<glm::vec4>& pos, std::vector<uint32_t>& idx, double x, double y, bool front) {
  const uint32_t base = static_cast<uint32_t>(pos.size());
  pos.push_back(pixel_to_clip(x, y, kW, kH));
  pos.push_back(pixel_to_clip(x + 8, y, kW, kH));
  pos.push_back(pixel_to_clip(x, y + 6, kW, kH));
  if (front) {
    idx.insert(idx.end(), {base, base + 2, base + 1});
  } else {
    idx.insert(idx.end(), {base, base + 1, base + 2});
  }
}

TEST(Idvs, VaryingsAreWrittenOnlyForVerticesOfSurvivingTriangles) {
  // N front-facing triangles on screen, K back-facing ones and J right of the viewport (rejected
  // as outside), each with its own three vertices.
  constexpr int kFront = 7, kBack = 4, kOffScreen = 2;
  std::vector<glm::vec4> pos;
  std::vector<uint32_t> idx;
  for (int i = 0; i < kFront; ++i) add_triangle(pos, idx, 4 + 12 * i, 5, true);
  for (int i = 0; i < kBack; ++i) add_triangle(pos, idx, 4 + 12 * i, 30, false);
  for (int i = 0; i < kOffScreen; ++i) add_triangle(pos, idx, kW + 20 + 12 * i, 10, true);
  const uint64_t vertices = 3u * (kFront + kBack + kOffScreen), surviving = 3u * kFront;

  const Drawn full = draw(pos, idx, false, VaryingPrecision::Fp32);
  ASSERT_EQ(full.pass.geometry.triangles_binned, uint64_t{kFront});
  ASSERT_EQ(full.pass.geometry.triangles_culled, uint64_t{kBack});
  ASSERT_EQ(full.pass.geometry.triangles_outside, uint64_t{kOffScreen});
  const uint64_t records = uint64_t{12} * kFront +
                           4u * full.pass.geometry.tile_list_entries;
  EXPECT_EQ(full.pass.geometry.parameter_position_bytes_written, 16u * vertices);
  EXPECT_EQ(full.pass.geometry.parameter_varying_bytes_written, 4u * kVaryings * vertices);
  EXPECT_EQ(full.pass.geometry.parameter_bytes_written, (16u + 4u * kVaryings) * vertices + records);

  const Drawn idvs = draw(pos, idx, true, VaryingPrecision::Fp32);
  EXPECT_EQ(idvs.pass.geometry.parameter_position_bytes_written, 16u * vertices);
  EXPECT_EQ(idvs.pass.geometry.parameter_varying_bytes_written, 4u * kVaryings * surviving);
  EXPECT_EQ(idvs.pass.geometry.parameter_bytes_written, 16u * vertices + 4u * kVaryings * surviving + records);
  EXPECT_EQ(idvs.pass.tiles.parameter_bytes_read, full.pass.tiles.parameter_bytes_read)
      << "tiles read the same records";

  const Drawn half = draw(pos, idx, true, VaryingPrecision::Fp16);
  EXPECT_EQ(half.pass.geometry.parameter_varying_bytes_written, 2u * kVaryings * surviving);
  const uint64_t entries = full.pass.geometry.tile_list_entries;
  EXPECT_EQ(half.pass.tiles.parameter_bytes_read, entries * (4 + 12 + 3 * (16 + 2 * kVaryings)));
  EXPECT_EQ(full.pass.tiles.parameter_bytes_read, entries * (4 + 12 + 3 * (16 + 4 * kVaryings)));

  const Drawn half_all = draw(pos, idx, false, VaryingPrecision::Fp16);
  EXPECT_EQ(half_all.pass.geometry.parameter_varying_bytes_written, 2u * kVaryings * vertices);

  // Storage only: interpolation stays fp32, so every configuration draws the same bits.
  EXPECT_EQ(idvs.pixels, full.pixels);
  EXPECT_EQ(half.pixels, full.pixels);
  EXPECT_EQ(half_all.pixels, full.pixels);
}

// Seven front-facing triangles, each with its own three vertices, and four back-facing ones.
void front_and_back(std::vector<glm::vec4>& pos, std::vector<uint32_t>& idx) {
  for (int i = 0; i < 7; ++i) add_triangle(pos, idx, 4 + 12 * i, 5, true);
  for (int i = 0; i < 4; ++i) add_triangle(pos, idx, 4 + 12 * i, 30, false);
}

TEST(Idvs, TheParameterCacheReadsVerticesAtTheFp16Stride) {
  // The replay through MemoryModel::parameter_read lays vertices out at the stored stride. With
  // a cache that holds the whole buffer every line misses once; tile lists and records are the
  // same, and the surviving triangles read vertices 0-20 of the draw: 21 x 32 B = 11 lines at
  // fp32, 21 x 24 B = 8 lines at fp16 (every region 64-byte aligned).
  std::vector<glm::vec4> pos;
  std::vector<uint32_t> idx;
  front_and_back(pos, idx);
  constexpr uint32_t kCacheBytes = 1u << 20;
  const Drawn fp32 = draw(pos, idx, true, VaryingPrecision::Fp32, Architecture::Tbdr, kCacheBytes);
  const Drawn fp16 = draw(pos, idx, true, VaryingPrecision::Fp16, Architecture::Tbdr, kCacheBytes);
  ASSERT_EQ(fp32.pass.geometry.triangles_binned, 7u);
  EXPECT_EQ(fp32.pass.parameter_cache.misses - fp16.pass.parameter_cache.misses, 11u - 8u);
  EXPECT_EQ(fp16.pass.tiles.parameter_bytes_read, 64u * fp16.pass.parameter_cache.misses);
  EXPECT_EQ(fp16.pixels, fp32.pixels);
}

TEST(Idvs, AnImmediateModeGpuWritesNoParameterBuffer) {
  std::vector<glm::vec4> pos;
  std::vector<uint32_t> idx;
  front_and_back(pos, idx);
  const Drawn tbdr = draw(pos, idx, true, VaryingPrecision::Fp16);
  const Drawn imr = draw(pos, idx, true, VaryingPrecision::Fp16, Architecture::Imr);
  ASSERT_GT(tbdr.pass.geometry.parameter_varying_bytes_written, 0u);
  EXPECT_EQ(imr.pass.geometry.parameter_bytes_written, 0u);
  EXPECT_EQ(imr.pass.geometry.parameter_position_bytes_written, 0u);
  EXPECT_EQ(imr.pass.geometry.parameter_varying_bytes_written, 0u);
  EXPECT_EQ(imr.pass.tiles.parameter_bytes_read, 0u);
  EXPECT_EQ(imr.pixels, tbdr.pixels);
}

TEST(Idvs, ASharedVertexCarriesVaryingsWhenAnySurvivingTriangleUsesIt) {
  // A quad split along its diagonal into one front- and one back-facing triangle: four
  // vertices positioned, the front triangle's three with varyings.
  const std::vector<glm::vec4> pos = {pixel_to_clip(10, 10, kW, kH), pixel_to_clip(40, 10, kW, kH),
                                      pixel_to_clip(10, 40, kW, kH), pixel_to_clip(40, 40, kW, kH)};
  // 0, 2, 1 winds as add_triangle's front triangles do; 1, 3, 2 the other way.
  const std::vector<uint32_t> idx = {0, 2, 1, 1, 3, 2};
  const Drawn full = draw(pos, idx, false, VaryingPrecision::Fp32);
  const Drawn idvs = draw(pos, idx, true, VaryingPrecision::Fp32);
  ASSERT_EQ(idvs.pass.geometry.triangles_binned, 1u);
  ASSERT_EQ(idvs.pass.geometry.triangles_culled, 1u);
  EXPECT_EQ(full.pass.geometry.parameter_varying_bytes_written, 4u * kVaryings * 4);
  EXPECT_EQ(idvs.pass.geometry.parameter_position_bytes_written, 16u * 4);
  EXPECT_EQ(idvs.pass.geometry.parameter_varying_bytes_written, 4u * kVaryings * 3);
  EXPECT_EQ(idvs.pixels, full.pixels);
}

TEST(Idvs, AClippedTriangleWritesVaryingsForThePolygonVerticesItsFanUses) {
  // One vertex behind the near plane (z < 0): clipping makes a quad, drawn as two fan triangles.
  // Without IDVS the three input vertices and the four polygon vertices are written whole; with
  // it all seven are positioned but only the polygon's four, which the records reference, carry
  // varyings.
  const std::vector<glm::vec4> pos = {pixel_to_clip(10, 10, kW, kH), pixel_to_clip(10, 50, kW, kH),
                                      pixel_to_clip(60, 30, kW, kH, 1.0, -0.5)};
  for (const std::vector<uint32_t>& idx : {std::vector<uint32_t>{0, 1, 2}, std::vector<uint32_t>{0, 2, 1}}) {
    const Drawn full = draw(pos, idx, false, VaryingPrecision::Fp32);
    if (full.pass.geometry.triangles_binned == 0) continue;  // the culled winding
    ASSERT_EQ(full.pass.geometry.triangles_clipped, 1u);
    ASSERT_EQ(full.pass.geometry.triangles_binned, 2u);
    const Drawn idvs = draw(pos, idx, true, VaryingPrecision::Fp32);
    EXPECT_EQ(full.pass.geometry.parameter_position_bytes_written, 16u * 7);
    EXPECT_EQ(full.pass.geometry.parameter_varying_bytes_written, 4u * kVaryings * 7);
    EXPECT_EQ(idvs.pass.geometry.parameter_position_bytes_written, 16u * 7);
    EXPECT_EQ(idvs.pass.geometry.parameter_varying_bytes_written, 4u * kVaryings * 4);
    EXPECT_EQ(idvs.pixels, full.pixels);
    return;
  }
  FAIL() << "neither winding survived culling";
}

}  // namespace
}  // namespace ontile::test
