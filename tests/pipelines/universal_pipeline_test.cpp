// The `universal` pipeline: the demo renders deterministically with the documented passes and
// traffic, renderer features run at their events in order, the main light casts shadows, the
// light loop stops at 8 lights, and the ScreenSpaceOutline feature only changes edge pixels.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <typeinfo>

#include <glm/gtc/matrix_transform.hpp>

#include "pipelines/kit/render_frame.h"
#include "pipelines/universal/universal_lit_functors.h"
#include "pipelines/universal/universal_lit_shader.h"
#include "pipelines/universal/universal_pipeline.h"
#include "scene/gltf_loader.h"
#include "support/cli_runner.h"
#include "util/error.h"

namespace ontile {
namespace {

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

RenderedFrame render_universal(const Scene& scene, int threads, int w = 320, int h = 180,
                          const std::vector<std::pair<std::string, std::string>>& options = {}) {
  RenderSettings s;
  s.pipeline = "universal";
  s.width_px = w;
  s.height_px = h;
  s.context.threads = threads;
  for (const auto& [key, value] : options) s.options.set(key, value);
  return render_frame(scene, s);
}

std::vector<std::string> pass_names(const FrameReport& report) {
  std::vector<std::string> names;
  for (const PassReport& p : report.passes) names.push_back(p.name);
  return names;
}

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream f(path);
  return nlohmann::json::parse(f);
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

// Each frame runs in its own CLI process: render-target snapshots get simulated texture
// addresses from a process-wide counter, so a second frame in one process sees different
// addresses and texture-cache conflicts (the images stay identical; see the in-process check).
TEST(UniversalPipeline, DemoIsDeterministicAtOneAndTwoThreads) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("ontile_universal_test_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  for (int threads : {1, 2}) {
    const std::string stem = (dir / ("t" + std::to_string(threads))).string();
    const std::string cmd = std::string(ONTILE_CLI) + " render --pipeline universal --scene " + kDemo +
                            " --size 320x180 --threads " + std::to_string(threads) + " --out " + stem +
                            ".png --report " + stem + ".json > /dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    test::validate_report(stem + ".json");
  }
  EXPECT_TRUE(read_bytes(dir / "t1.png") == read_bytes(dir / "t2.png"));
  nlohmann::json one = read_json(dir / "t1.json"), two = read_json(dir / "t2.json");
  one.erase("timing");
  two.erase("timing");
  one["run"].erase("threads");  // the one option the two runs differ in
  two["run"].erase("threads");
  EXPECT_EQ(one, two);
  EXPECT_EQ(one["passes"].size(), 6u);
  std::filesystem::remove_all(dir);

