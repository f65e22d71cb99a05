// The architecture study (docs/fidelity.md, after Antochi et al., "Memory bandwidth requirements
// of tile-based rendering", SAMOS 2004): one scene rendered as a tile-based GPU at several tile
// sizes and as an immediate-mode GPU, reporting external bytes per frame by category, the IMR
// over TBDR ratio at each tile size, and the tile size that moves the fewest bytes.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "util/progress.h"

namespace ontile {

struct ArchitectureStudySettings {
  int width_px = 1920, height_px = 1080;
  std::vector<int> tile_sizes_px = {8, 16, 32, 64};
  std::vector<std::string> pipelines = {"lambert"};
  int threads = 0;
  int parameter_cache_kib = 0;  // an L2 model for parameter-buffer reads (TBDR; 0: none)
  ProgressCallback progress;    // optional: hears of every rendered frame
};

struct ArchitectureRow {
  std::string pipeline;
  bool imr = false;
  int tile_size_px = 0;  // TBDR tile size (the IMR model walks triangles in blocks of 16)
  uint64_t bytes_read = 0, bytes_written = 0;
  std::map<std::string, uint64_t> bytes_by_category;
  uint64_t tile_list_entries = 0;  // TBDR: (tile, triangle) pairs binned
  uint64_t total() const { return bytes_read + bytes_written; }
};

// Per pipeline: one TBDR row per tile size, in the given order, then one IMR row. Throws
// ontile::Error for an unknown pipeline or a tile size the tiler refuses.
std::vector<ArchitectureRow> run_architecture_study(const Scene& scene, const ArchitectureStudySettings& settings);

// Markdown: bytes per row, then per pipeline IMR / TBDR at each tile size and the TBDR tile size
// with the fewest bytes, beside Antochi et al.'s 1.96x and 32x32.
std::string architecture_study_markdown(const std::vector<ArchitectureRow>& rows,
                                        const ArchitectureStudySettings& settings, const std::string& scene_name);
// The same as JSON: settings, rows, and per pipeline `imr_over_tbdr` (tile size -> ratio) and
// `best_tile_size_px`.
nlohmann::json architecture_study_json(const std::vector<ArchitectureRow>& rows,
                                       const ArchitectureStudySettings& settings, const std::string& scene_name);

}  // namespace ontile
