// Golden-image regression: every pipeline on the bundled demo scene and a few real assets, or a
// user's own cases (golden_cases_file.h), rendered and compared with reference images, bit for
// bit or within a tolerance. A mismatch writes the actual image and a diff image;
// `ontile golden --update` rewrites the references on purpose (never CI).
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "golden/image_compare.h"

namespace ontile {

struct GoldenCase {
  std::string name;                 // file stem of the reference and of the failure images
  std::filesystem::path scene;
  std::string pipeline;
  int width_px = 480, height_px = 270;
  std::vector<std::pair<std::string, std::string>> options;  // pipeline options (--set)
  int camera_index = -1;            // -1: the scene's first camera, or one framing the scene
  std::filesystem::path reference;  // empty: golden_dir / (name + ".png")
  CompareTolerance tolerance;       // default: bit for bit
};

struct GoldenResult {
  GoldenCase golden_case;
  enum class Status { Match, Mismatch, Missing, Updated, Skipped } status = Status::Match;
  uint64_t differing_pixels = 0;    // pixels over the case's tolerance
  double max_channel_difference = 0.0;  // in 8-bit codes (float values for a float reference)
  double psnr_db = 0.0;
  std::filesystem::path actual_image, diff_image;  // written on mismatch or missing
  std::string message;
};

// The built-in cases: each registered pipeline on `demo_scene` (scenes/demo.glb), and lambert +
// cartoon on two shared assets (skipped when `shared_assets` does not exist).
std::vector<GoldenCase> golden_cases(const std::filesystem::path& demo_scene,
                                     const std::filesystem::path& shared_assets);

// Renders one case (2 threads) and compares it with its reference, or rewrites the reference
// (a PNG) when `update`. Mismatches write NAME.actual.png and NAME.diff.png into `failure_dir`.
GoldenResult run_golden_case(const GoldenCase& c, const std::filesystem::path& golden_dir,
                             const std::filesystem::path& failure_dir, bool update);

}  // namespace ontile
