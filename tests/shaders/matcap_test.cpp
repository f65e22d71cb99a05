// MatCap: normal -> uv mapping, the generated spheres' character and determinism, style
// parsing, and MatCap files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <utility>
#include <vector>

#include "io/image_io.h"
#include "raster/pixel_format.h"
#include "shaders/toon_test_support.h"
#include "shaders_cpp/toon/matcap_generator.h"
#include "shaders_cpp/toon/matcap_shader.h"

namespace ontile {
namespace {

TEST(MatCapUv, MapsViewNormalsOntoTheSphereImage) {
  EXPECT_EQ(matcap_uv({0.0f, 0.0f, 1.0f}), glm::vec2(0.5f, 0.5f));   // centre
  EXPECT_EQ(matcap_uv({1.0f, 0.0f, 0.0f}), glm::vec2(1.0f, 0.5f));   // middle of the right edge
  EXPECT_EQ(matcap_uv({0.0f, 1.0f, 0.0f}), glm::vec2(0.5f, 0.0f));   // top (v = 0 is the top row)
  EXPECT_EQ(matcap_uv({-1.0f, 0.0f, 0.0f}), glm::vec2(0.0f, 0.5f));
  EXPECT_EQ(matcap_uv({0.0f, -1.0f, 0.0f}), glm::vec2(0.5f, 1.0f));
}

TEST(MatCapShader, ColourIsTheMatCapAtTheNormalTimesBaseColour) {
  // 2x2 MatCap: each quadrant its own colour; bilinear at a texel centre returns that texel.
  const auto matcap = test::make_float_texture(2, 2, [](int x, int y) {
    return glm::vec4(static_cast<float>(x), static_cast<float>(y), 0.5f, 1.0f);
  });
  MatCapParams p;
  p.matcap = matcap.get();
  p.base_color = glm::vec4(0.5f, 1.0f, 1.0f, 0.75f);
  const MatCapShader<ToonOutput::kColor, false, false> shader(p);
  QuadFragment q = test::make_quad(0, 0, 0xF);
  // matcap_uv((+-0.5, +-0.5, z)) = texel centres (0.25 or 0.75).
  test::set_var3(q, ToonVertexShader::kViewNormal, 0, {-0.5f, 0.5f, 0.70710677f});   // texel (0,0)
  test::set_var3(q, ToonVertexShader::kViewNormal, 1, {0.5f, 0.5f, 0.70710677f});    // texel (1,0)
  test::set_var3(q, ToonVertexShader::kViewNormal, 2, {-0.5f, -0.5f, 0.70710677f});  // texel (0,1)
  test::set_var3(q, ToonVertexShader::kViewNormal, 3, {0.5f, -0.5f, 0.70710677f});   // texel (1,1)
  QuadOutput out;
  shader.shade(q, out);
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    const glm::vec4 texel = matcap->fetch(0, lane & 1, lane >> 1);
    EXPECT_NEAR(out.color[0][lane].x, texel.x * 0.5f, 1e-6f) << lane;
    EXPECT_NEAR(out.color[0][lane].y, texel.y, 1e-6f) << lane;
    EXPECT_NEAR(out.color[0][lane].z, 0.5f, 1e-6f) << lane;
    EXPECT_EQ(out.color[0][lane].w, 0.75f) << lane;
  }
}

TEST(MatCapShader, FlatNormalMapKeepsTheGeometricNormal) {
  // A tangent-space normal of (0, 0, 1) maps to N itself, so the NORMAL_MAP variant with an
  // identity view rotation must read the same MatCap texel as the plain variant.
  const auto matcap = generate_matcap(MatCapStyle::Painted, 32);
  const auto flat = test::make_float_texture(1, 1, [](int, int) { return glm::vec4(0.5f, 0.5f, 1.0f, 1.0f); });
  MatCapParams p;
  p.matcap = matcap.get();
  p.normal_map = flat.get();
  const MatCapShader<ToonOutput::kColor, false, true> mapped(p);
  const MatCapShader<ToonOutput::kColor, false, false> plain(p);
  QuadFragment q = test::make_quad(0, 0, 0xF);
  const glm::vec3 normals[4] = {{0.3f, 0.4f, 0.866f}, {-0.6f, 0.0f, 0.8f}, {0.0f, -0.8f, 0.6f}, {0.0f, 0.0f, 1.0f}};
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    test::set_var3(q, ToonVertexShader::kNormal, lane, normals[lane]);
    test::set_var3(q, ToonVertexShader::kViewNormal, lane, normals[lane]);
    const glm::vec3 tangent = glm::normalize(glm::cross(glm::vec3(0, 1, 0.1f), normals[lane]));
    for (int k = 0; k < 3; ++k) q.varyings[ToonVertexShader::kTangent + k][lane] = tangent[k];
    q.varyings[ToonVertexShader::kTangent + 3][lane] = 1.0f;
  }
  QuadOutput a, b;
  mapped.shade(q, a);
  plain.shade(q, b);
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(a.color[0][lane][k], b.color[0][lane][k], 1e-5f) << lane;
  }
}

