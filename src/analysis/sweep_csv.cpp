// CSV output of the sweep (see sweep_csv.h). Numbers use fixed precision so the file is stable
// apart from the timing columns.
#include "analysis/sweep_csv.h"

#include <cmath>
#include <cstdio>

namespace ontile {
namespace {

std::string fixed(double v, int decimals) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string optional_fixed(const std::optional<double>& v, int decimals) {
  return v ? fixed(*v, decimals) : "";
}

}  // namespace

std::vector<std::string> sweep_csv_columns() {
  return {"setting", "axis", "label", "msaa", "subpixel_bits", "depth", "reversed_z", "normals", "filter",
          "width_px", "height_px", "reference_spp", "frames", "time_ms_median", "time_ms_min", "cpu_ms_median", "bytes_read",
          "bytes_written", "bytes_per_frame", "normal_buffer_bytes", "color_psnr_db", "color_mean_abs_srgb8",
          "color_max_abs_srgb8", "id_mismatch_vs_default", "id_mismatch_vs_reference", "normal_pixels",
          "normal_mean_error_deg", "normal_max_error_deg", "normal_storage_mean_error_deg",
          "normal_storage_max_error_deg", "pareto_time", "pareto_bytes"};
}

std::string sweep_csv(const SweepResult& result) {
  std::string out;
  const std::vector<std::string> columns = sweep_csv_columns();
  for (size_t i = 0; i < columns.size(); ++i) out += (i ? "," : "") + columns[i];
  out += "\n";
  for (const SweepRow& r : result.rows) {
    const LambertOptions& o = r.setting.options;
    const std::vector<std::string> fields = {
        r.setting.name,
        r.setting.axis,
        r.setting.label,
        std::to_string(o.msaa_samples),
        std::to_string(r.setting.subpixel_bits),
        lambert_depth_name(o.depth_format),
        o.reversed_z ? "on" : "off",
        o.normals ? normal_storage_name(*o.normals) : "none",
        texture_filtering_name(o.filtering),
        std::to_string(result.width_px),
        std::to_string(result.height_px),
        std::to_string(result.reference_spp),
        std::to_string(r.frames),
        fixed(r.time_ms_median, 3),
        fixed(r.time_ms_min, 3),
        fixed(r.cpu_ms_median, 3),
        std::to_string(r.bytes_read),
        std::to_string(r.bytes_written),
        std::to_string(r.bytes_per_frame()),
        std::to_string(r.normal_buffer_bytes),
        fixed(r.color.psnr_db, 4),
        fixed(r.color.mean_abs, 5),
        std::to_string(r.color.max_abs),
        optional_fixed(r.id_mismatch_vs_default, 6),
        optional_fixed(r.id_mismatch_vs_reference, 6),
        r.normal ? std::to_string(r.normal->pixels) : "",
        r.normal ? fixed(r.normal->mean_deg, 5) : "",
        r.normal ? fixed(r.normal->max_deg, 5) : "",
        r.normal_storage ? fixed(r.normal_storage->mean_deg, 6) : "",
        r.normal_storage ? fixed(r.normal_storage->max_deg, 6) : "",
        r.pareto_time ? "1" : "0",
        r.pareto_bytes ? "1" : "0",
    };
    for (size_t i = 0; i < fields.size(); ++i) out += (i ? "," : "") + fields[i];
    out += "\n";
  }
  return out;
}

}  // namespace ontile
