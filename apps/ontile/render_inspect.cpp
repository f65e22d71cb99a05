// The render verb's HTML page and attachment dumps (see render_inspect.h).
#include "render_inspect.h"

#include <filesystem>

#include "commands.h"
#include "report/attachment_images.h"
#include "report/frame_page.h"

namespace ontile::cli {

void check_inspect_options(const InspectOptions& o, bool aov) {
  if (aov && o.wanted()) {
    throw UsageError(std::string(o.html.empty() ? "--dump-attachments" : "--html") +
                     ": shows a pipeline's passes; --aov renders none");
  }
  if (o.tile_grid && o.dump_dir.empty()) throw UsageError("--tile-grid: draws over --dump-attachments files; give that too");
  if (!o.html.empty()) {
    if (std::filesystem::path(o.html).extension() != ".html") {
      throw UsageError("--html " + o.html + ": needs a .html file");
    }
    check_output_option("--html", o.html, false);
  }
  if (!o.dump_dir.empty()) {
    std::error_code ec;
    if (!std::filesystem::is_directory(o.dump_dir, ec)) {
      throw UsageError("--dump-attachments " + o.dump_dir + ": not an existing folder (folders are never created)");
    }
  }
}

size_t stage_inspection(const InspectOptions& o, const FrameOutputs& frame, const PassCapture& capture,
                        const nlohmann::json& run, const std::string& title, StagedOutputs& staged) {
  size_t files = 0;
  if (!o.dump_dir.empty()) {
    for (const CapturedPass& pass : capture.passes()) {
      const PassReport* report = pass.index < frame.report.passes.size() ? &frame.report.passes[pass.index] : nullptr;
      const bool grid = o.tile_grid && report && report->architecture == "tbdr";
      const int tile_w = grid ? report->tile_width_px : 0, tile_h = grid ? report->tile_height_px : 0;
      for (const CapturedAttachment& a : pass.attachments) {
        for (const Surface* s : {a.contents.get(), a.resolved.get()}) {
          if (!s) continue;
          const std::string name = s == a.resolved.get() ? a.name + "-resolved" : a.name;
          const std::filesystem::path path =
              std::filesystem::path(o.dump_dir) / attachment_file_name(pass.index, pass.name, name, s->format());
          stage_attachment_file(path, *s, tile_w, tile_h, staged);
          ++files;
        }
      }
    }
  }
  if (!o.html.empty()) {
    FramePage page;
    page.title = title;
    page.run = run;
    page.report = &frame.report;
    page.passes = &capture.passes();
    page.final_image = frame.color;
    staged.stage_text(o.html, frame_page_html(page));
  }
  return files;
}

}  // namespace ontile::cli
