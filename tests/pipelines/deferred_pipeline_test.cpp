// The deferred pipelines and their forward baseline: classic and subpass images bit-identical
// for every preset and light count, attachment traffic equal to the analytic per-pixel formula
// on a scene covering every pixel, transient attachments free, the over-budget G-buffer
// halving the tile, and MSAA resolved on tile vs by a separate pass.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pipelines/kit/render_frame.h"
#include "support/wall_scene.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile {
namespace {

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

RenderedFrame render(const Scene& scene, const std::string& pipeline, int w, int h,
                     std::vector<std::pair<std::string, std::string>> options = {}) {
  RenderSettings s;
  s.pipeline = pipeline;
  s.width_px = w;
  s.height_px = h;
  s.context.threads = 2;
  for (const auto& [key, value] : options) s.options.set(key, value);
  return render_frame(scene, s);
}

const AttachmentTraffic& attachment(const FrameReport& report, const std::string& pass, const std::string& name) {
  for (const PassReport& p : report.passes) {
    if (p.name != pass) continue;
    for (const AttachmentTraffic& a : p.attachments) {
      if (a.name == name) return a;
    }
  }
  throw Error("no attachment '" + name + "' in pass '" + pass + "'");
}

const PassReport& pass_named(const FrameReport& report, const std::string& name) {
  for (const PassReport& p : report.passes) {
    if (p.name == name) return p;
  }
  throw Error("no pass '" + name + "'");
}

TEST(DeferredPipelines, ClassicAndSubpassImagesAreBitIdentical) {
  const Scene scene = load_gltf(kDemo);
  for (const std::string preset : {"vulkan-samples", "unity", "vulkan-samples-large", "bjorge"}) {
    for (const std::string lights : {"0", "1", "64"}) {
      const RenderedFrame classic = render(scene, "deferred-classic", 200, 112, {{"gbuffer", preset}, {"lights", lights}});
      const RenderedFrame subpass = render(scene, "deferred-subpass", 200, 112, {{"gbuffer", preset}, {"lights", lights}});
      const RenderedFrame passes = render(scene, "deferred-subpass", 200, 112,
                                          {{"gbuffer", preset}, {"lights", lights}, {"technique", "render-passes"}});
      ASSERT_EQ(classic.outputs.color->bytes(), subpass.outputs.color->bytes()) << preset << ", " << lights << " lights";
      ASSERT_EQ(passes.outputs.color->bytes(), subpass.outputs.color->bytes()) << preset << ", " << lights << " lights";
    }
  }
}

TEST(DeferredPipelines, LightsChangeTheImageAndTransientOffDoesNot) {
  const Scene scene = load_gltf(kDemo);
  const RenderedFrame none = render(scene, "deferred-subpass", 160, 96);
  const RenderedFrame lit = render(scene, "deferred-subpass", 160, 96, {{"lights", "32"}});
  const RenderedFrame stored =
      render(scene, "deferred-subpass", 160, 96, {{"lights", "32"}, {"transient", "off"}, {"gbuffer_store", "store"}});
  EXPECT_NE(none.outputs.color->bytes(), lit.outputs.color->bytes());
  EXPECT_EQ(lit.outputs.color->bytes(), stored.outputs.color->bytes());
}

TEST(DeferredPipelines, AttachmentTrafficIsTheAnalyticPerPixelFormula) {
  const Scene scene = test::wall_scene();
  const int w = 256, h = 128;
  const uint64_t px = uint64_t(w) * h;
  {  // vulkan-samples, two passes: G-buffer pass stores albedo + normal + depth (4+4+4 B/px)
    // and the lighting pass stores the light (4 B/px) after reading all three as textures.
    const FrameReport r = render(scene, "deferred-classic", w, h, {{"lights", "8"}}).outputs.report;
    for (const char* name : {"albedo", "normal", "depth"}) {
      EXPECT_EQ(attachment(r, "gbuffer", name).bytes_stored, 4 * px) << name;
      EXPECT_EQ(attachment(r, "gbuffer", name).bytes_loaded, 0u) << name;
    }
    EXPECT_EQ(attachment(r, "lighting", "light").bytes_stored, 4 * px);
    EXPECT_EQ(attachment(r, "lighting", "light").bytes_loaded, 0u);
    // Each 64-byte line of the three 4 B/px textures is fetched exactly once (rows of a 16 px
    // tile are one aligned line each).
    EXPECT_EQ(pass_named(r, "lighting").texture.bytes_read, 12 * px);
    const auto by = r.bytes_by_category();
    EXPECT_EQ(by.at("attachment_store"), 16 * px);
    EXPECT_EQ(by.at("attachment_load"), 0u);
  }
  {  // vulkan-samples, subpasses: only the light target reaches memory.
    const FrameReport r = render(scene, "deferred-subpass", w, h, {{"lights", "8"}}).outputs.report;
    ASSERT_EQ(r.passes.size(), 1u);
    EXPECT_EQ(attachment(r, "deferred", "light").bytes_stored, 4 * px);
    for (const char* name : {"albedo", "normal", "depth"}) {
      const AttachmentTraffic& a = attachment(r, "deferred", name);
      EXPECT_TRUE(a.transient) << name;
      EXPECT_EQ(a.bytes_stored + a.bytes_loaded, 0u) << name;
    }
    EXPECT_EQ(r.bytes_by_category().at("attachment_store"), 4 * px);
    EXPECT_EQ(r.passes[0].texture.bytes_read, 0u);
  }
  {  // transient attachments off: memory-backed but DONT_CARE, so nothing more is written...
    const FrameReport r = render(scene, "deferred-subpass", w, h, {{"transient", "off"}}).outputs.report;
    EXPECT_FALSE(attachment(r, "deferred", "albedo").transient);
    EXPECT_EQ(r.bytes_by_category().at("attachment_store"), 4 * px);
  }
  {  // ...unless they are stored: then the G-buffer and depth are written back too.
    const FrameReport r =
        render(scene, "deferred-subpass", w, h, {{"transient", "off"}, {"gbuffer_store", "store"}}).outputs.report;
    EXPECT_EQ(r.bytes_by_category().at("attachment_store"), 16 * px);
  }
  {  // vulkan-samples, two render passes as the sample: the geometry pass clears and stores
    // light, depth, albedo and normal (4 B/px each); the lighting pass loads all four as input
    // attachments and stores the light. No texture reads.
    const FrameReport r =
        render(scene, "deferred-subpass", w, h, {{"lights", "8"}, {"technique", "render-passes"}}).outputs.report;
    ASSERT_EQ(r.passes.size(), 2u);
    for (const char* name : {"light", "depth", "albedo", "normal"}) {
      EXPECT_EQ(attachment(r, "gbuffer", name).bytes_stored, 4 * px) << name;
      EXPECT_EQ(attachment(r, "lighting", name).bytes_loaded, 4 * px) << name;
    }
    EXPECT_EQ(attachment(r, "lighting", "light").bytes_stored, 4 * px);
    EXPECT_EQ(pass_named(r, "lighting").texture.bytes_read, 0u);
    const auto by = r.bytes_by_category();
    EXPECT_EQ(by.at("attachment_store"), 20 * px);
    EXPECT_EQ(by.at("attachment_load"), 16 * px);
  }
  {  // unity, two passes + tonemap: G-buffer pass stores light 8 + diffuse, specular, normal,
    // depth 4 each; lighting loads and stores the light (8 + 8) reading depth + 3 targets as
    // textures (16); tonemap reads the light as a texture (8) and stores the final image (4).
    const FrameReport r = render(scene, "deferred-classic", w, h, {{"gbuffer", "unity"}}).outputs.report;
    EXPECT_EQ(attachment(r, "gbuffer", "light").bytes_stored, 8 * px);
    EXPECT_EQ(attachment(r, "lighting", "light").bytes_loaded, 8 * px);
    EXPECT_EQ(attachment(r, "lighting", "light").bytes_stored, 8 * px);
    EXPECT_EQ(pass_named(r, "lighting").texture.bytes_read, 16 * px);
    EXPECT_EQ(pass_named(r, "tonemap").texture.bytes_read, 8 * px);
    const auto by = r.bytes_by_category();
    EXPECT_EQ(by.at("attachment_store"), (24 + 8 + 4) * px);
    EXPECT_EQ(by.at("attachment_load"), 8 * px);
  }
  {  // unity, subpasses with the tonemap subpass: only the final RGBA8 image is stored.
    const FrameReport r = render(scene, "deferred-subpass", w, h, {{"gbuffer", "unity"}}).outputs.report;
    EXPECT_EQ(r.bytes_by_category().at("attachment_store"), 4 * px);
    EXPECT_EQ(attachment(r, "deferred", "light").bytes_stored, 0u);
  }
}

TEST(DeferredPipelines, GBufferOverTheBudgetHalvesTheTile) {
  const Scene scene = load_gltf(kDemo);
  const FrameReport fits = render(scene, "deferred-subpass", 320, 180).outputs.report;
  const FrameReport over = render(scene, "deferred-subpass", 320, 180, {{"gbuffer", "vulkan-samples-large"}}).outputs.report;
  ASSERT_EQ(fits.passes.size(), 1u);
  ASSERT_EQ(over.passes.size(), 1u);
  EXPECT_EQ(fits.passes[0].color_bits_per_px, 96);
  EXPECT_FALSE(fits.passes[0].tile_size_reduced);
  EXPECT_EQ(fits.passes[0].tile_width_px * fits.passes[0].tile_height_px, 256);
  EXPECT_EQ(over.passes[0].color_bits_per_px, 160);
  EXPECT_TRUE(over.passes[0].tile_size_reduced);
  EXPECT_EQ(over.passes[0].tile_width_px * over.passes[0].tile_height_px, 128);
  // Smaller tiles: more tiles, and a triangle spanning several tiles is listed and read once per
  // tile, so the tile lists grow in both directions while the triangles binned stay the same.
  EXPECT_GT(over.passes[0].tiles_total, fits.passes[0].tiles_total);
  EXPECT_EQ(over.passes[0].geometry.triangles_binned, fits.passes[0].geometry.triangles_binned);
  EXPECT_GT(over.passes[0].geometry.tile_list_entries, fits.passes[0].geometry.tile_list_entries);
  EXPECT_GT(over.passes[0].geometry.parameter_bytes_written, fits.passes[0].geometry.parameter_bytes_written);
  EXPECT_GT(over.passes[0].tiles.parameter_bytes_read, fits.passes[0].tiles.parameter_bytes_read);
}

TEST(ForwardPipeline, MsaaResolvedOnTileOrSeparatelyGivesTheSameImage) {
  const Scene scene = load_gltf(kDemo);
  const int w = 192, h = 112;
  const uint64_t px = uint64_t(w) * h;
  const RenderedFrame on_tile = render(scene, "forward", w, h, {{"msaa", "4"}, {"lights", "8"}});
  const RenderedFrame separate = render(scene, "forward", w, h, {{"msaa", "4"}, {"resolve", "separate"}, {"lights", "8"}});
  const RenderedFrame single = render(scene, "forward", w, h, {{"lights", "8"}});
  EXPECT_EQ(on_tile.outputs.color->bytes(), separate.outputs.color->bytes());
  EXPECT_NE(on_tile.outputs.color->bytes(), single.outputs.color->bytes()) << "4x MSAA must smooth edges";
  const auto a = on_tile.outputs.report.bytes_by_category();
  const auto b = separate.outputs.report.bytes_by_category();
  // On tile: the resolved image is the only attachment write (4 B/px).
  EXPECT_EQ(a.at("resolve"), 4 * px);
  EXPECT_EQ(a.at("attachment_store"), 0u);
  // Separately: 4 samples stored (16 B/px), loaded back by the resolve pass (16 B/px), resolved.
  EXPECT_EQ(b.at("attachment_store"), 16 * px);
  EXPECT_EQ(b.at("attachment_load"), 16 * px);
  EXPECT_EQ(b.at("resolve"), 4 * px);
}

TEST(DeferredPipelines, ForwardAndDeferredAgreeUpToGBufferQuantisation) {
  const Scene scene = load_gltf(kDemo);
  const RenderedFrame forward = render(scene, "forward", 200, 112, {{"lights", "16"}});
  const RenderedFrame deferred = render(scene, "deferred-subpass", 200, 112, {{"lights", "16"}});
  const auto& a = forward.outputs.color->bytes();
  const auto& b = deferred.outputs.color->bytes();
  ASSERT_EQ(a.size(), b.size());
  double sum = 0.0;
  int worst = 0;
  for (size_t i = 0; i < a.size(); i += 4) {
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(a[i + c]) - int(b[i + c]));
      sum += d;
      worst = std::max(worst, d);
    }
  }
  const double mean = sum / (a.size() / 4 * 3);
  EXPECT_LT(mean, 1.0) << "mean absolute difference in 8-bit steps";
  EXPECT_GT(sum, 0.0) << "the G-buffer quantises normals and material values";
  RecordProperty("max_difference", worst);
}

