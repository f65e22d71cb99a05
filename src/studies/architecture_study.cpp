// The architecture study (see architecture_study.h).
#include "studies/architecture_study.h"

#include <cstdio>

#include "pipelines/kit/pipeline.h"
#include "pipelines/kit/render_frame.h"
#include "studies/study_format.h"

namespace ontile {
namespace {

using study_format::category;
using study_format::fixed;
using study_format::kMiB;

// Antochi et al. 2004: tile-based rendering moved about 1.96x less external traffic than
// immediate mode on their workloads, and 32x32 tiles were the best trade-off.
constexpr double kPublishedImrOverTbdr = 1.96;
constexpr int kPublishedBestTilePx = 32;
constexpr int kImrBlockPx = 16;

ArchitectureRow render_row(const Scene& scene, const ArchitectureStudySettings& s, const std::string& pipeline,
                           bool imr, int tile_size_px) {
  RenderSettings settings;
  settings.pipeline = pipeline;
  settings.width_px = s.width_px;
  settings.height_px = s.height_px;
  settings.context.threads = s.threads;
  settings.context.tiler.tile_size_px = tile_size_px;
  settings.context.tiler.architecture = imr ? Architecture::Imr : Architecture::Tbdr;
  settings.context.tiler.parameter_cache.size_bytes = static_cast<uint32_t>(s.parameter_cache_kib) * 1024;
  const RenderedFrame frame = render_frame(scene, settings);
  const FrameReport& report = frame.outputs.report;
  ArchitectureRow row;
  row.pipeline = pipeline;
  row.imr = imr;
  row.tile_size_px = tile_size_px;
  row.bytes_read = report.bytes_read();
  row.bytes_written = report.bytes_written();
  row.bytes_by_category = report.bytes_by_category();
  if (!imr) {
    for (const PassReport& p : report.passes) row.tile_list_entries += p.geometry.tile_list_entries;
  }
  return row;
}

// The rows of one pipeline: its TBDR rows and its IMR row.
struct PipelineRows {
  std::vector<const ArchitectureRow*> tbdr;
  const ArchitectureRow* imr = nullptr;
  const ArchitectureRow* best() const {
    const ArchitectureRow* best = nullptr;
    for (const ArchitectureRow* r : tbdr) {
      if (!best || r->total() < best->total()) best = r;
    }
    return best;
  }
};

std::map<std::string, PipelineRows> by_pipeline(const std::vector<ArchitectureRow>& rows) {
  std::map<std::string, PipelineRows> out;
  for (const ArchitectureRow& r : rows) {
    PipelineRows& p = out[r.pipeline];
    if (r.imr) {
      p.imr = &r;
    } else {
      p.tbdr.push_back(&r);
    }
  }
  return out;
}

double ratio(uint64_t a, uint64_t b) { return b ? static_cast<double>(a) / static_cast<double>(b) : 0.0; }

}  // namespace

std::vector<ArchitectureRow> run_architecture_study(const Scene& scene, const ArchitectureStudySettings& s) {
  for (const std::string& pipeline : s.pipelines) make_pipeline(pipeline);  // unknown names fail before any work
  std::vector<ArchitectureRow> rows;
  const int total = static_cast<int>(s.pipelines.size() * (s.tile_sizes_px.size() + 1));
  int done = 0;
  for (const std::string& pipeline : s.pipelines) {
    for (const int tile : s.tile_sizes_px) {
      if (s.progress) s.progress(++done, total, pipeline + " tbdr " + std::to_string(tile));
      rows.push_back(render_row(scene, s, pipeline, false, tile));
    }
    if (s.progress) s.progress(++done, total, pipeline + " imr");
    rows.push_back(render_row(scene, s, pipeline, true, kImrBlockPx));
  }
  return rows;
}

std::string architecture_study_markdown(const std::vector<ArchitectureRow>& rows, const ArchitectureStudySettings& s,
                                        const std::string& scene_name) {
  std::string md = "Scene " + scene_name + ", " + std::to_string(s.width_px) + "x" + std::to_string(s.height_px) +
                   (s.parameter_cache_kib > 0 ? ", a " + std::to_string(s.parameter_cache_kib) +
                                                    " KiB parameter-buffer read cache"
                                              : "") +
                   "; MiB per frame (1 MiB = 2^20 bytes).\n\n";
  md += "| pipeline | architecture | tile | read | written | total | attachments | texture | vertex+index | "
        "param. write | param. read | tile-list entries |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const ArchitectureRow& r : rows) {
    const uint64_t attachments = category(r, "attachment_load") + category(r, "attachment_store") + category(r, "resolve");
    md += "| " + r.pipeline + " | " + (r.imr ? "IMR" : "TBDR") + " | " +
          (r.imr ? std::string("-") : std::to_string(r.tile_size_px) + "x" + std::to_string(r.tile_size_px)) + " | " +
          fixed(r.bytes_read / kMiB, 2) + " | " + fixed(r.bytes_written / kMiB, 2) + " | " +
          fixed(r.total() / kMiB, 2) + " | " + fixed(attachments / kMiB, 2) + " | " +
          fixed(category(r, "texture") / kMiB, 2) + " | " + fixed(category(r, "vertex_index") / kMiB, 2) + " | " +
          fixed(category(r, "parameter_buffer_write") / kMiB, 2) + " | " +
          fixed(category(r, "parameter_buffer_read") / kMiB, 2) + " | " +
          (r.imr ? std::string("-") : std::to_string(r.tile_list_entries)) + " |\n";
  }
  md += "\nIMR over TBDR, total bytes (Antochi et al. 2004: about " + fixed(kPublishedImrOverTbdr, 2) +
        "x; best tile " + std::to_string(kPublishedBestTilePx) + "x" + std::to_string(kPublishedBestTilePx) + "):\n\n";
  md += "| pipeline | tile | IMR / TBDR |\n|---|---|---|\n";
  for (const auto& [pipeline, p] : by_pipeline(rows)) {
    if (!p.imr) continue;
    for (const ArchitectureRow* r : p.tbdr) {
      md += "| " + pipeline + " | " + std::to_string(r->tile_size_px) + "x" + std::to_string(r->tile_size_px) + " | " +
            fixed(ratio(p.imr->total(), r->total()), 2) + " |\n";
    }
    if (const ArchitectureRow* best = p.best()) {
      md += "| " + pipeline + " | fewest bytes: " + std::to_string(best->tile_size_px) + "x" +
            std::to_string(best->tile_size_px) + " | " + fixed(ratio(p.imr->total(), best->total()), 2) + " |\n";
    }
  }
  return md;
}

