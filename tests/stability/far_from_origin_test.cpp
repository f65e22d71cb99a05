// Far from the origin: a mesh 1e5 and 1e6 units away, camera beside it, covers exactly the
// pixels it covers at the origin (MeshVertexShader folds world, view and projection in double);
// world-position varyings stay within a few float ulps of their magnitude.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "context/render_context.h"
#include "shaders_cpp/mesh_vertex_shader.h"
#include "support/closed_meshes.h"
#include "support/face_count_harness.h"

namespace ontile::test {
namespace {

constexpr int kW = 96, kH = 80;

MeshPrimitive sphere_primitive() {
  const ClosedMesh sphere = uv_sphere(24, 48);
  MeshPrimitive m;
  for (const glm::dvec3& p : sphere.positions) {
    m.positions.push_back(glm::vec3(p));
    m.normals.push_back(glm::vec3(p));
    m.bounds.extend(glm::vec3(p));
  }
  m.indices = sphere.indices;
  return m;
}

// What a float-only pipeline does: world transform in float, then view-projection in float.
class FloatWorldThenViewShader final : public VertexShader {
 public:
  FloatWorldThenViewShader(const MeshPrimitive& mesh, const glm::dmat4& world, const glm::dmat4& vp)
      : mesh_(mesh), world_(world), view_projection_(vp) {}
  int varying_count() const override { return 0; }
  void shade(uint32_t first, uint32_t count, glm::vec4* clip, float*) const override {
    for (uint32_t i = 0; i < count; ++i) clip[i] = view_projection_ * (world_ * glm::vec4(mesh_.positions[first + i], 1.0f));
  }

 private:
  const MeshPrimitive& mesh_;
  glm::mat4 world_, view_projection_;
};

class WorldPositionShader final : public FragmentShader {
 public:
  void shade(const QuadFragment& q, QuadOutput& out) const override {
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      out.color[0][lane] = glm::vec4(q.var3(MeshVertexShader::kWorldPos, lane), 1.0f);
    }
  }
};

struct Probe {
  Shader shader{"Probe"};
  RenderMaterial material{"probe", &shader};
  Probe() {
    PassState counting;
    counting.cull = CullMode::None;
    counting.depth_test = counting.depth_write = false;
    counting.blend.mode = BlendMode::Additive;
    shader.add_pass({"Count", "", counting, [](const DrawContext& c) {
                       DrawFunctors f;
                       f.vertex = std::make_unique<MeshVertexShader>(*c.mesh, c.world, c.camera.view_projection);
                       f.fragment = std::make_unique<FaceCountShader>();
                       return f;
                     }});
    shader.add_pass({"CountFloatOnly", "", counting, [](const DrawContext& c) {
                       DrawFunctors f;
                       f.vertex = std::make_unique<FloatWorldThenViewShader>(*c.mesh, c.world, c.camera.view_projection);
                       f.fragment = std::make_unique<FaceCountShader>();
                       return f;
                     }});
    shader.add_pass({"WorldPosition", "", PassState{}, [](const DrawContext& c) {
                       DrawFunctors f;
                       f.vertex = std::make_unique<MeshVertexShader>(*c.mesh, c.world, c.camera.view_projection);
                       f.fragment = std::make_unique<WorldPositionShader>();
                       return f;
                     }});
  }
};

// Renders the sphere placed at `offset` (rotated, scaled by 1.3) with the camera at
// offset + (0.4, 0.3, 3.1) looking at it; returns the RGBA32F image.
std::vector<glm::vec4> render(const glm::dvec3& offset, const std::string& pass) {
  static const MeshPrimitive mesh = sphere_primitive();
  Probe probe;
  RenderContext ctx(ContextConfig{2, {}});
  Surface* color = ctx.create_surface("c", PixelFormat::RGBA32_FLOAT, kW, kH);
  Surface* depth = ctx.create_surface("z", PixelFormat::D32_FLOAT, kW, kH);
  ctx.set_render_target({{RenderTargetRef::of(color), LoadAction::Clear, StoreAction::Store}},
                        TargetBinding{RenderTargetRef::of(depth), LoadAction::Clear, StoreAction::DontCare});
  ctx.clear_render_target(true, true, glm::vec4(0.0f), 1.0f);
  const glm::dvec3 eye = offset + glm::dvec3(0.4, 0.3, 3.1);
  const glm::dmat4 view = glm::lookAt(eye, offset, glm::dvec3(0.0, 1.0, 0.0));
  const glm::dmat4 projection = glm::perspectiveRH_ZO(0.9, double(kW) / kH, 0.1, 100.0);
  ctx.set_view_projection(view, projection);
  const glm::dmat4 world = glm::scale(glm::rotate(glm::translate(glm::dmat4(1.0), offset), 0.7,
                                                  glm::dvec3(0.2, 1.0, 0.4)),
                                      glm::dvec3(1.3));
  ctx.draw_mesh(mesh, world, &probe.material, pass);
  ctx.submit();
  std::vector<glm::vec4> image;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) image.push_back(color->read(x, y));
  return image;
}

