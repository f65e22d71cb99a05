// What the verbs share (commands.h): size parsing with overflow checks, output-option checks and
// the staged outputs of a run.
#include <charconv>
#include <string_view>

#include "commands.h"
#include "raster/raster_types.h"

namespace ontile::cli {
namespace {

enum class SideParse { Ok, Malformed, TooLarge };

// One side of a size: decimal digits only (no sign, no spaces), 1..max_image_side_px(). The
// length is checked before std::from_chars, so 99999999999 is "too large" instead of wrapping
// around (it used to parse as 1215752191).
SideParse parse_side(std::string_view digits, int& side_px) {
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) {
    return SideParse::Malformed;
  }
  const size_t first_nonzero = digits.find_first_not_of('0');
  digits = first_nonzero == std::string_view::npos ? std::string_view("0") : digits.substr(first_nonzero);
  if (digits.size() > 9) return SideParse::TooLarge;  // > 999,999,999: above any maximum
  long long value = 0;
  std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (value > max_image_side_px()) return SideParse::TooLarge;
  side_px = static_cast<int>(value);
  return SideParse::Ok;
}

}  // namespace

int max_image_side_px() { return kMaxTargetSizePx; }

void parse_size(const std::string& text, int& width_px, int& height_px, const char* option) {
  const std::string prefix = std::string(option) + " '" + text + "': ";
  const size_t x = text.find('x');
  int w = 0, h = 0;
  const SideParse width = x == std::string::npos ? SideParse::Malformed : parse_side(std::string_view(text).substr(0, x), w);
  const SideParse height = x == std::string::npos ? SideParse::Malformed : parse_side(std::string_view(text).substr(x + 1), h);
  if (width == SideParse::Malformed || height == SideParse::Malformed) {
    throw UsageError(prefix + "expected WIDTHxHEIGHT with positive integers, e.g. 1920x1080");
  }
  if (width == SideParse::TooLarge || height == SideParse::TooLarge) {
    throw UsageError(prefix + "larger than the maximum " + std::to_string(max_image_side_px()) + "x" +
                     std::to_string(max_image_side_px()));
  }
  if (w < 1 || h < 1) throw UsageError(prefix + "width and height must be at least 1");
  width_px = w;
  height_px = h;
}

void check_output_option(const char* option, const std::string& path, bool allow_stdout) {
  if (is_stdout(path)) {
    if (allow_stdout) return;
    throw UsageError(std::string(option) + " -: standard output is only for reports; give a file name");
  }
  try {
    check_output_path(path);
  } catch (const Error& e) {
    throw UsageError(std::string(option) + " " + e.what());
  }
}

void check_distinct_outputs(const std::vector<std::pair<const char*, std::string>>& outputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    for (size_t j = i + 1; j < outputs.size(); ++j) {
      const std::string& a = outputs[i].second;
      if (a.empty() || is_stdout(a)) continue;
      std::error_code ec;
      if (a == outputs[j].second || std::filesystem::weakly_canonical(a, ec) ==
                                        std::filesystem::weakly_canonical(outputs[j].second, ec)) {
        throw UsageError(std::string(outputs[j].first) + " " + outputs[j].second + ": the same file as " +
                         outputs[i].first);
      }
    }
  }
}

void RunOutputs::text(const std::string& path, const std::string& text) {
  if (is_stdout(path)) {
    stdout_texts_.push_back(text);
  } else {
    files_.stage_text(path, text);
  }
}

void RunOutputs::commit() {
  files_.commit();
  for (const std::string& t : stdout_texts_) std::fputs(t.c_str(), stdout);
  std::fflush(stdout);
  stdout_texts_.clear();
}

}  // namespace ontile::cli