TEST(DeferredPipelines, BadOptionsAreErrors) {
  const Scene scene = test::wall_scene();
  EXPECT_THROW(render(scene, "deferred-classic", 64, 64, {{"gbuffer", "fat"}}), Error);
  EXPECT_THROW(render(scene, "deferred-classic", 64, 64, {{"lights", "-1"}}), Error);
  EXPECT_THROW(render(scene, "deferred-classic", 64, 64, {{"transient", "off"}}), Error);
  EXPECT_THROW(render(scene, "deferred-subpass", 64, 64, {{"gbuffer_store", "store"}}), Error);
  EXPECT_THROW(render(scene, "deferred-subpass", 64, 64, {{"technique", "passes"}}), Error);
  EXPECT_THROW(render(scene, "deferred-subpass", 64, 64, {{"technique", "render-passes"}, {"transient", "off"}}), Error);
  EXPECT_THROW(render(scene, "deferred-classic", 64, 64, {{"technique", "render-passes"}}), Error);
  EXPECT_THROW(render(scene, "forward", 64, 64, {{"msaa", "3"}}), Error);
  EXPECT_THROW(render(scene, "forward", 64, 64, {{"resolve", "separate"}}), Error);
  EXPECT_THROW(render(scene, "deferred-subpass", 64, 64, {{"msaa", "4"}}), Error);
}

}  // namespace
}  // namespace ontile