TEST(PerturbNormal, FollowsTheTangentFrame) {
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  // Tangent +X, handedness +1: B = cross(N, T) = +Y.
  EXPECT_EQ(perturb_normal(n, {1, 0, 0, 1}, {1, 0, 0}), glm::vec3(1, 0, 0));
  EXPECT_EQ(perturb_normal(n, {1, 0, 0, 1}, {0, 1, 0}), glm::vec3(0, 1, 0));
  EXPECT_EQ(perturb_normal(n, {1, 0, 0, -1}, {0, 1, 0}), glm::vec3(0, -1, 0));
  // No tangent: unperturbed.
  EXPECT_EQ(perturb_normal(n, {0, 0, 0, 0}, {1, 0, 0}), n);
}

float luminance(glm::vec4 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

TEST(GenerateMatCap, IsDeterministicSrgbAndSized) {
  for (MatCapStyle style : {MatCapStyle::Metal, MatCapStyle::Clay, MatCapStyle::Painted}) {
    const auto a = generate_matcap(style, 64);
    const auto b = generate_matcap(style, 64);
    ASSERT_EQ(a->width(), 64);
    ASSERT_EQ(a->height(), 64);
    EXPECT_EQ(a->encoding(), TexelEncoding::Srgb8);
    EXPECT_EQ(a->name(), std::string("matcap:") + matcap_style_name(style));
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) ASSERT_EQ(a->fetch(0, x, y), b->fetch(0, x, y)) << x << "," << y;
  }
  EXPECT_THROW(generate_matcap(MatCapStyle::Clay, 0), Error);
}

TEST(GenerateMatCap, StylesHaveTheirCharacter) {
  constexpr int kSize = 128;
  const auto at = [](const Texture2D& t, glm::vec3 n) {
    const glm::vec2 uv = matcap_uv(glm::normalize(n));
    return t.fetch(0, static_cast<int>(uv.x * kSize), static_cast<int>(uv.y * kSize));
  };
  // Clay: lit from the upper left; the light-facing side is brighter, the far side still lit.
  const auto clay = generate_matcap(MatCapStyle::Clay, kSize);
  EXPECT_GT(luminance(at(*clay, {-0.4f, 0.5f, 0.75f})), luminance(at(*clay, {0.6f, -0.6f, 0.5f})) + 0.2f);
  EXPECT_GT(luminance(at(*clay, {0.6f, -0.6f, 0.5f})), 0.05f);
  // Metal: a bright horizon band, a dark bottom.
  const auto metal = generate_matcap(MatCapStyle::Metal, kSize);
  // The reflection of (0, 0, -1) about n is horizontal where n.y = 0 and n.z != 0.
  EXPECT_GT(luminance(at(*metal, {0.0f, 0.0f, 1.0f})), 0.9f);
  EXPECT_LT(luminance(at(*metal, {0.0f, -0.8f, 0.6f})), 0.05f);
  // Painted: flat bands, so nearly all interior texels take one of four exact colours (three
  // bands and the highlight); only texels on band borders are blends.
  const auto painted = generate_matcap(MatCapStyle::Painted, kSize);
  std::vector<std::pair<glm::vec4, int>> histogram;
  int interior = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const float nx = (x + 0.5f) / kSize * 2 - 1, ny = (y + 0.5f) / kSize * 2 - 1;
      if (nx * nx + ny * ny > 0.9f) continue;
      ++interior;
      const glm::vec4 c = painted->fetch(0, x, y);
      auto it = std::find_if(histogram.begin(), histogram.end(), [&](const auto& e) { return e.first == c; });
      if (it == histogram.end()) histogram.push_back({c, 1});
      else ++it->second;
    }
  }
  std::sort(histogram.begin(), histogram.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  ASSERT_GE(histogram.size(), 4u);
  const int top4 = histogram[0].second + histogram[1].second + histogram[2].second + histogram[3].second;
  EXPECT_GT(top4, interior * 9 / 10);
}

TEST(ParseMatCapStyle, KnowsTheThreeStyles) {
  EXPECT_EQ(parse_matcap_style("metal"), MatCapStyle::Metal);
  EXPECT_EQ(parse_matcap_style("Clay"), MatCapStyle::Clay);
  EXPECT_EQ(parse_matcap_style("PAINTED"), MatCapStyle::Painted);
  try {
    parse_matcap_style("chrome");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'chrome'"), std::string::npos) << e.what();
  }
}

TEST(LoadMatCap, ReadsAnSrgbImageAndNamesMissingFiles) {
  const auto dir = std::filesystem::temp_directory_path() / "ontile_matcap_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / "sphere.png";
  const std::vector<uint8_t> rgba = {10, 20, 30, 255, 200, 100, 50, 128};
  write_png_rgba8(path, 2, 1, rgba);
  const auto t = load_matcap(path);
  ASSERT_EQ(t->width(), 2);
  EXPECT_EQ(t->encoding(), TexelEncoding::Srgb8);
  const auto& srgb = srgb8_decode_table();
  EXPECT_EQ(t->fetch(0, 1, 0), glm::vec4(srgb[200], srgb[100], srgb[50], unorm8_decode_table()[128]));
  const auto missing = dir / "missing.png";
  try {
    load_matcap(missing);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ontile
