// `render --html FILE` and `render --dump-attachments DIR [--tile-grid]`: what the render verb
// writes besides the image and the JSON, from the passes captured while the frame ran.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "pipelines/kit/render_frame.h"
#include "report/pass_capture.h"
#include "util/atomic_file.h"

namespace ontile::cli {

struct InspectOptions {
  std::string html;       // --html: the page, empty for none
  std::string dump_dir;   // --dump-attachments: an existing folder, empty for none
  bool tile_grid = false; // --tile-grid: the grid over the dumped attachments
  bool wanted() const { return !html.empty() || !dump_dir.empty(); }
};

// Usage errors before any work: --html must end in .html and be writable, the dump folder must
// exist, --tile-grid needs --dump-attachments, and neither works with --aov.
void check_inspect_options(const InspectOptions& o, bool aov);

// Stages the page and the attachment files into `staged` (committed with the run's other outputs).
// Returns how many attachment files were staged.
size_t stage_inspection(const InspectOptions& o, const FrameOutputs& frame, const PassCapture& capture,
                        const nlohmann::json& run, const std::string& title, StagedOutputs& staged);

}  // namespace ontile::cli
