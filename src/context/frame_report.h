// A frame's traffic report: the passes' reports, totals per category, and the two forms users
// read it in: a JSON document (a stable, documented interface) and a readable table.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "context/graph_report.h"
#include "tiler/pass_report.h"

namespace ontile {

struct FrameReport {
  std::vector<PassReport> passes;
  int threads = 1;
  double total_ms = 0.0;  // wall clock, not deterministic
  std::optional<GraphReport> graph;  // a render graph compiled with cull or merge

  uint64_t bytes_read() const;
  uint64_t bytes_written() const;
  // Bytes per traffic category ("attachment_load", "attachment_store", "resolve",
  // "vertex_index", "texture", "parameter_buffer_write", "parameter_buffer_read").
  std::map<std::string, uint64_t> bytes_by_category() const;
};

struct FrameReportOptions {
  // Per-tile statistics of every pass ("tile_stats" in each pass, columns of tiles_x x tiles_y
  // values; which thread ran each tile and when it started under "timing").
  bool tiles = false;
};

// The JSON report (docs/memory-model.md documents every field). Timings are included under
// "timing" and are the only part that differs between runs.
nlohmann::json frame_report_json(const FrameReport& frame, const FrameReportOptions& options = {});
// A readable table of the same numbers.
std::string frame_report_table(const FrameReport& frame);

}  // namespace ontile
