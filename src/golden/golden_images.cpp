// Golden-image cases and comparison (see golden_images.h).
#include "golden/golden_images.h"

#include <algorithm>

#include "io/image_io.h"
#include "pipelines/kit/render_frame.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile {

std::vector<GoldenCase> golden_cases(const std::filesystem::path& demo_scene,
                                     const std::filesystem::path& shared_assets) {
  using Options = decltype(GoldenCase::options);
  std::vector<GoldenCase> cases;
  const auto add = [&](std::string name, std::filesystem::path scene, std::string pipeline, int width_px,
                       int height_px, Options options) {
    GoldenCase c;
    c.name = std::move(name);
    c.scene = std::move(scene);
    c.pipeline = std::move(pipeline);
    c.width_px = width_px;
    c.height_px = height_px;
    c.options = std::move(options);
    cases.push_back(std::move(c));
  };
  for (const std::string& p : pipeline_names()) {
    // The forward and deferred pipelines are shown with generated point lights.
    const bool lights = p == "forward" || p.starts_with("deferred");
    add("demo_" + p, demo_scene, p, 480, 270, lights ? Options{{"lights", "16"}} : Options{});
  }
  add("demo_deferred-subpass_unity", demo_scene, "deferred-subpass", 480, 270, {{"gbuffer", "unity"}, {"lights", "16"}});
  add("demo_forward_msaa4", demo_scene, "forward", 480, 270, {{"msaa", "4"}, {"lights", "16"}});
  for (const auto& [stem, relative] : {std::pair{"DamagedHelmet", "DamagedHelmet/DamagedHelmet.glb"},
                                       std::pair{"Duck", "Duck/Duck.gltf"}}) {
    for (const std::string p : {"lambert", "cartoon"}) {
      const auto names = pipeline_names();
      if (std::find(names.begin(), names.end(), p) == names.end()) continue;
      add(std::string(stem) + "_" + p, shared_assets / relative, p, 320, 240, {});
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
  settings.camera_index = c.camera_index;
  settings.width_px = c.width_px;
  settings.height_px = c.height_px;
  settings.context.threads = 2;
  for (const auto& [key, value] : c.options) settings.options.set(key, value);
  const RenderedFrame frame = render_frame(scene, settings);
  const Surface& color = *frame.outputs.color;
  if (color.format() != PixelFormat::RGBA8_SRGB && color.format() != PixelFormat::RGBA8_UNORM) {
    throw Error("golden case " + c.name + ": pipeline output is not 8-bit");
  }
  const std::filesystem::path reference = c.reference.empty() ? golden_dir / (c.name + ".png") : c.reference;
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
  const ImageRGBA32F expected = read_image(reference);
  const ImageComparison comparison =
      compare_images(image_from_rgba8(color.width(), color.height(), color.bytes()), expected, c.tolerance);
  if (!comparison.same_size) {
    write_failure(result.actual_image, color.bytes());
    result.status = GoldenResult::Status::Mismatch;
    result.message = "size " + std::to_string(color.width()) + "x" + std::to_string(color.height()) +
                     " differs from the reference's " + std::to_string(expected.width) + "x" +
                     std::to_string(expected.height);
    return result;
  }
  result.differing_pixels = comparison.pixels_over_tolerance;
  result.max_channel_difference = comparison.max_abs_difference;
  result.psnr_db = comparison.psnr_db;
  const std::string figures = "max channel difference " + format_difference(comparison.max_abs_difference) +
                              ", PSNR " + format_psnr(comparison.psnr_db) + " dB";
  if (comparison.matches) {
    if (comparison.differing_pixels > 0) {
      result.message = std::to_string(comparison.differing_pixels) + " pixels differ within the tolerance (" +
                       figures + ")";
    }
    return result;
  }
  result.status = GoldenResult::Status::Mismatch;
  result.diff_image = failure_dir / (c.name + ".diff.png");
  write_failure(result.actual_image, color.bytes());
  write_failure(result.diff_image, comparison.diff_rgba);
  result.message = std::to_string(result.differing_pixels) + " pixels differ (" + figures +
                   "); actual: " + result.actual_image.string() + ", diff: " + result.diff_image.string();
  return result;
}

}  // namespace ontile
