// Compares two render reports (`ontile diff A.json B.json`): what was run differently, the
// frame, category, pass and attachment byte deltas sorted by size, and the render-graph
// decisions that differ. This is how a user answers "why does design B move fewer bytes".
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ontile {

struct ByteDelta {
  std::string name;           // "bytes read", a category, a pass, or "pass / attachment"
  uint64_t a = 0, b = 0;      // bytes in each report (0 where absent)
  bool in_a = true, in_b = true;
  int64_t delta() const { return static_cast<int64_t>(b) - static_cast<int64_t>(a); }
  std::string percent() const;  // "-77.3%", "+0.0%", "new" (absent or 0 in A), "gone"
};

struct RunChange {
  std::string key, a, b;  // a "run" field (options.KEY for pipeline options) and its two values
};

struct ReportDiff {
  std::vector<RunChange> run_changes;
  // Each sorted by |delta|, largest first. attachment_totals sums each attachment name over the
  // passes, so designs whose passes differ still compare target by target.
  std::vector<ByteDelta> frame, categories, passes, attachments, attachment_totals;
  std::vector<std::string> decisions_only_in_a, decisions_only_in_b;  // "pass [resource]: decision: reason"
};

// Throws ontile::Error naming `name_a` or `name_b` when either is not an ontile render report.
ReportDiff diff_reports(const nlohmann::json& a, const nlohmann::json& b, const std::string& name_a,
                        const std::string& name_b);

// The diff as the CLI prints it, and as one self-contained HTML page (no scripts, no network).
std::string report_diff_text(const ReportDiff& diff, const std::string& name_a, const std::string& name_b);
std::string report_diff_html(const ReportDiff& diff, const std::string& name_a, const std::string& name_b);

}  // namespace ontile
