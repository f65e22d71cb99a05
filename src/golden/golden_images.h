// Golden-image regression: every pipeline on the bundled demo scene and a few real assets,
// rendered and compared bit for bit with PNGs in golden/. A mismatch writes the actual image and
// a diff image; `ontile golden --update` rewrites the references on purpose (never CI).
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace ontile {

struct GoldenCase {
  std::string name;                 // file stem in golden/
  std::filesystem::path scene;
  std::string pipeline;
  int width_px = 480, height_px = 270;
  std::vector<std::pair<std::string, std::string>> options;  // pipeline options (--set)
};

struct GoldenResult {
  GoldenCase golden_case;
  enum class Status { Match, Mismatch, Missing, Updated, Skipped } status = Status::Match;
  uint64_t differing_pixels = 0;
  int max_channel_difference = 0;
  std::filesystem::path actual_image, diff_image;  // written on mismatch or missing
  std::string message;
};

// The cases: each registered pipeline on scenes/demo.glb, and lambert + cartoon on two shared
// assets (skipped when `shared_assets` does not exist).
std::vector<GoldenCase> golden_cases(const std::filesystem::path& source_dir,
                                     const std::filesystem::path& shared_assets);

// Renders one case (2 threads) and compares it with golden_dir/NAME.png, or rewrites that file
// when `update`. Mismatches write NAME.actual.png and NAME.diff.png into `failure_dir`.
GoldenResult run_golden_case(const GoldenCase& c, const std::filesystem::path& golden_dir,
                             const std::filesystem::path& failure_dir, bool update);

}  // namespace ontile
