// Cel shading: the shadow banding formula against a hand-made table, and the functor's mix of
// lit and shadow colours.
#include <gtest/gtest.h>

#include "shaders_cpp/toon/cel_shader.h"
#include "shaders/toon_test_support.h"

namespace ontile {
namespace {

struct CelCase {
  int steps;
  float step_size;
  float n_dot_l;
  float expected;
};

// shadow = 0 when d >= 0, else min(1, ceil(-d / step_size) / steps). By hand:
//   steps 1, size 1:   d = 1, 0, -0 -> 0;  d = -1e-6 -> ceil(1e-6) = 1 -> 1;  -0.5, -1 -> 1
//   steps 3, size 1/3: d = 0.2, 0 -> 0;  -0.1 -> ceil(0.3) = 1 -> 1/3;  -1/3 -> ceil(1) = 1 -> 1/3
//                      -0.34 -> ceil(1.02) = 2 -> 2/3;  -0.5 -> ceil(1.5) = 2 -> 2/3
//                      -0.9 -> ceil(2.7) = 3 -> 1;  -1 -> ceil(3) = 3 -> 1
//   steps 6, size 1/6: d = 0 -> 0;  -0.05 -> ceil(0.3) = 1 -> 1/6;  -1/6 -> ceil(1) = 1 -> 1/6
//                      -0.17 -> ceil(1.02) = 2 -> 2/6;  -0.45 -> ceil(2.7) = 3 -> 3/6
//                      -0.6 -> ceil(3.6) = 4 -> 4/6;  -0.8 -> ceil(4.8) = 5 -> 5/6;  -1 -> 6 -> 1
//   steps 3, size 0.1: d = -0.15 -> ceil(1.5) = 2 -> 2/3;  -0.5 -> ceil(5) = 5 -> 5/3 -> 1
TEST(CelShadowFactor, MatchesHandMadeTable) {
  const float third = 1.0f / 3.0f, sixth = 1.0f / 6.0f;
  const CelCase cases[] = {
      {1, 1.0f, 1.0f, 0.0f},       {1, 1.0f, 0.0f, 0.0f},          {1, 1.0f, -0.0f, 0.0f},
      {1, 1.0f, -1e-6f, 1.0f},     {1, 1.0f, -0.5f, 1.0f},         {1, 1.0f, -1.0f, 1.0f},
      {3, third, 0.2f, 0.0f},      {3, third, 0.0f, 0.0f},         {3, third, -0.1f, 1.0f / 3.0f},
      {3, third, -third, 1.0f / 3.0f}, {3, third, -0.34f, 2.0f / 3.0f}, {3, third, -0.5f, 2.0f / 3.0f},
      {3, third, -0.9f, 1.0f},     {3, third, -1.0f, 1.0f},
      {6, sixth, 0.0f, 0.0f},      {6, sixth, -0.05f, 1.0f / 6.0f}, {6, sixth, -sixth, 1.0f / 6.0f},
      {6, sixth, -0.17f, 2.0f / 6.0f}, {6, sixth, -0.45f, 3.0f / 6.0f}, {6, sixth, -0.6f, 4.0f / 6.0f},
      {6, sixth, -0.8f, 5.0f / 6.0f},  {6, sixth, -1.0f, 1.0f},
      {3, 0.1f, -0.15f, 2.0f / 3.0f},  {3, 0.1f, -0.5f, 1.0f},
  };
  for (const CelCase& c : cases) {
    EXPECT_EQ(cel_shadow_factor(c.n_dot_l, c.steps, c.step_size), c.expected)
        << "steps " << c.steps << " step " << c.step_size << " d " << c.n_dot_l;
  }
}

TEST(CelShader, MixesLitAndShadowColoursByBand) {
  CelParams p;
  p.to_light = glm::vec3(0.0f, 1.0f, 0.0f);
  p.steps = 2;  // step_size defaults to 1/2
  p.lit_color = glm::vec4(1.0f, 0.5f, 0.25f, 1.0f);
  p.shadow_color = glm::vec4(0.0f, 0.0f, 0.5f, 0.5f);
  const CelShader<ToonOutput::kColor, false> shader(p);
  QuadFragment q = test::make_quad(0, 0, 0xF);
  test::set_var3(q, ToonVertexShader::kNormal, 0, {0.0f, 2.0f, 0.0f});    // d = 1: lit
  test::set_var3(q, ToonVertexShader::kNormal, 1, {0.0f, -1.0f, 0.0f});   // d = -1: shadow 1
  test::set_var3(q, ToonVertexShader::kNormal, 2, {0.0f, -0.25f, 1.0f});  // d = -0.24: 1/2
  test::set_var3(q, ToonVertexShader::kNormal, 3, {1.0f, 0.0f, 0.0f});    // d = 0: lit
  QuadOutput out;
  shader.shade(q, out);
  EXPECT_EQ(out.color[0][0], p.lit_color);
  EXPECT_EQ(out.color[0][1], p.shadow_color);
  EXPECT_EQ(out.color[0][2], glm::mix(p.lit_color, p.shadow_color, 0.5f));
  EXPECT_EQ(out.color[0][3], p.lit_color);

  // Back faces flip the normal: lane 1's (0,-1,0) faces the light.
  QuadFragment back = q;
  back.front_facing = false;
  shader.shade(back, out);
  EXPECT_EQ(out.color[0][1], p.lit_color);
}

TEST(CelShader, TexturesMultiplyTheirColours) {
  const auto lit_map = test::make_float_texture(1, 1, [](int, int) { return glm::vec4(0.5f); });
  CelParams p;
  p.steps = 1;
  p.lit_color = glm::vec4(1.0f, 0.5f, 0.25f, 1.0f);
  p.lit_map = lit_map.get();  // shadow_map left null: the shadow colour stays constant
  const CelShader<ToonOutput::kColor, true> shader(p);
  QuadFragment q = test::make_quad(0, 0, 0x3);
  test::set_var3(q, ToonVertexShader::kNormal, 0, {0.0f, 1.0f, 0.0f});
  test::set_var3(q, ToonVertexShader::kNormal, 1, {0.0f, -1.0f, 0.0f});
  QuadOutput out;
  shader.shade(q, out);
  EXPECT_EQ(out.color[0][0], p.lit_color * 0.5f);
  EXPECT_EQ(out.color[0][1], p.shadow_color);
}

TEST(CelShader, RejectsZeroSteps) {
  CelParams p;
  p.steps = 0;
  EXPECT_THROW((CelShader<ToonOutput::kColor, false>(p)), Error);
}

}  // namespace
}  // namespace ontile
