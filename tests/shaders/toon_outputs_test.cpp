// ToonOutput masks: slot packing, normal encodings, and the rule that a functor writing colour,
// normal and border at once (MRT) writes bit for bit what three single-output functors write;
// plus the ToonVertexShader varying layout.
#include <gtest/gtest.h>

#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "shaders/toon_test_support.h"
#include "shaders_cpp/toon/cel_shader.h"
#include "shaders_cpp/toon/matcap_generator.h"
#include "shaders_cpp/toon/matcap_shader.h"
#include "shaders_cpp/toon/outline_shader.h"
#include "shaders_cpp/toon/toon_env_shader.h"
#include "shaders_cpp/toon/toon_vertex_shader.h"

namespace ontile {
namespace {

constexpr uint32_t kC = ToonOutput::kColor, kN = ToonOutput::kNormal, kB = ToonOutput::kBorder;

TEST(ToonOutput, SlotsArePackedInBitOrder) {
  static_assert(toon_output_slot(kC | kN | kB, kC) == 0);
  static_assert(toon_output_slot(kC | kN | kB, kN) == 1);
  static_assert(toon_output_slot(kC | kN | kB, kB) == 2);
  static_assert(toon_output_slot(kC | kB, kB) == 1);
  static_assert(toon_output_slot(kN, kN) == 0);
  static_assert(toon_output_slot(kB, kB) == 0);
  static_assert(toon_output_count(kC | kN | kB) == 3);
  static_assert(!is_valid_toon_output_mask(0) && !is_valid_toon_output_mask(8));
  EXPECT_EQ(encode_view_normal({0, -1, 0}, NormalEncoding::Unorm), glm::vec4(0.5f, 0.0f, 0.5f, 1.0f));
  EXPECT_EQ(encode_view_normal({0, -1, 0}, NormalEncoding::Float), glm::vec4(0.0f, -1.0f, 0.0f, 1.0f));
  EXPECT_EQ(decode_view_normal({0.5f, 0.0f, 1.0f, 1.0f}, NormalEncoding::Unorm), glm::vec3(0, -1, 1));
}

// A quad with uneven, deterministic varyings in the ToonVertexShader layout.
QuadFragment varied_quad(uint8_t mask, bool front_facing) {
  QuadFragment q = test::make_quad(4, 6, mask, front_facing);
  for (int i = 0; i < ToonVertexShader::kVaryingCount; ++i) {
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      q.varyings[i][lane] = 0.37f * static_cast<float>((i * 7 + lane * 3) % 11) / 11.0f - 0.13f * lane;
    }
  }
  return q;
}

// Runs the MRT functor and the three single-output functors on the same quad and compares
// every written value bitwise.
template <typename All, typename ColorOnly, typename NormalOnly, typename BorderOnly, typename P>
void expect_mrt_matches_single_outputs(const P& params) {
  const All all(params);
  const ColorOnly color(params);
  const NormalOnly normal(params);
  const BorderOnly border(params);
  for (bool front : {true, false}) {
    const QuadFragment q = varied_quad(0b1011, front);
    QuadOutput mrt, c, n, b;
    all.shade(q, mrt);
    color.shade(q, c);
    normal.shade(q, n);
    border.shade(q, b);
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (!q.lane_active(lane)) continue;
      EXPECT_EQ(std::memcmp(&mrt.color[0][lane], &c.color[0][lane], sizeof(glm::vec4)), 0) << lane;
      EXPECT_EQ(std::memcmp(&mrt.color[1][lane], &n.color[0][lane], sizeof(glm::vec4)), 0) << lane;
      EXPECT_EQ(std::memcmp(&mrt.color[2][lane], &b.color[0][lane], sizeof(glm::vec4)), 0) << lane;
    }
  }
}

TEST(ToonOutput, MatCapMrtIsBitIdenticalToSingleOutputs) {
  const auto matcap = generate_matcap(MatCapStyle::Metal, 32);
  const auto base = test::make_float_texture(4, 4, [](int x, int y) {
    return glm::vec4(0.2f + 0.2f * x, 0.9f - 0.2f * y, 0.5f, 1.0f);
  });
  const auto normals = test::make_float_texture(4, 4, [](int x, int y) {
    return glm::vec4(0.4f + 0.05f * x, 0.6f - 0.05f * y, 0.9f, 1.0f);
  });
  MatCapParams p;
  p.matcap = matcap.get();
  p.base_map = base.get();
  p.normal_map = normals.get();
  p.normal_scale = 0.8f;
  p.world_to_view = glm::mat3(glm::rotate(glm::mat4(1.0f), 0.3f, glm::vec3(0, 1, 0)));
  p.base_color = glm::vec4(0.9f, 0.8f, 0.7f, 0.6f);
  p.outputs = {NormalEncoding::Unorm, glm::vec4(0.1f, 0.2f, 0.3f, 1.0f)};
  expect_mrt_matches_single_outputs<MatCapShader<kC | kN | kB, true, true>, MatCapShader<kC, true, true>,
                                    MatCapShader<kN, true, true>, MatCapShader<kB, true, true>>(p);
  p.outputs.normal_encoding = NormalEncoding::Float;
  expect_mrt_matches_single_outputs<MatCapShader<kC | kN | kB, false, false>, MatCapShader<kC, false, false>,
                                    MatCapShader<kN, false, false>, MatCapShader<kB, false, false>>(p);
}