nlohmann::json architecture_study_json(const std::vector<ArchitectureRow>& rows, const ArchitectureStudySettings& s,
                                       const std::string& scene_name) {
  nlohmann::json json_rows = nlohmann::json::array();
  for (const ArchitectureRow& r : rows) {
    nlohmann::json categories = nlohmann::json::object();
    for (const auto& [name, bytes] : r.bytes_by_category) categories[name] = bytes;
    json_rows.push_back({{"pipeline", r.pipeline},
                         {"architecture", r.imr ? "imr" : "tbdr"},
                         {"tile_size_px", r.tile_size_px},
                         {"bytes_read", r.bytes_read},
                         {"bytes_written", r.bytes_written},
                         {"by_category", categories},
                         {"tile_list_entries", r.tile_list_entries}});
  }
  nlohmann::json pipelines = nlohmann::json::object();
  for (const auto& [pipeline, p] : by_pipeline(rows)) {
    nlohmann::json ratios = nlohmann::json::object();
    if (p.imr) {
      for (const ArchitectureRow* r : p.tbdr) ratios[std::to_string(r->tile_size_px)] = ratio(p.imr->total(), r->total());
    }
    const ArchitectureRow* best = p.best();
    pipelines[pipeline] = {{"imr_over_tbdr", ratios},
                           {"best_tile_size_px", best ? nlohmann::json(best->tile_size_px) : nlohmann::json()}};
  }
  return {{"format", "ontile-study-architecture"},
          {"scene", scene_name},
          {"width_px", s.width_px},
          {"height_px", s.height_px},
          {"parameter_cache_kib", s.parameter_cache_kib},
          {"rows", json_rows},
          {"pipelines", pipelines},
          {"published", {{"imr_over_tbdr", kPublishedImrOverTbdr}, {"best_tile_size_px", kPublishedBestTilePx}}}};
}

}  // namespace ontile