  const Scene scene = load_gltf(kDemo);
  const RenderedFrame a = render_universal(scene, 1), b = render_universal(scene, 2);
  EXPECT_TRUE(a.outputs.color->bytes() == b.outputs.color->bytes());
  EXPECT_EQ(a.outputs.color->format(), PixelFormat::RGBA8_SRGB);
  EXPECT_NE(a.outputs.color->read(0, 0), a.outputs.color->read(160, 120)) << "sky vs ground";
}

TEST(UniversalPipeline, DemoPassesFormatsAndAttachmentTraffic) {
  const Scene scene = load_gltf(kDemo);
  const int w = 320, h = 180;
  const uint64_t px = uint64_t(w) * h;
  const FrameReport r = render_universal(scene, 2, w, h).outputs.report;
  ASSERT_EQ(pass_names(r), (std::vector<std::string>{"MainLightShadow", "DepthNormalPrepass", "ForwardRendering",
                                                     "blit CopyColor", "blit ScreenSpaceOutline",
                                                     "blit PostProcessing"}));
  // Shadow map: D32F 2048^2 cleared and stored.
  EXPECT_EQ(r.passes[0].attachments.at(0).format, PixelFormat::D32_FLOAT);
  EXPECT_EQ(r.passes[0].attachment_bytes_stored(), 2048u * 2048u * 4u);
  EXPECT_GT(r.passes[0].geometry.triangles_binned, 0u);
  // DepthNormals: RGB10A2 normals + D32F depth, both stored.
  EXPECT_EQ(r.passes[1].attachment_bytes_stored(), px * (4 + 4));
  EXPECT_EQ(r.passes[1].attachment_bytes_loaded(), 0u);
  // Forward: depth loaded, not stored; RGBA16F colour cleared and stored.
  EXPECT_EQ(r.passes[2].attachment_bytes_loaded(), px * 4);
  EXPECT_EQ(r.passes[2].attachment_bytes_stored(), px * 8);
  EXPECT_GT(r.passes[2].texture.bytes_read, 0u) << "shadow map and base-colour texture reads";
  // The copy and the outline write RGBA16F; the tonemap writes RGBA8 sRGB.
  EXPECT_EQ(r.passes[3].attachment_bytes_stored(), px * 8);
  EXPECT_EQ(r.passes[4].attachment_bytes_stored(), px * 8);
  EXPECT_EQ(r.passes[5].attachment_bytes_stored(), px * 4);
  EXPECT_EQ(r.passes[5].attachments.at(0).format, PixelFormat::RGBA8_SRGB);
}

// Records the order it ran in and leaves a 1x1 pass named after itself in the frame report,
// so its place among the pipeline's passes is visible.
class OrderProbeFeature final : public RendererFeature {
 public:
  OrderProbeFeature(std::string name, int event, std::vector<std::string>* log)
      : name_(std::move(name)), event_(event), log_(log) {}
  std::string name() const override { return name_; }
  int event() const override { return event_; }
  void record(RenderContext& context, const RenderingData&) override {
    log_->push_back(name_);
    Surface* s = context.create_surface(name_, PixelFormat::RGBA8_UNORM, 1, 1);
    context.set_render_target({{RenderTargetRef::of(s), LoadAction::Clear, StoreAction::Store}}, {},
                              "feature " + name_);
  }

 private:
  std::string name_;
  int event_;
  std::vector<std::string>* log_;
};

TEST(UniversalPipeline, FeaturesRunByEventThenInsertionOrderAtTheirPlaceInTheFrame) {
  const Scene scene = load_gltf(kDemo);
  std::vector<std::string> log;
  UniversalPipeline pipeline;
  auto add = [&](const std::string& name, int event) {
    return &pipeline.add_feature(std::make_unique<OrderProbeFeature>(name, event, &log));
  };
  add("end", RenderPassEvent::AfterRendering);
  add("opaques a", RenderPassEvent::AfterRenderingOpaques);
  add("shadows", RenderPassEvent::AfterRenderingShadows);
  add("opaques +10", RenderPassEvent::AfterRenderingOpaques + 10);
  add("start", RenderPassEvent::BeforeRendering);
  add("opaques b", RenderPassEvent::AfterRenderingOpaques);
  add("inactive", RenderPassEvent::BeforeRendering)->set_active(false);
  add("post", RenderPassEvent::BeforeRenderingPostProcessing);
  add("after post", RenderPassEvent::AfterRenderingPostProcessing);
  RenderContext context(ContextConfig{2, {}});
  FrameInputs in;
  in.scene = &scene;
  in.camera = select_camera(scene, -1);
  in.width_px = 64;
  in.height_px = 36;
  const FrameReport r = pipeline.render(context, in).report;
  EXPECT_EQ(log, (std::vector<std::string>{"start", "shadows", "opaques a", "opaques b", "opaques +10", "post",
                                           "after post", "end"}));
  ASSERT_EQ(pass_names(r),
            (std::vector<std::string>{"feature start", "MainLightShadow", "feature shadows", "DepthPrepass",
                                      "ForwardRendering", "feature opaques a", "feature opaques b",
                                      "feature opaques +10", "ForwardRendering (resumed)", "blit CopyColor",
                                      "feature post", "blit PostProcessing", "feature after post",
                                      "feature end"}));
  // Features inside the forward pass split it: depth is stored, then both targets are loaded.
  const uint64_t px = 64u * 36u;
  EXPECT_EQ(r.passes[4].attachment_bytes_stored(), px * (8 + 4));
  EXPECT_EQ(r.passes[8].attachment_bytes_loaded(), px * (8 + 4));
}

// A ground quad (y = 0, 10 x 10) and a unit box floating at y = 1.5..2.5 over the origin, lit
// straight from above, seen from the side and above.
struct ShadowScene {
  Scene scene;
  ShadowScene() {
    Mesh ground, box;
    MeshPrimitive quad;
    quad.positions = {{-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}};
    quad.normals.assign(4, glm::vec3(0, 1, 0));
    quad.indices = {0, 1, 2, 0, 2, 3};
    ground.primitives.push_back(quad);
    MeshPrimitive cube;
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int face = 0; face < 6; ++face) {
      const glm::vec3 n = axes[face / 2] * (face % 2 ? -1.0f : 1.0f);
      const glm::vec3 u = axes[(face / 2 + 1) % 3], v = glm::cross(n, u);
      const uint32_t base = static_cast<uint32_t>(cube.positions.size());
      for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        cube.positions.push_back(0.5f * (n + c.x * u + c.y * v));
        cube.normals.push_back(n);
      }
      cube.indices.insert(cube.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    box.primitives.push_back(cube);
    for (Mesh* m : {&ground, &box}) {
      for (MeshPrimitive& p : m->primitives) {
        p.material = 0;
        for (const glm::vec3& q : p.positions) p.bounds.extend(q);
      }
      scene.meshes.push_back(*m);
    }
    Material grey;
    grey.base_color_factor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    grey.metallic_factor = 0.0f;
    scene.materials.push_back(grey);
    for (int mesh = 0; mesh < 2; ++mesh) {
      MeshInstance instance;
      instance.mesh = mesh;
      instance.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, mesh == 1 ? 2.0f : 0.0f, 0.0f));
      const Bounds& b = scene.meshes[mesh].primitives[0].bounds;
      instance.world_bounds.extend(glm::vec3(glm::mat4(instance.world) * glm::vec4(b.min, 1.0f)));
      instance.world_bounds.extend(glm::vec3(glm::mat4(instance.world) * glm::vec4(b.max, 1.0f)));
      scene.world_bounds.extend(instance.world_bounds);
      scene.instances.push_back(instance);
    }
    Light sun;
    sun.direction = glm::vec3(0, -1, 0);
    sun.intensity = 2.0f;
    scene.lights.push_back(sun);
    Camera camera;
    camera.yfov_rad = 0.9f;
    camera.znear = 0.1f;
    camera.zfar = 100.0f;
    camera.world = glm::inverse(glm::lookAt(glm::vec3(0, 6, 8), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0)));
    scene.cameras.push_back(camera);
  }
};

