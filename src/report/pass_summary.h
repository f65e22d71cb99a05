// A few generated sentences per pass for the HTML report: what stayed in tile memory (transient
// attachments, merged subpasses, clears and discards that cost no bytes) and what went to or
// came from external memory (loads, stores, resolves, texture, parameter-buffer and vertex bytes).
#pragma once
#include <string>
#include <vector>

#include "context/frame_report.h"
#include "report/pass_capture.h"

namespace ontile {

struct PassSummary {
  std::vector<std::string> on_chip;    // one phrase each
  std::vector<std::string> to_memory;  // one phrase each, with bytes
};

// `captured` (load/store actions, subpass count) and `graph` (subpass names) may be null.
PassSummary summarize_pass(const PassReport& pass, const CapturedPass* captured, const GraphReport* graph);
// "On chip: a; b. Memory: c; d." (plain text).
std::string pass_summary_text(const PassSummary& summary);

}  // namespace ontile
