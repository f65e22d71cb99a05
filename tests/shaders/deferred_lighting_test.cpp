// Building blocks of the forward and deferred lighting: the GGX BRDF's limits, punctual-light
// range cut-off, G-buffer encode/decode through each preset's real formats, the generated
// lights and the screen-space light grid.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "context/camera_matrices.h"
#include "pipelines/deferred/scene_lighting_setup.h"
#include "shaders_cpp/deferred/gbuffer_layout.h"
#include "util/error.h"

namespace ontile {
namespace {

TEST(DeferredLighting, LambertLimitOfTheBrdf) {
  // A rough dielectric lit head-on: diffuse = albedo x radiance, plus the specular lobe,
  // which for alpha = 1 is F0 x D x V x pi = 0.04 x (1/pi) x (1/4) x pi = 0.01 exactly.
  BrdfInputs b = metallic_roughness_brdf(glm::vec3(0.5f), 0.0f, 1.0f);
  const glm::vec3 n(0, 0, 1);
  const glm::vec3 c = shade_ggx(b, n, n, n, glm::vec3(1.0f));
  EXPECT_NEAR(c.x, 0.5f + 0.01f, 1e-6f);
  // Light from behind the surface contributes nothing; a metal has no diffuse term.
  EXPECT_EQ(shade_ggx(b, n, n, -n, glm::vec3(1.0f)), glm::vec3(0.0f));
  b = metallic_roughness_brdf(glm::vec3(0.5f), 1.0f, 1.0f);
  EXPECT_EQ(b.diffuse_color, glm::vec3(0.0f));
  EXPECT_EQ(b.f0, glm::vec3(0.5f));
}

TEST(DeferredLighting, PointLightStopsAtItsRange) {
  PunctualLight l;
  l.position = glm::vec3(0.0f);
  l.intensity = glm::vec3(4.0f);
  l.range = 2.0f;
  glm::vec3 to_light, radiance;
  ASSERT_TRUE(light_incidence(l, glm::vec3(1, 0, 0), to_light, radiance));
  EXPECT_EQ(to_light, glm::vec3(-1, 0, 0));
  EXPECT_FLOAT_EQ(radiance.x, 4.0f * (1.0f - 1.0f / 16.0f));  // (1 - (d/r)^4) / d^2
  EXPECT_FALSE(light_incidence(l, glm::vec3(2, 0, 0), to_light, radiance));
  EXPECT_FALSE(light_incidence(l, glm::vec3(0, 3, 0), to_light, radiance));
}

TEST(DeferredLighting, GBufferRoundTripThroughTheStoredFormats) {
  for (const std::string& name : gbuffer_layout_names()) {
    const GBufferLayout layout = gbuffer_layout(name);
    const std::vector<PixelFormat> formats = layout.target_formats();
    const GBufferSurface s{glm::vec3(0.8f, 0.4f, 0.2f), 1.0f, 0.6f, glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f))};
    glm::vec4 targets[3];
    encode_gbuffer(layout, s, targets);
    for (int k = 0; k < layout.target_count(); ++k) targets[k] = quantize_pixel(formats[k], targets[k]);
    const DecodedGBuffer d = decode_gbuffer(layout, targets);
    const BrdfInputs expected = metallic_roughness_brdf(s.base_color, s.metallic, s.roughness);
    const float normal_error = glm::length(d.normal - s.normal);
    // RGB10A2 keeps 10 bits per component (error < 2^-9 after renormalising), 8-bit values
    // are within half a step, half floats within 2^-11 relative. Roughness sits in the albedo
    // target's alpha: 8 bits, or 2 in bjorge's RGB10A2 albedo (half a step of 1/3).
    EXPECT_LT(normal_error, 2e-3f) << name;
    const float roughness_step = layout.albedo_format == PixelFormat::RGB10A2_UNORM ? 1.0f / 3.0f : 1.0f / 255.0f;
    EXPECT_NEAR(d.brdf.roughness, s.roughness, 0.5f * roughness_step + 1e-6f) << name;
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(d.brdf.f0[c], expected.f0[c], 0.5f / 255.0f + 1e-6f) << name;
      EXPECT_NEAR(d.brdf.diffuse_color[c], expected.diffuse_color[c], 0.5f / 255.0f + 1e-6f) << name;
    }
  }
  EXPECT_EQ(gbuffer_layout("vulkan-samples").color_bits_per_px(), 96);
  EXPECT_EQ(gbuffer_layout("unity").color_bits_per_px(), 160);
  EXPECT_EQ(gbuffer_layout("vulkan-samples-large").color_bits_per_px(), 160);
  EXPECT_EQ(gbuffer_layout("bjorge").color_bits_per_px(), 96);
  EXPECT_THROW(gbuffer_layout("gbuffer9000"), Error);
}

