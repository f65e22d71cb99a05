// Golden-image cases and comparison (see golden_images.h).
#include "golden/golden_images.h"

#include <algorithm>
#include <cstdlib>

#include "io/image_io.h"
#include "pipelines/kit/render_frame.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile {

std::vector<GoldenCase> golden_cases(const std::filesystem::path& source_dir,
                                     const std::filesystem::path& shared_assets) {
  std::vector<GoldenCase> cases;
  const std::filesystem::path demo = source_dir / "scenes" / "demo.glb";
  for (const std::string& p : pipeline_names()) {
    GoldenCase c{"demo_" + p, demo, p, 480, 270, {}};
    // The forward and deferred pipelines are shown with generated point lights.
    if (p == "forward" || p.starts_with("deferred")) c.options = {{"lights", "16"}};
    cases.push_back(c);
  }
  cases.push_back({"demo_deferred-subpass_unity", demo, "deferred-subpass", 480, 270, {{"gbuffer", "unity"}, {"lights", "16"}}});
  cases.push_back({"demo_forward_msaa4", demo, "forward", 480, 270, {{"msaa", "4"}, {"lights", "16"}}});
  for (const auto& [stem, relative] : {std::pair{"DamagedHelmet", "DamagedHelmet/DamagedHelmet.glb"},
                                       std::pair{"Duck", "Duck/Duck.gltf"}}) {
    for (const std::string p : {"lambert", "cartoon"}) {
      const auto names = pipeline_names();
      if (std::find(names.begin(), names.end(), p) == names.end()) continue;
      cases.push_back({std::string(stem) + "_" + p, shared_assets / relative, p, 320, 240, {}});
    }
  }
  return cases;
}

GoldenResult run_golden_case(const GoldenCase& c, const std::filesystem::path& golden_dir,
                             const std::filesystem::path& failure_dir, bool update) {
  GoldenResult result;
  result.golden_case = c;
  if (!std::filesystem::exists(c.scene)) {
    result.status = GoldenResult::Status::Skipped;
    result.message = "scene " + c.scene.string() + " not found";
    return result;
  }
  const Scene scene = load_gltf(c.scene);
  RenderSettings settings;
  settings.pipeline = c.pipeline;
  settings.width_px = c.width_px;
  settings.height_px = c.height_px;
  settings.context.threads = 2;
  for (const auto& [key, value] : c.options) settings.options.set(key, value);
  const RenderedFrame frame = render_frame(scene, settings);
  const Surface& color = *frame.outputs.color;
  if (color.format() != PixelFormat::RGBA8_SRGB && color.format() != PixelFormat::RGBA8_UNORM) {
    throw Error("golden case " + c.name + ": pipeline output is not 8-bit");
  }
  const std::filesystem::path reference = golden_dir / (c.name + ".png");
  if (update) {
    write_png_rgba8(reference, color.width(), color.height(), color.bytes());
    result.status = GoldenResult::Status::Updated;
    return result;
  }
  result.actual_image = failure_dir / (c.name + ".actual.png");
  // The failure folder (a documented default, out/golden_failures) is made only when there is a
  // failure to write into it.
  const auto write_failure = [&](const std::filesystem::path& path, const std::vector<uint8_t>& rgba) {
    std::filesystem::create_directories(failure_dir);
    write_png_rgba8(path, color.width(), color.height(), rgba);
  };
  if (!std::filesystem::exists(reference)) {
    write_failure(result.actual_image, color.bytes());
    result.status = GoldenResult::Status::Missing;
    result.message = reference.string() + " does not exist (run `ontile golden --update`)";
    return result;
  }
  int w = 0, h = 0;
  const std::vector<uint8_t> expected = read_png_rgba8(reference, w, h);
  if (w != color.width() || h != color.height()) {
    write_failure(result.actual_image, color.bytes());
    result.status = GoldenResult::Status::Mismatch;
    result.message = "size " + std::to_string(color.width()) + "x" + std::to_string(color.height()) +
                     " differs from the golden " + std::to_string(w) + "x" + std::to_string(h);
    return result;
  }
  const std::vector<uint8_t>& actual = color.bytes();
  std::vector<uint8_t> diff(actual.size(), 0);
  for (size_t px = 0; px < actual.size(); px += 4) {
    int worst = 0;
    for (int ch = 0; ch < 4; ++ch) worst = std::max(worst, std::abs(int(actual[px + ch]) - int(expected[px + ch])));
    if (worst) ++result.differing_pixels;
    result.max_channel_difference = std::max(result.max_channel_difference, worst);
    // Diff image: differing pixels in red, brighter for larger differences; the rest a dim
    // grey copy of the expected image so the difference can be located.
    const uint8_t grey = static_cast<uint8_t>((expected[px] + expected[px + 1] + expected[px + 2]) / 12);
    diff[px] = worst ? static_cast<uint8_t>(std::min(255, 128 + worst * 8)) : grey;
    diff[px + 1] = worst ? 0 : grey;
    diff[px + 2] = worst ? 0 : grey;
    diff[px + 3] = 255;
  }
  if (result.differing_pixels == 0) return result;
  result.status = GoldenResult::Status::Mismatch;
  result.diff_image = failure_dir / (c.name + ".diff.png");
  write_failure(result.actual_image, actual);
  write_failure(result.diff_image, diff);
  result.message = std::to_string(result.differing_pixels) + " pixels differ (max channel difference " +
                   std::to_string(result.max_channel_difference) + "); actual: " +
                   result.actual_image.string() + ", diff: " + result.diff_image.string();
  return result;
}

}  // namespace ontile