glm::ivec2 pixel_of(const Scene& scene, glm::vec3 world, int w, int h) {
  const CameraMatrices m = camera_matrices(scene.cameras[0], double(w) / h);
  const glm::dvec4 clip = m.view_projection * glm::dvec4(glm::dvec3(world), 1.0);
  return {static_cast<int>((clip.x / clip.w + 1.0) * 0.5 * w), static_cast<int>((1.0 - clip.y / clip.w) * 0.5 * h)};
}

TEST(UniversalPipeline, GroundUnderABoxIsInItsShadow) {
  const ShadowScene s;
  const int w = 160, h = 90;
  const glm::ivec2 under = pixel_of(s.scene, {0, 0, 0}, w, h);
  const glm::ivec2 open = pixel_of(s.scene, {2.5f, 0, 0}, w, h);
  auto luminance = [&](const RenderedFrame& f, glm::ivec2 p) {
    const glm::vec4 c = f.outputs.color->read(p.x, p.y);
    return c.x + c.y + c.z;
  };
  const RenderedFrame shadowed = render_universal(s.scene, 2, w, h);
  EXPECT_LT(luminance(shadowed, under), 0.5f * luminance(shadowed, open));
  const RenderedFrame unshadowed = render_universal(s.scene, 2, w, h, {{"shadows", "off"}});
  EXPECT_EQ(pass_names(unshadowed.outputs.report).front(), "DepthNormalPrepass");
  EXPECT_GT(luminance(unshadowed, under), 0.9f * luminance(unshadowed, open));
  EXPECT_TRUE(shadowed.outputs.color->read(open.x, open.y) == unshadowed.outputs.color->read(open.x, open.y))
      << "a lit pixel does not change with shadows";
}

