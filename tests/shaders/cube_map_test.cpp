// Cube maps: face selection per the Vulkan table (axes, ties, a diagonal), the inverse
// mapping, sampling, the equirect and gradient-sky factories and their errors.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>

#include "raster/pixel_format.h"
#include "shaders/toon_test_support.h"
#include "shaders_cpp/toon/toon_env_shader.h"

namespace ontile {
namespace {

void expect_coord(glm::vec3 d, CubeFace face, glm::vec2 uv) {
  const CubeFaceCoord c = cube_face_coord(d);
  EXPECT_EQ(c.face, face) << d.x << "," << d.y << "," << d.z;
  EXPECT_EQ(c.uv, uv) << d.x << "," << d.y << "," << d.z;
}

TEST(CubeFaceCoord, SelectsFacesPerTheVulkanTable) {
  expect_coord({1, 0, 0}, CubeFace::PositiveX, {0.5f, 0.5f});
  expect_coord({-1, 0, 0}, CubeFace::NegativeX, {0.5f, 0.5f});
  expect_coord({0, 1, 0}, CubeFace::PositiveY, {0.5f, 0.5f});
  expect_coord({0, -1, 0}, CubeFace::NegativeY, {0.5f, 0.5f});
  expect_coord({0, 0, 1}, CubeFace::PositiveZ, {0.5f, 0.5f});
  expect_coord({0, 0, -1}, CubeFace::NegativeZ, {0.5f, 0.5f});
  // Off-centre, one per face: s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2.
  expect_coord({2, 1, -0.5f}, CubeFace::PositiveX, {0.625f, 0.25f});   // sc = -z, tc = -y
  expect_coord({-2, 1, -0.5f}, CubeFace::NegativeX, {0.375f, 0.25f});  // sc = z, tc = -y
  expect_coord({0.5f, 2, 1}, CubeFace::PositiveY, {0.625f, 0.75f});    // sc = x, tc = z
  expect_coord({0.5f, -2, 1}, CubeFace::NegativeY, {0.625f, 0.25f});   // sc = x, tc = -z
  expect_coord({0.5f, 1, 2}, CubeFace::PositiveZ, {0.625f, 0.25f});    // sc = x, tc = -y
  expect_coord({0.5f, 1, -2}, CubeFace::NegativeZ, {0.375f, 0.25f});   // sc = -x, tc = -y
  // Ties: z wins over y and x, y over x. The diagonal lands in +Z's top-right corner.
  expect_coord({1, 1, 1}, CubeFace::PositiveZ, {1.0f, 0.0f});
  expect_coord({-1, -1, -1}, CubeFace::NegativeZ, {1.0f, 1.0f});
  expect_coord({1, 1, 0.5f}, CubeFace::PositiveY, {1.0f, 0.75f});
  // Degenerate directions fall back to the +Z centre.
  expect_coord({0, 0, 0}, CubeFace::PositiveZ, {0.5f, 0.5f});
}

TEST(CubeFaceCoord, InvertsCubeFaceDirection) {
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (glm::vec2 uv : {glm::vec2(0.25f, 0.75f), glm::vec2(0.875f, 0.125f), glm::vec2(0.5f, 0.5f)}) {
      const CubeFaceCoord c = cube_face_coord(cube_face_direction(static_cast<CubeFace>(f), uv));
      EXPECT_EQ(static_cast<int>(c.face), f);
      EXPECT_EQ(c.uv, uv) << f;
    }
  }
}

std::array<std::shared_ptr<const Texture2D>, kCubeFaceCount> solid_faces(int size) {
  std::array<std::shared_ptr<const Texture2D>, kCubeFaceCount> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    faces[f] = test::make_float_texture(size, size, [f](int, int) {
      return glm::vec4(static_cast<float>(f), 0.0f, 0.0f, 1.0f);
    });
  }
  return faces;
}

TEST(CubeMap, SamplesTheSelectedFace) {
  const CubeMap cube(solid_faces(4));
  EXPECT_EQ(cube.face_size_px(), 4);
  EXPECT_EQ(cube.sample({-3, 1, 1}).x, 1.0f);
  EXPECT_EQ(cube.sample({0.1f, -3, 1}).x, 3.0f);
  EXPECT_EQ(cube.sample({0.1f, 0.2f, -0.5f}).x, 5.0f);
}

