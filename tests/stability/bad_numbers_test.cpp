// NaN/Inf in positions, normals and UVs through MeshVertexShader and the Lit shader: bad clip
// positions drop their triangle (triangles_non_finite), bad varyings become 0
// (varyings_sanitized); the rest of the image is bit-identical and no NaN is written.
#include <gtest/gtest.h>

#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "pipelines/lit/lit_shader.h"
#include "shaders_cpp/mesh_vertex_shader.h"
#include "support/raster_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 64, kH = 48;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A 6 x 6 grid facing the camera, with normals and UVs, plus `extra` triangles that each have
// their own three vertices (so dropping one cannot affect the grid).
MeshPrimitive grid_with_extra_triangles(int extra) {
  MeshPrimitive m;
  const int n = 6;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      m.positions.push_back({-1.0f + 2.0f * i / n, -1.0f + 2.0f * j / n, 0.1f * float((i * j) % 3)});
      m.normals.push_back(glm::normalize(glm::vec3(0.2f * i - 0.6f, 0.1f * j - 0.3f, 1.0f)));
      m.uv0.push_back({float(i) / n, float(j) / n});
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  }
  for (int t = 0; t < extra; ++t) {
    const float x = -0.8f + 0.35f * t;
    const uint32_t base = static_cast<uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), {{x, -0.5f, 0.3f}, {x + 0.3f, -0.4f, 0.3f}, {x + 0.1f, 0.6f, 0.3f}});
    for (int k = 0; k < 3; ++k) {
      m.normals.push_back({0.0f, 0.0f, 1.0f});
      m.uv0.push_back({0.25f, 0.75f});
    }
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
  }
  for (const glm::vec3& p : m.positions) m.bounds.extend(p);
  return m;
}

// Writes the raw normal and UV varyings (after sanitising) to two RGBA32F targets.
class AttributeShader final : public FragmentShader {
 public:
  void shade(const QuadFragment& q, QuadOutput& out) const override {
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      out.color[0][lane] = glm::vec4(q.var3(MeshVertexShader::kNormal, lane), 1.0f);
      out.color[1][lane] = glm::vec4(q.var2(MeshVertexShader::kUv, lane), 0.0f, 1.0f);
    }
  }
};

struct Frame {
  std::vector<uint8_t> lit_bytes, normal_bytes, uv_bytes;  // RGBA16F, RGBA32F, RGBA32F
  GeometryCounters lit, attributes;
};

