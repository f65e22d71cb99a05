// The deferred-shading bandwidth study (see deferred_study.h).
#include "studies/deferred_study.h"

#include <algorithm>
#include <cstdio>

#include "pipelines/kit/render_frame.h"
#include "tiler/gpu_presets.h"
#include "studies/study_format.h"
#include "util/error.h"

namespace ontile {
namespace {

using study_format::category;
using study_format::find_row;
using study_format::fixed;
using study_format::kMiB;

// Published Mali-G76 measurements, Khronos Vulkan-Samples (render_subpasses tutorial; rates in
// MiB/s at 2220x1080, each at its own frame rate), as summed up in ../shared/REFERENCES.md.
struct Published {
  const char* label;
  double read_mib_s, write_mib_s;
};
constexpr Published kMali[] = {
    {"two render passes", 949.4, 641.1},
    {"subpasses, transient", 389.0, 127.4},
    {"subpasses, transient off", 403.6, 138.5},
    {"subpasses, G-buffer > 128 bit", 310.8, 252.9},
};

std::string mib(uint64_t bytes) {
  char s[32];
  std::snprintf(s, sizeof s, "%.2f", bytes / kMiB);
  return s;
}


// The application's choices when not the defaults, for the table's heading.
std::string application_choices(const StudySettings& s) {
  std::string text;
  if (s.varying_precision == VaryingPrecision::Fp16) text += ", fp16 varyings";
  if (s.texture_compression != "none") text += ", " + s.texture_compression + " textures";
  return text;
}

}  // namespace

std::vector<StudyVariant> deferred_study_variants(int lights) {
  const std::string n = std::to_string(lights);
  return {
      // The sample's "two render passes": the G-buffer stored, then loaded as input attachments.
      {"two render passes", "deferred-subpass",
       {{"gbuffer", "vulkan-samples"}, {"lights", n}, {"technique", "render-passes"}}},
      {"subpasses, transient", "deferred-subpass", {{"gbuffer", "vulkan-samples"}, {"lights", n}}},
      {"subpasses, transient off", "deferred-subpass", {{"gbuffer", "vulkan-samples"}, {"lights", n}, {"transient", "off"}}},
      {"subpasses, G-buffer stored", "deferred-subpass",
       {{"gbuffer", "vulkan-samples"}, {"lights", n}, {"transient", "off"}, {"gbuffer_store", "store"}}},
      {"subpasses, G-buffer > 128 bit", "deferred-subpass", {{"gbuffer", "vulkan-samples-large"}, {"lights", n}}},
      {"forward", "forward", {{"lights", n}}},
      {"forward 4x MSAA, on-tile resolve", "forward", {{"lights", n}, {"msaa", "4"}}},
      {"forward 4x MSAA, separate resolve", "forward", {{"lights", n}, {"msaa", "4"}, {"resolve", "separate"}}},
      // The classic renderer: the lighting pass samples the stored G-buffer as textures.
      {"two render passes, G-buffer sampled", "deferred-classic", {{"gbuffer", "vulkan-samples"}, {"lights", n}}},
  };
}

std::vector<StudyRow> run_study(const Scene& scene, const StudySettings& s, const std::vector<StudyVariant>& variants) {
  if (s.frames < 1) throw Error("study: frames must be at least 1");
  std::vector<StudyRow> rows;
  int frames_done = 0;
  const int frames_total = static_cast<int>(variants.size()) * s.frames;
  for (const StudyVariant& v : variants) {
    RenderSettings settings;
    settings.pipeline = v.pipeline;
    settings.width_px = s.width_px;
    settings.height_px = s.height_px;
    settings.context.threads = s.threads;
    settings.context.tiler.tile_size_px = s.tile_size_px;
    settings.context.tiler.color_budget_bits_per_px = s.color_budget_bits_per_px;
    settings.context.tiler.parameter_cache.size_bytes = static_cast<uint32_t>(s.parameter_cache_kib) * 1024;
    if (!s.gpu.empty()) {
      const GpuPreset* preset = find_gpu_preset(s.gpu);
      if (!preset) throw Error("study: unknown GPU preset '" + s.gpu + "' (known: " + gpu_preset_names() + ")");
      apply_gpu_preset(*preset, settings.context.tiler);
    }
    settings.context.tiler.varying_precision = s.varying_precision;
    for (const auto& [key, value] : v.options) settings.options.set(key, value);
    StudyRow row;
    row.variant = v;
    std::vector<double> times;
    // Transaction elimination compares with the previous frame: one frame first fills the CRCs.
    if (settings.context.tiler.transaction_elimination) render_frame(scene, settings);
    for (int f = 0; f < s.frames; ++f) {
      if (s.progress) s.progress(++frames_done, frames_total, v.label);
      const RenderedFrame frame = render_frame(scene, settings);
      const FrameReport& r = frame.outputs.report;
      times.push_back(r.total_ms);
      if (f > 0) continue;
      row.bytes_read = r.bytes_read();
      row.bytes_written = r.bytes_written();
      row.bytes_by_category = r.bytes_by_category();
      row.passes = static_cast<int>(r.passes.size());
      for (const PassReport& p : r.passes) row.tiles += p.tiles_total;
      if (!r.passes.empty()) {
        row.tile_width_px = r.passes[0].tile_width_px;
        row.tile_height_px = r.passes[0].tile_height_px;
      }
    }
    std::sort(times.begin(), times.end());
    row.median_frame_ms = times[times.size() / 2];
    rows.push_back(row);
  }
  return rows;
}

std::string deferred_study_markdown(const std::vector<StudyRow>& rows, const StudySettings& s,
                                    const std::string& scene_name) {
  std::string md;
  if (!s.gpu.empty()) {
    md += "Scene " + scene_name + ", " + std::to_string(s.width_px) + "x" + std::to_string(s.height_px) + ", --gpu " +
          s.gpu + " (" + find_gpu_preset(s.gpu)->description + "), " + std::to_string(s.lights) +
          " point lights" + application_choices(s) + "; MiB per frame (1 MiB = 2^20 bytes).\n\n";
  } else {
  md += "Scene " + scene_name + ", " + std::to_string(s.width_px) + "x" + std::to_string(s.height_px) + ", " +
        std::to_string(s.tile_size_px) + "x" + std::to_string(s.tile_size_px) + " tiles, " +
        std::to_string(s.color_budget_bits_per_px) + "-bit colour budget, " + std::to_string(s.lights) +
        " point lights" +
        (s.parameter_cache_kib > 0 ? ", a " + std::to_string(s.parameter_cache_kib) + " KiB parameter-buffer read cache" : "") +
        application_choices(s) + "; MiB per frame (1 MiB = 2^20 bytes).\n\n";
  }
  md += "| variant | passes | tile | tiles | read | written | attachment load | attachment store | resolve | texture | "
        "vertex+index | param. write | param. read | frame ms |\n";
  md += "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const StudyRow& r : rows) {
    md += "| " + r.variant.label + " | " + std::to_string(r.passes) + " | " + std::to_string(r.tile_width_px) + "x" +
          std::to_string(r.tile_height_px) + " | " + std::to_string(r.tiles) + " | " + mib(r.bytes_read) + " | " +
          mib(r.bytes_written) + " | " + mib(category(r, "attachment_load")) + " | " +
          mib(category(r, "attachment_store")) + " | " + mib(category(r, "resolve")) + " | " +
          mib(category(r, "texture")) + " | " + mib(category(r, "vertex_index")) + " | " +
          mib(category(r, "parameter_buffer_write")) + " | " + mib(category(r, "parameter_buffer_read")) + " | " +
          fixed(r.median_frame_ms, 0) + " |\n";
  }
  // Ratios against the subpass variant: the published rates were measured at different frame
  // rates, so only ratios compare.
  const StudyRow* base = find_row(rows, "subpasses, transient");
  const Published& mali_base = kMali[1];
  if (base) {
    md += "\nAgainst the published Mali-G76 figures (ratios to \"subpasses, transient\"; Mali in MiB/s, ours in "
          "MiB/frame):\n\n";
    md += "| variant | Mali read | Mali write | Mali read ratio | Mali write ratio | Mali total ratio | ours read | "
          "ours written | ours read ratio | ours write ratio | ours total ratio |\n";
    md += "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Published& m : kMali) {
      const StudyRow* r = find_row(rows, m.label);
      if (!r) continue;
      const double ours_total = double(r->bytes_read + r->bytes_written) / double(base->bytes_read + base->bytes_written);
      const double mali_total = (m.read_mib_s + m.write_mib_s) / (mali_base.read_mib_s + mali_base.write_mib_s);
      md += "| " + std::string(m.label) + " | " + fixed(m.read_mib_s, 1) + " | " + fixed(m.write_mib_s, 1) + " | " +
            fixed(m.read_mib_s / mali_base.read_mib_s, 2) + " | " + fixed(m.write_mib_s / mali_base.write_mib_s, 2) +
            " | " + fixed(mali_total, 2) + " | " + mib(r->bytes_read) + " | " + mib(r->bytes_written) + " | " +
            fixed(double(r->bytes_read) / base->bytes_read, 2) + " | " +
            fixed(double(r->bytes_written) / base->bytes_written, 2) + " | " + fixed(ours_total, 2) + " |\n";
    }
  }
  const StudyRow* forward = find_row(rows, "forward");
  const StudyRow* on_tile = find_row(rows, "forward 4x MSAA, on-tile resolve");
  const StudyRow* separate = find_row(rows, "forward 4x MSAA, separate resolve");
  if (forward && on_tile && separate) {
    const double total = double(forward->bytes_read + forward->bytes_written);
    const double on_tile_extra = double(on_tile->bytes_read + on_tile->bytes_written) - total;
    const double separate_extra = double(separate->bytes_read + separate->bytes_written) - total;
    md += "\n4x MSAA against forward without MSAA (published: about +3% for the on-tile resolve, several GB/s for a "
          "separate resolve at 1080p60):\n\n";
    md += "| resolve | extra MiB/frame | extra % | extra GiB/s at 60 fps |\n|---|---|---|---|\n";
    md += "| on tile | " + fixed(on_tile_extra / kMiB, 2) + " | " + fixed(100.0 * on_tile_extra / total, 1) + " | " +
          fixed(on_tile_extra * 60.0 / (kMiB * 1024.0), 2) + " |\n";
    md += "| separate pass | " + fixed(separate_extra / kMiB, 2) + " | " + fixed(100.0 * separate_extra / total, 1) +
          " | " + fixed(separate_extra * 60.0 / (kMiB * 1024.0), 2) + " |\n";
  }
  return md;
}

}  // namespace ontile