TEST(CubeMap, RejectsMismatchedFaces) {
  auto faces = solid_faces(4);
  faces[3] = test::make_float_texture(2, 2, [](int, int) { return glm::vec4(1.0f); });
  EXPECT_THROW(CubeMap{faces}, Error);
  faces[3] = test::make_float_texture(4, 2, [](int, int) { return glm::vec4(1.0f); });
  EXPECT_THROW(CubeMap{faces}, Error);
  faces[3] = nullptr;
  EXPECT_THROW(CubeMap{faces}, Error);
}

TEST(CubeMap, FromEquirectPutsTheImageCentreAtMinusZ) {
  // 8x4 equirect: row 0 = up colour, row 3 = down colour, rows 1-2 by longitude: columns
  // (7, 0) +Z (u = 1), (1, 2) -X (u = 0.25), (3, 4) -Z (u = 0.5), (5, 6) +X (u = 0.75). Bilinear
  // taps at those u fall between the two columns of each pair.
  const glm::vec4 up(1, 1, 1, 1), down(0, 0, 0, 1), pz(1, 0, 0, 1), nx(0, 1, 0, 1), nz(0, 0, 1, 1),
      px(1, 1, 0, 1);
  const auto equirect = test::make_float_texture(8, 4, [&](int x, int y) {
    if (y == 0) return up;
    if (y == 3) return down;
    const glm::vec4 by_pair[4] = {nx, nz, px, pz};  // pairs starting at columns 1, 3, 5, 7
    return by_pair[((x + 7) % 8) / 2];
  });
  // Face size 3: the centre texel looks exactly along the axis.
  const auto cube = cube_map_from_equirect(*equirect, 3, /*float_faces=*/true);
  EXPECT_EQ(cube->face(CubeFace::NegativeZ).fetch(0, 1, 1), nz);
  EXPECT_EQ(cube->face(CubeFace::PositiveZ).fetch(0, 1, 1), pz);
  EXPECT_EQ(cube->face(CubeFace::PositiveX).fetch(0, 1, 1), px);
  EXPECT_EQ(cube->face(CubeFace::NegativeX).fetch(0, 1, 1), nx);
  EXPECT_EQ(cube->face(CubeFace::PositiveY).fetch(0, 1, 1), up);
  EXPECT_EQ(cube->face(CubeFace::NegativeY).fetch(0, 1, 1), down);
}

TEST(CubeMap, GradientSkyIsBlueAboveAndBrownBelow) {
  const auto sky = generate_gradient_sky(16);
  const glm::vec4 zenith = sky->sample({0, 1, 0});
  const glm::vec4 ground = sky->sample({0, -1, 0});
  const glm::vec4 horizon = sky->sample({0, 0, -1});
  EXPECT_GT(zenith.z, zenith.x + 0.4f);   // blue
  EXPECT_GT(ground.x, ground.z + 0.05f);  // warm
  EXPECT_GT(horizon.x, zenith.x + 0.3f);  // pale horizon
  EXPECT_EQ(sky->face(CubeFace::PositiveY).encoding(), TexelEncoding::Srgb8);
  EXPECT_THROW(generate_gradient_sky(0), Error);
}

TEST(CubeMap, LoadNamesTheMissingFile) {
  const auto dir = std::filesystem::temp_directory_path() / "ontile_cube_map_test";
  std::array<std::filesystem::path, kCubeFaceCount> paths;
  for (int f = 0; f < kCubeFaceCount; ++f) paths[f] = dir / ("face" + std::to_string(f) + ".png");
  try {
    load_cube_map(paths);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("face0.png"), std::string::npos) << e.what();
  }
}

TEST(ToonEnvShader, LooksUpWorldOrViewNormals) {
  const CubeMap cube(solid_faces(2));
  ToonEnvParams p;
  p.environment = &cube;
  p.base_color = glm::vec4(0.5f, 1.0f, 1.0f, 0.25f);
  QuadFragment q = test::make_quad(0, 0, 0x1);
  test::set_var3(q, ToonVertexShader::kNormal, 0, {0, 2, 0});       // world: +Y face (2)
  test::set_var3(q, ToonVertexShader::kViewNormal, 0, {0, 0, -3});  // view: -Z face (5)
  QuadOutput out;
  ToonEnvShader<ToonOutput::kColor, false>(p).shade(q, out);
  EXPECT_EQ(out.color[0][0], glm::vec4(1.0f, 0.0f, 0.0f, 0.25f));
  ToonEnvShader<ToonOutput::kColor, true>(p).shade(q, out);
  EXPECT_EQ(out.color[0][0], glm::vec4(2.5f, 0.0f, 0.0f, 0.25f));
}

}  // namespace
}  // namespace ontile