const glm::dvec3 kDirection(0.6, -0.48, 0.64);  // unit length

TEST(FarFromOrigin, CoverageIsIdenticalAt1e5And1e6Units) {
  const std::vector<glm::vec4> at_origin = render(glm::dvec3(0.0), "Count");
  int covered = 0;
  for (const glm::vec4& v : at_origin) {
    ASSERT_EQ(v.x, v.y) << "closed sphere: front and back coverage agree";
    covered += v.x == 1.0f;
  }
  EXPECT_GT(covered, kW * kH / 5);
  for (double distance : {1e5, 1e6}) {
    EXPECT_TRUE(render(distance * kDirection, "Count") == at_origin) << distance << " units away";
  }
  // The comparison is sensitive: a float-only transform at 1e6 units (vertex positions
  // quantised to 1/16 unit) changes the coverage.
  EXPECT_TRUE(render(glm::dvec3(0.0), "CountFloatOnly") == at_origin);
  EXPECT_FALSE(render(1e6 * kDirection, "CountFloatOnly") == at_origin);
}

// World-position varyings are floats: at 1e6 units their spacing is 0.0625. Each is the sum of
// three float products of perspective weights and vertex values, so the error is a few ulps of
// the magnitude; this pins that bound (it does not get worse than a float allows).
TEST(FarFromOrigin, WorldPositionVaryingsAreWithinFourUlpsOfTheirMagnitude) {
  const std::vector<glm::vec4> at_origin = render(glm::dvec3(0.0), "WorldPosition");
  for (double distance : {1e5, 1e6}) {
    const glm::dvec3 offset = distance * kDirection;
    const std::vector<glm::vec4> far = render(offset, "WorldPosition");
    double worst_ulps = 0.0;
    int compared = 0;
    for (size_t i = 0; i < far.size(); ++i) {
      ASSERT_EQ(far[i].w, at_origin[i].w) << "pixel " << i << ": coverage differs";
      if (far[i].w == 0.0f) continue;
      ++compared;
      for (int c = 0; c < 3; ++c) {
        const float magnitude = static_cast<float>(std::abs(offset[c]));
        const double ulp = std::nextafter(magnitude, 2.0f * magnitude) - magnitude;
        const double error = std::abs(double(far[i][c]) - offset[c] - double(at_origin[i][c]));
        worst_ulps = std::max(worst_ulps, error / ulp);
      }
    }
    EXPECT_GT(compared, kW * kH / 5);
    EXPECT_LE(worst_ulps, 4.0) << distance << " units away";
    RecordProperty("worst_ulps_at_" + std::to_string(static_cast<int>(distance)), std::to_string(worst_ulps));
  }
}

}  // namespace
}  // namespace ontile::test
