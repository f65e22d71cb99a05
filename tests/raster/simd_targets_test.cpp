// Bit-identical results on every SIMD target the build compiles and this CPU runs (Highway's
// runtime dispatch forced to each in turn): images and traffic reports of several pipelines,
// including MSAA, must not depend on the vector width or instruction set.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "context/frame_report.h"
#include "pipelines/kit/render_frame.h"
#include "raster/cell_raster.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile {
namespace {

struct Frame {
  std::vector<uint8_t> image;
  nlohmann::json report;
};

Frame render(const Scene& scene, const std::string& pipeline, const std::string& options_key = "",
             const std::string& options_value = "") {
  RenderSettings s;
  s.pipeline = pipeline;
  s.width_px = 320;
  s.height_px = 180;
  s.context.threads = 2;
  if (!options_key.empty()) s.options.set(options_key, options_value);
  const RenderedFrame f = render_frame(scene, s);
  nlohmann::json report = frame_report_json(f.outputs.report);
  report.erase("timing");
  return {f.outputs.color->bytes(), report};
}

// Restores automatic target selection however the test exits.
struct AutomaticTargetOnExit {
  ~AutomaticTargetOnExit() { force_simd_target(""); }
};

TEST(SimdTargets, EveryTargetRendersTheSameBits) {
  const std::vector<std::string> targets = simd_targets();
  ASSERT_FALSE(targets.empty());
  std::string names;
  for (const std::string& t : targets) names += t + " ";
  RecordProperty("targets", names);
  std::cout << "SIMD targets on this machine: " << names << "\n";
  const Scene scene = load_gltf(std::filesystem::path(ONTILE_SOURCE_DIR) / "scenes" / "demo.glb");
  const AutomaticTargetOnExit restore;
  struct Case {
    std::string pipeline, key, value;
  };
  const std::vector<Case> cases = {{"lambert", "", ""},
                                   {"lambert", "msaa", "4"},
                                   {"cartoon", "", ""},
                                   {"deferred-subpass", "", ""},
                                   {"forward", "msaa", "4"},
                                   {"universal", "", ""}};
  for (const Case& c : cases) {
    force_simd_target(targets.front());
    const Frame reference = render(scene, c.pipeline, c.key, c.value);
    for (size_t i = 1; i < targets.size(); ++i) {
      force_simd_target(targets[i]);
      ASSERT_EQ(active_simd_target(), targets[i]);
      const Frame f = render(scene, c.pipeline, c.key, c.value);
      EXPECT_TRUE(f.image == reference.image) << c.pipeline << " " << c.key << "=" << c.value << " on "
                                              << targets[i] << " differs from " << targets.front();
      EXPECT_EQ(f.report, reference.report) << c.pipeline << " on " << targets[i];
    }
  }
}

TEST(SimdTargets, UnknownTargetIsAnError) {
  EXPECT_THROW(force_simd_target("NOT_A_TARGET"), Error);
  force_simd_target("");
}

}  // namespace
}  // namespace ontile