Frame render(const MeshPrimitive& mesh) {
  const auto lit_shader = make_lit_shader();
  const auto lit_material = make_lit_material(*lit_shader, Material{});
  Shader probe("Attributes");
  PassState state;
  state.cull = CullMode::None;
  probe.add_pass({"Attributes", "", state, [](const DrawContext& c) {
                    DrawFunctors f;
                    f.vertex = std::make_unique<MeshVertexShader>(*c.mesh, c.world, c.camera.view_projection);
                    f.fragment = std::make_unique<AttributeShader>();
                    return f;
                  }});
  RenderMaterial probe_material("attributes", &probe);

  RenderContext ctx(ContextConfig{2, {}});
  Surface* lit = ctx.create_surface("lit", PixelFormat::RGBA16_FLOAT, kW, kH);
  Surface* normals = ctx.create_surface("n", PixelFormat::RGBA32_FLOAT, kW, kH);
  Surface* uvs = ctx.create_surface("uv", PixelFormat::RGBA32_FLOAT, kW, kH);
  Surface* depth = ctx.create_surface("z", PixelFormat::D32_FLOAT, kW, kH);
  const glm::dmat4 view = glm::lookAt(glm::dvec3(0.3, 0.2, 3.0), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
  const glm::dmat4 world = glm::rotate(glm::dmat4(1.0), 0.4, glm::dvec3(0.3, 1.0, 0.1));
  ctx.set_view_projection(view, glm::perspectiveRH_ZO(0.9, double(kW) / kH, 0.1, 50.0));
  set_lighting_globals(ctx, DirectionalLighting{});
  const TargetBinding z{RenderTargetRef::of(depth), LoadAction::Clear, StoreAction::DontCare};
  ctx.set_render_target({{RenderTargetRef::of(lit), LoadAction::Clear, StoreAction::Store}}, z);
  ctx.clear_render_target(true, true, glm::vec4(0.0f), 1.0f);
  ctx.draw_mesh(mesh, world, lit_material.get(), lit::kForwardLit);
  ctx.set_render_target({{RenderTargetRef::of(normals), LoadAction::Clear, StoreAction::Store},
                         {RenderTargetRef::of(uvs), LoadAction::Clear, StoreAction::Store}}, z);
  ctx.clear_render_target(true, true, glm::vec4(0.0f), 1.0f);
  ctx.draw_mesh(mesh, world, &probe_material, "Attributes");
  const FrameReport report = ctx.submit();
  Frame f;
  f.lit_bytes = lit->bytes();
  f.normal_bytes = normals->bytes();
  f.uv_bytes = uvs->bytes();
  f.lit = report.passes.at(0).geometry;
  f.attributes = report.passes.at(1).geometry;
  return f;
}

int count_nan(const std::vector<uint8_t>& bytes, PixelFormat format) {
  int nan = 0;
  for (size_t i = 0; i < bytes.size(); i += bytes_per_pixel(format)) {
    const glm::vec4 v = decode_pixel(format, bytes.data() + i);
    for (int c = 0; c < 4; ++c) nan += std::isnan(v[c]);
  }
  return nan;
}

TEST(BadNumbers, NonFinitePositionsDropOnlyTheirTriangleAndAreCounted) {
  const MeshPrimitive clean = grid_with_extra_triangles(0);
  const Frame reference = render(clean);
  MeshPrimitive bad = grid_with_extra_triangles(5);
  const size_t first_extra = clean.positions.size();
  // One bad component per triangle: NaN, +Inf, -Inf in x, y or z; and a vertex so large that
  // the clip position overflows to Inf.
  bad.positions[first_extra + 0].x = kNaN;
  bad.positions[first_extra + 4].y = kInf;
  bad.positions[first_extra + 8].z = -kInf;
  bad.positions[first_extra + 9] = glm::vec3(kNaN);
  bad.positions[first_extra + 13].x = 3e38f;
  const Frame f = render(bad);
  EXPECT_EQ(f.lit.triangles_non_finite, 5u);
  EXPECT_EQ(f.attributes.triangles_non_finite, 5u);
  EXPECT_EQ(f.lit.triangles_submitted, clean.triangle_count() + 5u);
  EXPECT_TRUE(f.lit_bytes == reference.lit_bytes);
  EXPECT_TRUE(f.normal_bytes == reference.normal_bytes);
  EXPECT_TRUE(f.uv_bytes == reference.uv_bytes);
  EXPECT_EQ(count_nan(f.lit_bytes, PixelFormat::RGBA16_FLOAT), 0);
}

// A non-finite normal becomes non-finite in all three world components (the normal matrix
// mixes them) and each is replaced by 0; a non-finite UV component is replaced by 0. The image
// is bit-identical to the same mesh with those attributes set to zero, and holds no NaN.
TEST(BadNumbers, NonFiniteNormalsAndUvsAreSanitisedToZeroAndCounted) {
  MeshPrimitive bad = grid_with_extra_triangles(3);
  MeshPrimitive zeroed = bad;
  const size_t first_extra = grid_with_extra_triangles(0).positions.size();
  for (int k = 0; k < 3; ++k) {
    bad.normals[first_extra + k] = glm::vec3(k == 0 ? kNaN : 0.0f, k == 1 ? kInf : 0.0f, k == 2 ? -kInf : 1.0f);
    zeroed.normals[first_extra + k] = glm::vec3(0.0f);
    bad.uv0[first_extra + 3 + k] = glm::vec2(k == 0 ? kNaN : 0.5f, k == 2 ? kInf : 0.5f);
    zeroed.uv0[first_extra + 3 + k] = glm::vec2(k == 0 ? 0.0f : 0.5f, k == 2 ? 0.0f : 0.5f);
  }
  bad.uv0[first_extra + 6] = glm::vec2(-kInf, kNaN);
  zeroed.uv0[first_extra + 6] = glm::vec2(0.0f);
  const Frame f = render(bad), expected = render(zeroed);
  // 3 normals x 3 components + UV components: 1 + 0 + 1 + 2.
  EXPECT_EQ(f.lit.varyings_sanitized, 13u);
  EXPECT_EQ(f.attributes.varyings_sanitized, 13u);
  EXPECT_EQ(expected.lit.varyings_sanitized, 0u);
  EXPECT_EQ(f.lit.triangles_non_finite, 0u);
  EXPECT_TRUE(f.lit_bytes == expected.lit_bytes);
  EXPECT_TRUE(f.normal_bytes == expected.normal_bytes);
  EXPECT_TRUE(f.uv_bytes == expected.uv_bytes);
  EXPECT_EQ(count_nan(f.lit_bytes, PixelFormat::RGBA16_FLOAT), 0);
  EXPECT_EQ(count_nan(f.normal_bytes, PixelFormat::RGBA32_FLOAT), 0);
  EXPECT_EQ(count_nan(f.uv_bytes, PixelFormat::RGBA32_FLOAT), 0);
  // The sanitised triangles are drawn: the image differs from the mesh without them.
  EXPECT_FALSE(f.normal_bytes == render(grid_with_extra_triangles(0)).normal_bytes);
}

}  // namespace
}  // namespace ontile::test
