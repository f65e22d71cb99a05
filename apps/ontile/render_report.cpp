// The render verb's self-describing report (see render_report.h).
#include "render_report.h"

#include "memory/transaction_elimination.h"

namespace ontile {

nlohmann::json render_report_json(const FrameReport& report, const RenderRun& run) {
  const RenderSettings& s = run.settings;
  const TilerConfig& tiler = s.context.tiler;
  nlohmann::json options = nlohmann::json::object();
  for (const auto& [key, value] : s.options.values()) options[key] = value;
  nlohmann::json json = frame_report_json(report, FrameReportOptions{.tiles = run.tiles});
  json["ontile_version"] = ONTILE_VERSION;
  json["run"] = {
      {"scene", run.scene},
      {"pipeline", s.pipeline},
      {"options", options},
      {"width_px", s.width_px},
      {"height_px", s.height_px},
      {"camera", s.camera_index},
      {"arch", tiler.architecture == Architecture::Imr ? "imr" : "tbdr"},
      {"render_graph", render_graph_mode_name(s.context.render_graph)},
      {"threads", s.context.threads},
      {"tile_size_px", tiler.tile_size_px},
      {"budget_bits_per_px", tiler.color_budget_bits_per_px},
      {"subpixel_bits", tiler.subpixel_bits},
      {"texture_cache_bytes", tiler.texture_cache.size_bytes},
      {"parameter_cache_bytes", tiler.parameter_cache.size_bytes},
      {"render_target_cache_bytes", tiler.render_target_cache.size_bytes},
      {"afbc", tiler.afbc},
      {"transaction_elimination", tiler.transaction_elimination != nullptr},
      {"transaction_elimination_targets", tiler.transaction_elimination
                                              ? nlohmann::json(crc_targets_name(tiler.transaction_elimination->targets()))
                                              : nlohmann::json()},
      {"gpu", run.gpu.empty() ? nlohmann::json() : nlohmann::json(run.gpu)},
      {"camera_pan_deg_per_frame", s.camera_pan_deg_per_frame},
      {"idvs", tiler.idvs},
      {"varying_precision", tiler.varying_precision == VaryingPrecision::Fp16 ? "fp16" : "fp32"},
      {"texture_compression", texture_compression_name(run.texture_compression)},
      {"aov", run.aov.empty() ? nlohmann::json() : nlohmann::json(run.aov)},
      {"frames", run.frames ? nlohmann::json(*run.frames) : nlohmann::json()},
      {"tiles", run.tiles}};
  return json;
}

}  // namespace ontile