// Globals recorded into a command buffer, applied as the frame executor would.
PropertyBlock globals_of(const CommandBuffer& cmd) {
  PropertyBlock p;
  for (const Command& c : cmd.commands()) {
    if (const auto* v = std::get_if<op::SetGlobalVector>(&c)) p.vectors[v->name] = v->value;
    if (const auto* f = std::get_if<op::SetGlobalFloat>(&c)) p.floats[f->name] = f->value;
  }
  return p;
}

TEST(UniversalPipeline, LightLoopShadesAtMostEightLightsChosenByInfluence) {
  Scene scene;
  for (int i = 0; i < 12; ++i) {  // light i at distance 1 + i from the unit box's bounds
    Light l;
    l.type = Light::Type::Point;
    l.intensity = 10.0f;
    l.position = glm::vec3(1.5f + static_cast<float>(i), 0.0f, 0.0f);
    scene.lights.push_back(l);
  }
  const UniversalLights lights = universal_lights(scene);
  ASSERT_EQ(lights.additional.size(), 12u);
  MeshPrimitive mesh = ShadowScene().scene.meshes[1].primitives[0];  // unit box at the origin
  const auto shader = make_universal_lit_shader();
  const auto material = make_universal_lit_material(*shader, Material{});
  auto light_count = [&](float per_object_limit, std::vector<glm::vec3>* positions = nullptr) {
    CommandBuffer cmd;
    set_light_globals(cmd, lights);
    DrawContext ctx;
    ctx.mesh = &mesh;
    ctx.material = material.get();
    ctx.properties = globals_of(cmd);
    if (per_object_limit >= 0.0f) ctx.properties.floats["_AdditionalLightsPerObject"] = per_object_limit;
    ctx.properties.merge_from(material->properties);
    const DrawFunctors f = shader->find_light_mode(universal_light_mode::kForward)->factory(ctx);
    const auto* lit = dynamic_cast<const UniversalLitFragment*>(f.fragment.get());
    if (!lit) throw Error("not a UniversalLitFragment");
    for (int i = 0; positions && i < lit->params().additional_light_count; ++i) {
      positions->push_back(lit->params().additional_lights[i].position);
    }
    return lit->light_count();
  };
  std::vector<glm::vec3> chosen;
  EXPECT_EQ(light_count(-1.0f, &chosen), kMaxLightsPerObject);
  ASSERT_EQ(chosen.size(), 7u);
  for (int i = 0; i < 7; ++i) EXPECT_EQ(chosen[i].x, 1.5f + i) << "nearest (strongest) first";
  EXPECT_EQ(light_count(3.0f), 4);
  EXPECT_EQ(light_count(0.0f), 1);
  // Out of range lights are never chosen.
  scene.lights.resize(3);
  scene.lights[1].range = 1.0f;  // 2 away from the box
  EXPECT_EQ(select_additional_lights(universal_lights(scene).additional, mesh.bounds, 7), (std::vector<int>{0, 2}));
}

TEST(UniversalPipeline, KeywordsPickVariantsAndAlphaTestedDepthPassesDiscard) {
  MeshPrimitive mesh = ShadowScene().scene.meshes[1].primitives[0];
  const auto shader = make_universal_lit_shader();
  auto build = [&](const RenderMaterial& m, const char* light_mode) {
    DrawContext ctx;
    ctx.mesh = &mesh;
    ctx.material = &m;
    ctx.properties = m.properties;
    return shader->find_light_mode(light_mode)->factory(ctx);
  };
  Material gltf;
  const auto opaque = make_universal_lit_material(*shader, gltf);
  EXPECT_EQ(typeid(*build(*opaque, universal_light_mode::kForward).fragment),
            typeid(UniversalLitShader<false, false, false, false>));
  EXPECT_EQ(build(*opaque, universal_light_mode::kDepthOnly).fragment, nullptr) << "depth only: no functor";
  gltf.emissive_factor = glm::vec3(1.0f, 0.5f, 0.0f);
  EXPECT_EQ(typeid(*build(*make_universal_lit_material(*shader, gltf), universal_light_mode::kForward).fragment),
            typeid(UniversalLitShader<false, false, true, false>));
  gltf.emissive_factor = glm::vec3(0.0f);
  gltf.alpha_mode = AlphaMode::Mask;
  QuadFragment quad;
  quad.lane_mask = 0xF;
  for (auto& varying : quad.varyings)
    for (float& v : varying) v = 0.0f;
  for (const float alpha : {0.3f, 0.8f}) {
    gltf.base_color_factor.w = alpha;
    const auto masked = make_universal_lit_material(*shader, gltf);
    EXPECT_EQ(masked->render_queue, render_queue::kAlphaTest);
    for (const char* mode : {universal_light_mode::kForward, universal_light_mode::kDepthOnly,
                             universal_light_mode::kShadowCaster, universal_light_mode::kDepthNormals}) {
      const DrawFunctors f = build(*masked, mode);
      ASSERT_NE(f.fragment, nullptr) << mode;
      EXPECT_TRUE(f.fragment->may_discard()) << mode;
      QuadOutput out;
      f.fragment->shade(quad, out);
      EXPECT_EQ(out.discard_mask, alpha < 0.5f ? 0xF : 0x0) << mode << " alpha " << alpha;
    }
  }
}

