// The lambert pipeline's options: explicit defaults reproduce the default image bit for bit;
// reversed Z gives the identical image on the demo scene (no surfaces closer than D32F
// resolves, so visibility cannot change); MSAA lowers the error against a supersampled
// reference; the stored normal buffer differs from the float normals by at most its encoding's
// bound; bad values are errors naming key and value.
#include <gtest/gtest.h>

#include <numbers>

#include "analysis/sweep_metrics.h"
#include "aov/aov_pass.h"
#include "pipelines/lambert/lambert_pipeline.h"
#include "pipelines/kit/render_frame.h"
#include "reference/reference_shading.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr int kW = 160, kH = 90;

const Scene& demo() {
  static const Scene scene = load_gltf(std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb");
  return scene;
}

RenderSettings settings_with(const std::vector<std::pair<std::string, std::string>>& options) {
  RenderSettings s;
  s.width_px = kW;
  s.height_px = kH;
  s.context.threads = 2;
  for (const auto& [k, v] : options) s.options.set(k, v);
  return s;
}

std::vector<uint8_t> image(const std::vector<std::pair<std::string, std::string>>& options) {
  return render_frame(demo(), settings_with(options)).outputs.color->bytes();
}

TEST(LambertOptions, ExplicitDefaultsAreTheDefaultImage) {
  EXPECT_EQ(image({}), image({{"msaa", "1"}, {"depth", "d32f"}, {"reversed_z", "off"}, {"normals", "none"},
                              {"filter", "gltf"}}));
}

// Reversed Z changes every depth value but not the order of surfaces that D32F separates in
// both conventions. The demo scene has no surfaces close enough to reorder (its D16 image is
// identical too), so the images must be bit-identical; a scene with near-coplanar surfaces may
// differ exactly at the pixels where standard D32F could not separate them.
TEST(LambertOptions, ReversedZGivesTheSameImageOnTheDemo) {
  const std::vector<uint8_t> standard = image({});
  EXPECT_EQ(image({{"reversed_z", "on"}}), standard);
  EXPECT_EQ(image({{"reversed_z", "on"}, {"depth", "d24"}}), standard);
}

TEST(LambertOptions, MsaaLowersTheErrorAgainstASupersampledReference) {
  const Camera camera = select_camera(demo(), -1);
  const LambertReferenceScene ref_scene = make_lambert_reference_scene(demo(), camera, kW, kH);
  const ReferenceImage reference = render_reference(ref_scene, kW, kH, 16);
  double error[9] = {};
  for (int samples : {1, 2, 4, 8}) {
    const RenderedFrame frame = render_frame(demo(), settings_with({{"msaa", std::to_string(samples)}}));
    error[samples] = color_error(*frame.outputs.color, reference).mean_abs;
  }
  EXPECT_LT(error[2], error[1]);
  EXPECT_LT(error[4], error[2]);
  EXPECT_LT(error[8], error[1]);
}

TEST(LambertOptions, NormalBufferIsTheFloatNormalWithinTheEncodingBound) {
  RenderSettings aov = settings_with({});
  const AovFrame float_normals = render_aov_frame(demo(), aov, {AovKind::Normal, AovKind::PrimitiveId});
  constexpr double kDeg = 180.0 / std::numbers::pi;
  // The analytic bounds of tests/shaders/normal_encoding_test.cpp.
  const std::pair<NormalStorage, double> cases[] = {{NormalStorage::Rgb10a2, std::sqrt(3.0) / 1023.0 * kDeg},
                                                    {NormalStorage::Rgba16f, std::ldexp(1.0, -11) * kDeg},
                                                    {NormalStorage::OctRg16, std::sqrt(18.0) / 65535.0 * kDeg}};
  for (const auto& [storage, bound_deg] : cases) {
    RenderContext context(aov.context);
    FrameInputs in;
    in.scene = &demo();
    in.camera = float_normals.camera;
    in.width_px = kW;
    in.height_px = kH;
    LambertOptions options;
    options.normals = storage;
    options.primitive_id_output = true;
    const LambertFrame frame = render_lambert(context, in, options);
    ASSERT_EQ(frame.normals->format(), normal_storage_format(storage));
    EXPECT_EQ(primitive_id_mismatch(*frame.primitive_ids, *float_normals.surfaces[1]), 0.0);
    const NormalError e = normal_error(*frame.normals, storage, *frame.primitive_ids, *float_normals.surfaces[0],
                                       *float_normals.surfaces[1]);
    EXPECT_GT(e.pixels, uint64_t(kW * kH / 4)) << normal_storage_name(storage);
    EXPECT_LE(e.max_deg, bound_deg) << normal_storage_name(storage);
    // The normal target is stored: its bytes are written once per frame.
    EXPECT_EQ(frame.normals->size_bytes(), uint64_t(kW) * kH * bytes_per_pixel(normal_storage_format(storage)));
  }
}

TEST(LambertOptions, BilinearFilteringChangesTheTexturedImage) {
  EXPECT_NE(image({{"filter", "bilinear"}}), image({{"filter", "trilinear"}}));
}

TEST(LambertOptions, BadValuesAreErrorsNamingKeyAndValue) {
  const std::pair<std::string, std::string> bad[] = {{"msaa", "3"},       {"depth", "d8"},   {"reversed_z", "yes"},
                                                     {"normals", "oct"},  {"filter", "aniso"}};
  for (const auto& [key, value] : bad) {
    try {
      image({{key, value}});
      ADD_FAILURE() << key << "=" << value << " was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(key + "=" + value), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(image({{"msaa", "4"}, {"normals", "rgb10a2"}}), Error);
  EXPECT_THROW(image({{"unknown", "1"}}), Error);
}

}  // namespace
}  // namespace ontile
