// The llvmpipe peer's cartoon frame (bench/llvmpipe/) against ontile's `cartoon` pipeline on
// small generated scenes: the same Sobel edge decision and the same colour on at least the
// shares documented in docs/performance-peer.md. Skips, saying why, where the runner was not
// built (no EGL/GLES headers) or EGL/llvmpipe cannot be opened (the runner exits with 77).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <ostream>
#include <string>
#include <unistd.h>

#include "peer/cartoon_reference.h"
#include "peer/peer_child.h"
#include "peer/peer_compare.h"
#include "pipelines/kit/render_frame.h"
#include "scene/gen/scene_generator.h"
#include "scene/gltf_loader.h"

namespace ontile::peer {
namespace {

namespace fs = std::filesystem;

// docs/performance-peer.md, "The cartoon frame": measured on these scenes and sizes, with
// margin for llvmpipe builds that round differently.
constexpr double kMinEdgeAgreementPercent = 99.0;
constexpr double kMinColorAgreementPercent = 98.0;
constexpr int kWidthPx = 320, kHeightPx = 180;

struct PeerScene {
  const char* generator;
  double size;
};

// How ctest and gtest name the parameter (instead of its bytes).
void PrintTo(const PeerScene& s, std::ostream* out) { *out << s.generator << " at size " << s.size; }

fs::path scene_file(const PeerScene& s) {
  const fs::path folder = fs::path(ONTILE_TEST_OUTPUT) / "peer";
  fs::create_directories(folder);
  const fs::path path = folder / (std::string(s.generator) + "_" + std::to_string(getpid()) + ".glb");
  SceneGenOptions options;
  options.size = s.size;
  generate_scene(s.generator, options, path);
  return path;
}

RenderSettings cartoon_settings() {
  RenderSettings settings;
  settings.pipeline = "cartoon";
  settings.width_px = kWidthPx;
  settings.height_px = kHeightPx;
  settings.context.threads = 2;
  return settings;
}

class LlvmpipeCartoonPeer : public testing::TestWithParam<PeerScene> {};

// The rebuilt frame the edge masks come from is the pipeline's frame, bit for bit.
TEST_P(LlvmpipeCartoonPeer, ReferenceIsThePipelinesFrame) {
  const fs::path file = scene_file(GetParam());
  const Scene scene = load_gltf(file);
  fs::remove(file);
  const RenderedFrame frame = render_frame(scene, cartoon_settings());
  const CartoonReference reference = render_cartoon_reference(scene, cartoon_settings());
  EXPECT_EQ(reference.final_rgba, frame.outputs.color->bytes());
  uint64_t edges = 0;
  for (uint8_t e : reference.edge_mask) edges += e;
  EXPECT_GT(edges, 0u) << "the scene should show outlines";
  EXPECT_LT(edges, reference.edge_mask.size() / 4) << "an edge on most pixels means a broken mask";
}

TEST_P(LlvmpipeCartoonPeer, LlvmpipeDrawsTheSameFrame) {
#ifndef ONTILE_LLVMPIPE_RUNNER
  GTEST_SKIP() << "ontile_llvmpipe was not built (EGL or GLES 3 headers missing at configure time; "
                  "scripts/install_deps.sh installs them)";
#else
  const fs::path file = scene_file(GetParam());
  const Scene scene = load_gltf(file);
  const std::string stem = file.stem().string();
  LlvmpipeRequest request;
  request.runner = ONTILE_LLVMPIPE_RUNNER;
  request.scene = file;
  request.width_px = kWidthPx;
  request.height_px = kHeightPx;
  request.frames = 1;
  request.threads = 1;
  request.pipeline = "cartoon";
  request.color_png = file.parent_path() / (stem + "_llvmpipe.png");
  request.edges_png = file.parent_path() / (stem + "_llvmpipe_edges.png");
  try {
    run_llvmpipe(request);
  } catch (const LlvmpipeUnavailable& e) {
    fs::remove(file);
    GTEST_SKIP() << "EGL/llvmpipe runtime unavailable: " << e.what();
  }
  fs::remove(file);
  const RenderedFrame frame = render_frame(scene, cartoon_settings());
  const CartoonReference reference = render_cartoon_reference(scene, cartoon_settings());
  const EdgeAgreement edges = compare_edge_masks(reference.edge_mask, kWidthPx, kHeightPx, request.edges_png);
  const ColorAgreement color = compare_colors(*frame.outputs.color, request.color_png);
  EXPECT_GE(edges.percent(), kMinEdgeAgreementPercent)
      << "edge pixels: ontile " << edges.ontile_edges << ", llvmpipe " << edges.llvmpipe_edges << "; only ontile "
      << edges.only_ontile << ", only llvmpipe " << edges.only_llvmpipe;
  EXPECT_GT(edges.llvmpipe_edges, 0u);
  EXPECT_GE(color.percent(), kMinColorAgreementPercent) << "mean |diff| " << color.mean_abs_diff;
  std::printf("%s: edge decisions equal on %.3f%% (ontile %llu, llvmpipe %llu edge pixels), colour within %d/255 on "
              "%.2f%%\n",
              GetParam().generator, edges.percent(), static_cast<unsigned long long>(edges.ontile_edges),
              static_cast<unsigned long long>(edges.llvmpipe_edges), kColorTolerance, color.percent());
  fs::remove(request.color_png);
  fs::remove(request.edges_png);
#endif
}

// The atrium: cel shading of textured glTF materials without extras; the demo: the cartoon
// design's scene with cel, MatCap and ToonEnv materials and borders with and without alpha.
INSTANTIATE_TEST_SUITE_P(Scenes, LlvmpipeCartoonPeer,
                         testing::Values(PeerScene{"atrium", 0.05}, PeerScene{"demo", 1.0}),
                         [](const testing::TestParamInfo<PeerScene>& info) { return std::string(info.param.generator); });

}  // namespace
}  // namespace ontile::peer