TEST(UniversalPipeline, AttenuationFollowsTheKhrLightsPunctualRecommendation) {
  EXPECT_FLOAT_EQ(range_attenuation(4.0f, 0.0f), 0.25f);                // 1 / d^2
  EXPECT_FLOAT_EQ(range_attenuation(1.0f, 2.0f), 1.0f - 1.0f / 16.0f);  // (1 - (d/r)^4) / d^2
  EXPECT_EQ(range_attenuation(4.0f, 2.0f), 0.0f);
  AdditionalLight spot;
  spot.type = AdditionalLight::Type::Spot;
  spot.direction = glm::vec3(0, 0, -1);
  spot.spot_scale = 1.0f / (1.0f - 0.5f);  // inner 0 deg, outer 60 deg
  spot.spot_offset = -0.5f * spot.spot_scale;
  EXPECT_FLOAT_EQ(spot_attenuation(spot, {0, 0, -1}), 1.0f);
  EXPECT_EQ(spot_attenuation(spot, {1, 0, 0}), 0.0f);
  EXPECT_FLOAT_EQ(spot_attenuation(spot, glm::normalize(glm::vec3(0, 1, -1))), 0.17157288f);  // (2 cos45 - 1)^2
  EXPECT_FLOAT_EQ(tonemap_reinhard(glm::vec3(1.0f)).x, 0.5f);
  EXPECT_EQ(tonemap_aces_fitted(glm::vec3(0.0f)), glm::vec3(0.0f));
  EXPECT_EQ(tonemap_aces_fitted(glm::vec3(1e6f)), glm::vec3(1.0f));
}

TEST(UniversalPipeline, OutlineFeatureOnlyBlackensEdgePixels) {
  const Scene scene = load_gltf(kDemo);
  const RenderedFrame with = render_universal(scene, 2);
  const RenderedFrame without = render_universal(scene, 2, 320, 180, {{"outline", "off"}});
  EXPECT_EQ(pass_names(without.outputs.report),
            (std::vector<std::string>{"MainLightShadow", "DepthPrepass", "ForwardRendering", "blit CopyColor",
                                      "blit PostProcessing"}));
  int changed = 0;
  for (int y = 0; y < 180; ++y) {
    for (int x = 0; x < 320; ++x) {
      const glm::vec4 a = with.outputs.color->read(x, y), b = without.outputs.color->read(x, y);
      if (a == b) continue;
      ++changed;
      EXPECT_EQ(a, glm::vec4(0, 0, 0, 1)) << "changed pixels are border-coloured: " << x << "," << y;
    }
  }
  EXPECT_GT(changed, 0);
  EXPECT_LT(changed, 320 * 180 / 5);
}

TEST(UniversalPipeline, OptionErrors) {
  const Scene scene = load_gltf(kDemo);
  for (const auto& [key, value, phrase] :
       {std::tuple{"shadows", "maybe", "expected on or off"}, std::tuple{"tonemap", "filmic", "expected aces"},
        std::tuple{"max_lights", "9", "expected an integer in"},
        std::tuple{"max_lights", "2.5", "expected an integer in"}, std::tuple{"exposure", "x", "expected a number"},
        std::tuple{"msaa", "4", "has no option 'msaa'"}}) {
    try {
      render_universal(scene, 1, 16, 16, {{key, value}});
      ADD_FAILURE() << key << "=" << value << " was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace ontile
