// `ontile compare ACTUAL EXPECTED [--max-abs N] [--max-pixels P] [--diff FILE.png]`: the
// golden-test contract for other test suites. Compares two images channel by channel, prints
// the pixels over the tolerance, the largest difference and the PSNR; exit 0 when they match,
// 1 when they do not (sizes differing included), 2 for a missing or unreadable file.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "commands.h"
#include "golden/image_compare.h"
#include "io/image_io.h"

namespace ontile::cli {
namespace {

struct CompareOptions {
  std::string actual, expected, diff;
  double max_abs = 0.0;
  uint64_t max_pixels = 0;
};

std::string size_text(const ImageRGBA32F& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

void run_compare(const CompareOptions& o) {
  if (!o.diff.empty()) {
    check_output_option("--diff", o.diff, false);
    if (std::filesystem::path(o.diff).extension() != ".png") {
      throw UsageError("--diff " + o.diff + ": the diff picture is a PNG (give a .png file name)");
    }
    check_distinct_outputs({{"--diff", o.diff}, {"ACTUAL", o.actual}, {"EXPECTED", o.expected}});
  }
  const ImageRGBA32F actual = read_image(o.actual);
  const ImageRGBA32F expected = read_image(o.expected);
  const ImageComparison c = compare_images(actual, expected, CompareTolerance{o.max_abs, o.max_pixels});
  if (!c.same_size) {
    throw MismatchError(o.actual + " is " + size_text(actual) + " but " + o.expected + " is " +
                        size_text(expected) + ": the sizes differ, nothing compared");
  }
  RunOutputs outputs;
  if (!o.diff.empty()) {
    write_png_rgba8(o.diff, actual.width, actual.height, c.diff_rgba, &outputs.files());
  }
  outputs.commit();
  std::printf("size: %s, %llu pixels; units: %s\n", size_text(actual).c_str(),
              static_cast<unsigned long long>(c.pixel_count), c.float_units ? "float values" : "8-bit codes");
  std::printf("pixels over tolerance: %llu (allowed %llu, tolerance %s); pixels differing: %llu\n",
              static_cast<unsigned long long>(c.pixels_over_tolerance),
              static_cast<unsigned long long>(o.max_pixels), format_difference(o.max_abs).c_str(),
              static_cast<unsigned long long>(c.differing_pixels));
  std::printf("max abs difference: %s\n", format_difference(c.max_abs_difference).c_str());
  std::printf("PSNR: %s dB\n", format_psnr(c.psnr_db).c_str());
  if (!o.diff.empty()) std::printf("wrote %s\n", o.diff.c_str());
  std::printf("%s\n", c.matches ? "match" : "MISMATCH");
  if (!c.matches) {
    throw MismatchError(o.actual + ": " + std::to_string(c.pixels_over_tolerance) + " pixels differ from " +
                        o.expected + " by more than " + format_difference(o.max_abs) + " (allowed " +
                        std::to_string(o.max_pixels) + ")");
  }
}

}  // namespace

void add_compare_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "compare", "Compare two images (PNG, EXR, ...) within a per-channel tolerance: exit 0 match, 1 mismatch, "
                 "2 error");
  auto o = std::make_shared<CompareOptions>();
  cmd->add_option("ACTUAL", o->actual, "The image under test")->required();
  cmd->add_option("EXPECTED", o->expected, "The reference image")->required();
  cmd->add_option("--max-abs", o->max_abs,
                  "Largest per-channel difference a pixel may have: 8-bit codes (0-255) for integer images, "
                  "values for float images (EXR); default 0")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-pixels", o->max_pixels, "How many pixels may exceed --max-abs; default 0");
  cmd->add_option("--diff", o->diff, "Write a diff picture (PNG): red over the tolerance, blue within it");
  cmd->callback([o] { run_compare(*o); });
}

}  // namespace ontile::cli