TEST(DeferredLighting, GeneratedLightsAreDeterministicAndInsideTheScene) {
  Bounds b;
  b.extend(glm::vec3(-10, 0, -20));
  b.extend(glm::vec3(10, 8, 20));
  const auto a = generate_point_lights(b, 64);
  const auto c = generate_point_lights(b, 64);
  ASSERT_EQ(a.size(), 64u);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].position, c[i].position);
    EXPECT_EQ(a[i].intensity, c[i].intensity);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(a[i].position[k], b.min[k]);
      EXPECT_LE(a[i].position[k], b.max[k]);
    }
    EXPECT_FLOAT_EQ(a[i].range, 0.6f * glm::length(b.max - b.min) / 4.0f);  // cbrt(64) = 4
  }
  EXPECT_TRUE(generate_point_lights(b, 0).empty());
}

TEST(DeferredLighting, LightGridListsALightOnlyInTheCellsItsRangeReaches) {
  Camera camera;  // at the origin looking down -Z
  camera.yfov_rad = 1.0f;
  camera.znear = 0.1f;
  camera.zfar = 100.0f;
  const int w = 320, h = 160;
  const CameraMatrices m = camera_matrices(camera, double(w) / h);
  PunctualLight centre;
  centre.position = glm::vec3(0, 0, -10);
  centre.range = 1.0f;
  PunctualLight behind = centre;
  behind.position = glm::vec3(0, 0, 10);  // outside the frustum
  PunctualLight around = centre;
  around.position = glm::vec3(0, 0, 0.5f);  // the camera is inside its range
  PunctualLight sun;
  sun.type = PunctualLight::Type::Directional;
  const LightGrid grid = build_light_grid({centre, behind, around, sun}, m, w, h);
  ASSERT_EQ(grid.cells_x, 20);
  ASSERT_EQ(grid.cells_y, 10);
  int cells_with_centre = 0;
  for (int cy = 0; cy < grid.cells_y; ++cy) {
    for (int cx = 0; cx < grid.cells_x; ++cx) {
      const auto list = grid.lights_at(cx * 16, cy * 16);
      std::vector<uint32_t> v(list.begin(), list.end());
      EXPECT_TRUE(std::is_sorted(v.begin(), v.end()));
      EXPECT_EQ(std::count(v.begin(), v.end(), 1u), 0) << "a light behind the camera is culled";
      EXPECT_EQ(std::count(v.begin(), v.end(), 2u), 1) << "a light around the camera covers the screen";
      EXPECT_EQ(std::count(v.begin(), v.end(), 3u), 1) << "directional lights cover the screen";
      cells_with_centre += static_cast<int>(std::count(v.begin(), v.end(), 0u));
    }
  }
  // The range-1 sphere at distance 10 projects to about +-0.1 / tan(0.5) of the half height
  // (~15 px of 80): a small block of cells around the centre, always including the centre.
  EXPECT_GE(cells_with_centre, 4);
  EXPECT_LE(cells_with_centre, 16);
  const auto at_centre = grid.lights_at(w / 2, h / 2);
  EXPECT_EQ(std::count(at_centre.begin(), at_centre.end(), 0u), 1);
  const auto at_corner = grid.lights_at(0, 0);
  EXPECT_EQ(std::count(at_corner.begin(), at_corner.end(), 0u), 0);
}

}  // namespace
}  // namespace ontile