TEST(ToonOutput, CelEnvAndOutlineMrtAreBitIdenticalToSingleOutputs) {
  CelParams cel;
  cel.to_light = glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f));
  cel.steps = 3;
  cel.outputs.border_color = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
  expect_mrt_matches_single_outputs<CelShader<kC | kN | kB, false>, CelShader<kC, false>,
                                    CelShader<kN, false>, CelShader<kB, false>>(cel);
  const auto sky = generate_gradient_sky(8);
  ToonEnvParams env;
  env.environment = sky.get();
  env.outputs = {NormalEncoding::Float, glm::vec4(0.0f, 0.0f, 0.0f, 0.5f)};
  expect_mrt_matches_single_outputs<ToonEnvShader<kC | kN | kB, true>, ToonEnvShader<kC, true>,
                                    ToonEnvShader<kN, true>, ToonEnvShader<kB, true>>(env);
  expect_mrt_matches_single_outputs<ToonEnvShader<kC | kN | kB, false>, ToonEnvShader<kC, false>,
                                    ToonEnvShader<kN, false>, ToonEnvShader<kB, false>>(env);
  const QuadFragment q = varied_quad(0xF, false);
  QuadOutput mrt;
  OutlineColorShader<kC | kN | kB>(glm::vec4(0.1f, 0.1f, 0.1f, 1.0f), NormalEncoding::Unorm).shade(q, mrt);
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    EXPECT_EQ(mrt.color[0][lane], glm::vec4(0.1f, 0.1f, 0.1f, 1.0f));
    EXPECT_EQ(mrt.color[1][lane], glm::vec4(0.5f, 0.5f, 1.0f, 1.0f));  // (0, 0, 1) encoded
    EXPECT_EQ(mrt.color[2][lane], glm::vec4(0.0f));                     // no border
  }
}

TEST(ToonVertexShader, WritesTheFifteenVaryings) {
  MeshPrimitive prim;
  prim.positions = {{1.0f, 2.0f, 3.0f}};
  prim.normals = {{0.0f, 1.0f, 0.0f}};
  prim.uv0 = {{0.25f, 0.75f}};
  prim.tangents = {{1.0f, 0.0f, 0.0f, 1.0f}};
  prim.indices = {0, 0, 0};
  // World: mirror x and translate; view: rotate 90 degrees about z (x -> y).
  const glm::dmat4 world = glm::translate(glm::dmat4(1.0), glm::dvec3(10, 0, 0)) *
                           glm::scale(glm::dmat4(1.0), glm::dvec3(-1, 1, 1));
  const glm::dmat4 view = glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(0, 0, 1));
  const ToonVertexShader vs(prim, world, view, view);
  ASSERT_EQ(vs.varying_count(), 15);
  EXPECT_EQ(vs.input_vertex_bytes(), 48u);
  glm::vec4 clip;
  float v[15];
  vs.shade(0, 1, &clip, v);
  const auto near3 = [&](int first, glm::vec3 expected) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[first + k], expected[k], 1e-6f) << first + k;
  };
  near3(ToonVertexShader::kNormal, {0, 1, 0});
  EXPECT_EQ(v[ToonVertexShader::kUv], 0.25f);
  EXPECT_EQ(v[ToonVertexShader::kUv + 1], 0.75f);
  near3(ToonVertexShader::kWorldPos, {9, 2, 3});
  near3(ToonVertexShader::kViewNormal, {-1, 0, 0});  // +Y rotated 90 degrees about z
  near3(ToonVertexShader::kTangent, {-1, 0, 0});     // mirrored
  EXPECT_EQ(v[ToonVertexShader::kTangent + 3], -1.0f);  // handedness flips with the mirror

  prim.tangents.clear();
  const ToonVertexShader no_tangents(prim, world, view, view);
  EXPECT_EQ(no_tangents.input_vertex_bytes(), 32u);
  no_tangents.shade(0, 1, &clip, v);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(v[ToonVertexShader::kTangent + k], 0.0f);
}

}  // namespace
}  // namespace ontile
