// The deferred study as JSON (see deferred_study.h): what scripts check instead of parsing the
// Markdown tables.
#include "studies/deferred_study.h"

#include "studies/study_format.h"

namespace ontile {
namespace {

// Two render passes over subpasses per frame on the same view, Mali-G76 (Vulkan-Samples
// render_subpasses; rates divided by each variant's frame rate, ../shared/REFERENCES.md).
constexpr double kMaliReadRatio = 2.00, kMaliWriteRatio = 3.93, kMaliTotalRatio = 2.49;

nlohmann::json variant_json(const StudyRow& r) {
  nlohmann::json options = nlohmann::json::object();
  for (const auto& [key, value] : r.variant.options) options[key] = value;
  nlohmann::json categories = nlohmann::json::object();
  for (const auto& [name, bytes] : r.bytes_by_category) categories[name] = bytes;
  return {{"label", r.variant.label},
          {"pipeline", r.variant.pipeline},
          {"options", options},
          {"passes", r.passes},
          {"tile_size_px", {r.tile_width_px, r.tile_height_px}},
          {"tiles", r.tiles},
          {"bytes_read", r.bytes_read},
          {"bytes_written", r.bytes_written},
          {"by_category", categories},
          {"median_frame_ms", r.median_frame_ms}};
}

}  // namespace

nlohmann::json deferred_study_json(const std::vector<StudyRow>& rows, const StudySettings& s,
                                   const std::string& scene_name) {
  nlohmann::json variants = nlohmann::json::array();
  for (const StudyRow& r : rows) variants.push_back(variant_json(r));
  nlohmann::json json = {{"format", "ontile-study-deferred"},
                         {"scene", scene_name},
                         {"width_px", s.width_px},
                         {"height_px", s.height_px},
                         {"tile_size_px", s.tile_size_px},
                         {"budget_bits_per_px", s.color_budget_bits_per_px},
                         {"lights", s.lights},
                         {"parameter_cache_kib", s.parameter_cache_kib},
                         {"gpu", s.gpu.empty() ? nlohmann::json() : nlohmann::json(s.gpu)},
                         {"varying_precision", s.varying_precision == VaryingPrecision::Fp16 ? "fp16" : "fp32"},
                         {"texture_compression", s.texture_compression},
                         {"variants", variants}};
  const StudyRow* two_passes = study_format::find_row(rows, std::string("two render passes"));
  const StudyRow* subpasses = study_format::find_row(rows, std::string("subpasses, transient"));
  if (two_passes && subpasses && subpasses->bytes_read > 0 && subpasses->bytes_written > 0) {
    const auto ratio = [](uint64_t a, uint64_t b) { return static_cast<double>(a) / static_cast<double>(b); };
    json["ratios"] = {
        {"of", "two render passes"},
        {"over", "subpasses, transient"},
        {"read", ratio(two_passes->bytes_read, subpasses->bytes_read)},
        {"write", ratio(two_passes->bytes_written, subpasses->bytes_written)},
        {"total", ratio(two_passes->bytes_read + two_passes->bytes_written,
                        subpasses->bytes_read + subpasses->bytes_written)},
        {"published_mali_g76", {{"read", kMaliReadRatio}, {"write", kMaliWriteRatio}, {"total", kMaliTotalRatio}}}};
  }
  return json;
}

}  // namespace ontile
