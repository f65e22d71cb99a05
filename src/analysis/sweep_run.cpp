// The accuracy sweep (see sweep_run.h).
#include "analysis/sweep_run.h"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "analysis/pareto_front.h"
#include "aov/aov_pass.h"
#include "pipelines/lambert/lambert_pipeline.h"
#include "pipelines/kit/render_frame.h"
#include "util/error.h"

namespace ontile {
namespace {

struct RenderedSetting {
  std::unique_ptr<RenderContext> context;  // owns the surfaces
  LambertFrame frame;
  double wall_ms = 0.0;
  double cpu_ms = 0.0;  // process CPU time, all threads
};

double cpu_ms_now() { return 1000.0 * static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

RenderedSetting render_setting(const Scene& scene, const Camera& camera, const SweepConfig& config,
                               const SweepSetting& setting, const LambertOptions& options) {
  ContextConfig context_config;
  context_config.threads = config.threads;
  context_config.tiler.subpixel_bits = setting.subpixel_bits;
  RenderedSetting r;
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_ms_now();
  r.context = std::make_unique<RenderContext>(context_config);
  FrameInputs inputs;
  inputs.scene = &scene;
  inputs.camera = camera;
  inputs.width_px = config.width_px;
  inputs.height_px = config.height_px;
  r.frame = render_lambert(*r.context, inputs, options);
  r.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  r.cpu_ms = cpu_ms_now() - cpu_start;
  return r;
}

// The same setting with a primitive-id target (and its normal target, if any): what the
// visibility and normal measures read. Not timed.
RenderedSetting render_diagnostics(const Scene& scene, const Camera& camera, const SweepConfig& config,
                                   const SweepSetting& setting) {
  LambertOptions options = setting.options;
  options.primitive_id_output = true;
  return render_setting(scene, camera, config, setting, options);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

void mark_pareto_rows(std::vector<SweepRow>& rows) {
  std::vector<ParetoPoint> by_time, by_bytes;
  for (const SweepRow& r : rows) {
    by_time.push_back({r.time_ms_median, r.color.mean_abs});
    by_bytes.push_back({double(r.bytes_per_frame()), r.color.mean_abs});
  }
  for (SweepRow& r : rows) r.pareto_time = r.pareto_bytes = false;
  for (size_t i : pareto_front(by_time)) rows[i].pareto_time = true;
  for (size_t i : pareto_front(by_bytes)) rows[i].pareto_bytes = true;
}

SweepResult run_sweep(const Scene& scene, const SweepConfig& config, const std::vector<SweepSetting>& settings,
                      const std::function<void(const SweepRow&)>& progress) {
  if (config.width_px <= 0 || config.height_px <= 0 || config.width_px > kMaxTargetSizePx ||
      config.height_px > kMaxTargetSizePx) {
    throw Error("sweep: image size " + std::to_string(config.width_px) + "x" + std::to_string(config.height_px) +
                " outside 1.." + std::to_string(kMaxTargetSizePx));
  }
  if (config.frames < 1) throw Error("sweep: " + std::to_string(config.frames) + " frames (at least 1)");
  check_samples_per_pixel(config.reference_spp);
  for (const SweepSetting& s : settings) check_lambert_options(s.options);

  SweepResult result;
  result.width_px = config.width_px;
  result.height_px = config.height_px;
  result.reference_spp = config.reference_spp;
  const Camera camera = select_camera(scene, config.camera_index);
  const auto reference_start = std::chrono::steady_clock::now();
  const LambertReferenceScene reference_scene =
      make_lambert_reference_scene(scene, camera, config.width_px, config.height_px);
  const ReferenceImage reference =
      render_reference(reference_scene, config.width_px, config.height_px, config.reference_spp, config.steps);
  result.reference_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - reference_start).count();

  // The default setting's ids, and the float (RGBA32F) normals of the same geometry: what a
  // normal buffer stores before its format quantises it.
  const RenderedSetting baseline = render_diagnostics(scene, camera, config, SweepSetting{});
  RenderSettings aov_settings;
  aov_settings.camera_index = config.camera_index;
  aov_settings.width_px = config.width_px;
  aov_settings.height_px = config.height_px;
  aov_settings.context.threads = config.threads;
  const AovFrame float_normals = render_aov_frame(scene, aov_settings, {AovKind::Normal, AovKind::PrimitiveId});

  // Untimed: the error measures, from one frame of each setting (images are deterministic).
  const int renders_total = static_cast<int>(settings.size()) * (1 + config.frames);
  int renders_done = 0;
  for (const SweepSetting& setting : settings) {
    if (config.steps) config.steps(++renders_done, renders_total, setting.name + " (error)");
    SweepRow row;
    row.setting = setting;
    row.frames = config.frames;
    const RenderedSetting measured = render_setting(scene, camera, config, setting, setting.options);
    row.bytes_read = measured.frame.report.bytes_read();
    row.bytes_written = measured.frame.report.bytes_written();
    if (measured.frame.normals) row.normal_buffer_bytes = measured.frame.normals->size_bytes();
    row.color = color_error(*measured.frame.color, reference);
    if (setting.options.msaa_samples == 1) {
      const RenderedSetting diagnostics = render_diagnostics(scene, camera, config, setting);
      const Surface& ids = *diagnostics.frame.primitive_ids;
      row.id_mismatch_vs_default = primitive_id_mismatch(ids, *baseline.frame.primitive_ids);
      row.id_mismatch_vs_reference = primitive_id_mismatch(ids, reference);
      if (setting.options.normals) {
        row.normal = normal_error(*diagnostics.frame.normals, *setting.options.normals, ids, reference);
        row.normal_storage = normal_error(*diagnostics.frame.normals, *setting.options.normals, ids,
                                          *float_normals.surfaces[0], *float_normals.surfaces[1]);
      }
    }
    result.rows.push_back(std::move(row));
  }
  // Timed: round robin over the settings, so a change in machine load during the sweep spreads
  // over all of them instead of biasing the ones measured at that moment.
  std::vector<std::vector<double>> times(settings.size()), cpu_times(settings.size());
  for (int f = 0; f < config.frames; ++f) {
    for (size_t i = 0; i < settings.size(); ++i) {
      if (config.steps) config.steps(++renders_done, renders_total, settings[i].name + " (timed)");
      const RenderedSetting timed = render_setting(scene, camera, config, settings[i], settings[i].options);
      times[i].push_back(timed.wall_ms);
      cpu_times[i].push_back(timed.cpu_ms);
    }
  }
  for (size_t i = 0; i < settings.size(); ++i) {
    result.rows[i].time_ms_median = median(times[i]);
    result.rows[i].time_ms_min = *std::min_element(times[i].begin(), times[i].end());
    result.rows[i].cpu_ms_median = median(cpu_times[i]);
    if (progress) progress(result.rows[i]);
  }
  mark_pareto_rows(result.rows);
  return result;
}

}  // namespace ontile
