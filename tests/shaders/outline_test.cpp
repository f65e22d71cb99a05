// Inverted-hull outlines: object-space offsets are exact; screen-space offsets move the projected
// vertex by thickness_px pixels at any depth; the functor writes the outline colour.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "context/camera_matrices.h"
#include "shaders_cpp/toon/outline_shader.h"
#include "util/error.h"

namespace ontile {
namespace {

TEST(OutlineVertexShader, ObjectSpacePushesAlongTheUnitNormal) {
  MeshPrimitive prim;
  prim.positions = {{1.0f, 2.0f, 3.0f}, {-1.0f, 0.5f, 0.0f}};
  prim.normals = {{0.0f, 2.0f, 0.0f}, {-3.0f, 0.0f, 4.0f}};  // lengths 2 and 5
  OutlineParams params;
  params.mode = OutlineMode::ObjectSpace;
  params.thickness_object_units = 0.25f;
  const OutlineVertexShader vs(prim, glm::dmat4(1.0), glm::dmat4(1.0), params);
  EXPECT_EQ(vs.varying_count(), 0);
  glm::vec4 clip[2];
  vs.shade(0, 2, clip, nullptr);
  EXPECT_EQ(clip[0], glm::vec4(1.0f, 2.25f, 3.0f, 1.0f));
  EXPECT_EQ(clip[1], glm::vec4(-1.15f, 0.5f, 0.2f, 1.0f));

  // Through a scaled world and a projection: the offset happens before both.
  const glm::dmat4 world = glm::scale(glm::translate(glm::dmat4(1.0), {0, 0, -5}), {2, 2, 2});
  const glm::dmat4 proj = glm::perspectiveRH_ZO(0.8, 1.5, 0.1, 100.0);
  const OutlineVertexShader vs2(prim, world, proj, params);
  vs2.shade(0, 2, clip, nullptr);
  const glm::dvec4 expected = proj * world * glm::dvec4(1.0, 2.25, 3.0, 1.0);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(clip[0][k], expected[k], 1e-5 * std::abs(expected[k]) + 1e-6);
}

glm::dvec2 to_pixels(glm::vec4 clip, int width, int height) {
  return {(static_cast<double>(clip.x) / clip.w * 0.5 + 0.5) * width,
          (0.5 - static_cast<double>(clip.y) / clip.w * 0.5) * height};
}

TEST(OutlineVertexShader, ScreenSpaceOffsetIsThicknessPixelsAtEveryDepth) {
  constexpr int kWidth = 640, kHeight = 480;
  Camera camera;  // at the origin, looking down -Z
  camera.znear = 0.1f;
  camera.zfar = 100.0f;
  const CameraMatrices m = camera_matrices(camera, static_cast<double>(kWidth) / kHeight);
  MeshPrimitive prim;
  // Two depths (2 and 40 units away), several normal directions, including one towards the camera.
  for (float z : {-2.0f, -40.0f}) {
    for (glm::vec3 n : {glm::vec3(1, 0, 0), glm::vec3(0.6f, 0.8f, 0), glm::vec3(0.3f, -0.5f, 0.81f),
                        glm::vec3(-0.2f, 0.1f, -0.9f)}) {
      prim.positions.push_back(glm::vec3(0.1f, -0.05f, 0.0f) * (-z * 0.5f) + glm::vec3(0, 0, z));
      prim.normals.push_back(n);
    }
  }
  const glm::dmat4 world = glm::translate(glm::dmat4(1.0), {0.05, 0.0, 0.0});
  OutlineParams params;
  params.mode = OutlineMode::ScreenSpace;
  params.viewport_width_px = kWidth;
  params.viewport_height_px = kHeight;
  params.thickness_px = 0.0f;
  const OutlineVertexShader base(prim, world, m.view_projection, params);
  params.thickness_px = 3.0f;
  const OutlineVertexShader pushed(prim, world, m.view_projection, params);
  const uint32_t count = static_cast<uint32_t>(prim.positions.size());
  std::vector<glm::vec4> c0(count), c1(count);
  base.shade(0, count, c0.data(), nullptr);
  pushed.shade(0, count, c1.data(), nullptr);
  for (uint32_t i = 0; i < count; ++i) {
    const glm::dvec2 offset = to_pixels(c1[i], kWidth, kHeight) - to_pixels(c0[i], kWidth, kHeight);
    EXPECT_NEAR(glm::length(offset), 3.0, 1e-4) << i;
    EXPECT_EQ(c1[i].z, c0[i].z) << i;  // depth unchanged
    EXPECT_EQ(c1[i].w, c0[i].w) << i;
    // The direction is where the surface point moves on screen when pushed along its normal.
    const glm::dvec3 p = glm::dvec3(world * glm::dvec4(prim.positions[i], 1.0));
    const glm::dvec3 n = glm::normalize(glm::dvec3(prim.normals[i]));
    const auto project = [&](glm::dvec3 q) {
      const glm::dvec4 c = m.view_projection * glm::dvec4(q, 1.0);
      return glm::dvec2((c.x / c.w * 0.5 + 0.5) * kWidth, (0.5 - c.y / c.w * 0.5) * kHeight);
    };
    const glm::dvec2 moved = project(p + n * 1e-4) - project(p);
    EXPECT_GT(glm::dot(glm::normalize(moved), offset / 3.0), 0.9999) << i;
  }
}

TEST(OutlineVertexShader, ScreenSpaceLeavesCameraFacingCentreVerticesAndNeedsAViewport) {
  MeshPrimitive prim;
  prim.positions = {{0.0f, 0.0f, -5.0f}};
  prim.normals = {{0.0f, 0.0f, 1.0f}};
  OutlineParams params;
  params.viewport_width_px = 64;
  params.viewport_height_px = 64;
  const glm::dmat4 proj = glm::perspectiveRH_ZO(0.8, 1.0, 0.1, 100.0);
  const OutlineVertexShader vs(prim, glm::dmat4(1.0), proj, params);
  glm::vec4 clip;
  vs.shade(0, 1, &clip, nullptr);
  EXPECT_EQ(clip, glm::vec4(glm::mat4(proj) * glm::vec4(0.0f, 0.0f, -5.0f, 1.0f)));
  params.viewport_width_px = 0;
  EXPECT_THROW(OutlineVertexShader(prim, glm::dmat4(1.0), proj, params), Error);
}

}  // namespace
}  // namespace ontile
