// Every model in ../shared/assets renders with the Lambert pipeline without error, draws
// something, and meets no NaN/Inf geometry.
#include <gtest/gtest.h>

#include <filesystem>

#include "pipelines/kit/render_frame.h"
#include "scene/gltf_loader.h"

namespace ontile {
namespace {

TEST(SharedAssets, EveryModelRenders) {
  const std::filesystem::path root(ONTILE_SHARED_ASSETS);
  if (!std::filesystem::is_directory(root)) GTEST_SKIP() << "no shared assets at " << root;
  int rendered = 0;
  for (const auto& dir : std::filesystem::directory_iterator(root)) {
    if (!dir.is_directory()) continue;
    for (const auto& file : std::filesystem::directory_iterator(dir.path())) {
      const std::string ext = file.path().extension().string();
      if (ext != ".gltf" && ext != ".glb") continue;
      SCOPED_TRACE(file.path().string());
      const Scene scene = load_gltf(file.path());
      RenderSettings settings;
      settings.width_px = 160;
      settings.height_px = 120;
      const RenderedFrame frame = render_frame(scene, settings);
      const PassReport& pass = frame.outputs.report.passes.at(0);
      EXPECT_GT(pass.tiles.fragments_shaded, 0u);
      EXPECT_EQ(pass.geometry.triangles_non_finite, 0u);
      EXPECT_EQ(pass.geometry.triangles_submitted, scene.drawn_triangle_count());
      ++rendered;
    }
  }
  EXPECT_EQ(rendered, 11);
}

}  // namespace
}  // namespace ontile
