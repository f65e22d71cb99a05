// The accuracy sweep: renders the 64-spp ray-traced reference once, then every setting of
// sweep_settings.h with the lambert pipeline, measuring time per frame, external bytes per
// frame and the error against the reference; marks the Pareto-optimal settings.
#pragma once
#include "util/progress.h"
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "analysis/sweep_metrics.h"
#include "analysis/sweep_settings.h"
#include "scene/scene.h"

namespace ontile {

struct SweepConfig {
  int width_px = 640, height_px = 360;
  int camera_index = -1;    // as RenderSettings
  int frames = 5;           // timed frames per setting, round robin (the median is reported)
  int threads = 0;          // rasterizer threads, 0 = all cores
  int reference_spp = 64;   // a perfect square (render_reference)
  ProgressCallback steps;   // optional: hears of the reference rows, then of every rendered setting
};

struct SweepRow {
  SweepSetting setting;
  int frames = 0;
  double time_ms_median = 0.0, time_ms_min = 0.0;  // wall clock of a whole frame
  // Process CPU time of a frame summed over all threads: less sensitive than the wall clock to
  // other processes competing for the cores, but it counts idle spinning of worker threads.
  double cpu_ms_median = 0.0;
  uint64_t bytes_read = 0, bytes_written = 0;      // FrameReport, per frame
  uint64_t normal_buffer_bytes = 0;                // the stored normal target, 0 without one
  ColorError color;
  // Primitive-id comparisons; absent with MSAA (ids are single-sample).
  std::optional<double> id_mismatch_vs_default;    // vs the default setting's ids
  std::optional<double> id_mismatch_vs_reference;  // vs the reference's primitive-id AOV
  std::optional<NormalError> normal;               // with a normal buffer: vs the reference
  std::optional<NormalError> normal_storage;       // the same, vs the unquantised float normals
  bool pareto_time = false;   // on the front of (time_ms_median, color.mean_abs)
  bool pareto_bytes = false;  // on the front of (bytes per frame, color.mean_abs)
  uint64_t bytes_per_frame() const { return bytes_read + bytes_written; }
};

struct SweepResult {
  int width_px = 0, height_px = 0, reference_spp = 0;
  double reference_ms = 0.0;
  std::vector<SweepRow> rows;  // in settings order
};

// Throws ontile::Error for bad sizes, frame counts below 1, sample counts render_reference
// rejects, or a setting the pipeline rejects. `progress` (optional) sees each row when measured.
SweepResult run_sweep(const Scene& scene, const SweepConfig& config, const std::vector<SweepSetting>& settings,
                      const std::function<void(const SweepRow&)>& progress = {});

// Sets pareto_time and pareto_bytes of every row (pareto_front.h).
void mark_pareto_rows(std::vector<SweepRow>& rows);

}  // namespace ontile
