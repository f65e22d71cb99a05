// `ontile render --html`: one self-contained HTML page about a rendered frame (no network: images
// are PNG data URIs, charts inline SVG, style and script inline): the final image, the pass graph
// as written and as executed, every attachment after every pass, per-tile heatmaps, the traffic
// tables and a short text per pass on what stayed on chip and what went to memory.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "context/frame_report.h"
#include "report/pass_capture.h"
#include "tiler/surface.h"

namespace ontile {

struct FramePage {
  std::string title;                          // e.g. "scenes/demo.glb: cartoon, 1280x720"
  nlohmann::json run = nlohmann::json::object();  // the report's "run" section, shown as a table
  const FrameReport* report = nullptr;
  const std::vector<CapturedPass>* passes = nullptr;  // PassCapture::passes() of the same frame
  const Surface* final_image = nullptr;
  int thumbnail_width_px = 320;
  int heatmap_width_px = 360;
};

// The page; the same bytes for the same frame. Throws ontile::Error when report, passes or
// final_image is missing.
std::string frame_page_html(const FramePage& page);

}  // namespace ontile
