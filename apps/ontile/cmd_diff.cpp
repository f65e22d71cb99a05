// `ontile diff A.json B.json [--html FILE]`: compares two render reports (report/report_diff.h).
// Exit 0 whatever the differences: a diff is information, not a verdict (`golden` judges).
#include <fstream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "report/report_diff.h"

namespace ontile::cli {
namespace {

struct DiffOptions {
  std::string a, b, html;
};

nlohmann::json read_report(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot read the report");
  std::stringstream text;
  text << in.rdbuf();
  try {
    return nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {
    throw Error(path + ": not JSON (" + e.what() + ")");
  }
}

void run_diff(const DiffOptions& o) {
  if (!o.html.empty()) {
    check_output_option("--html", o.html, false);
    check_distinct_outputs({{"--html", o.html}, {"A", o.a}, {"B", o.b}});
  }
  const ReportDiff diff = diff_reports(read_report(o.a), read_report(o.b), o.a, o.b);
  RunOutputs outputs;
  if (!o.html.empty()) outputs.text(o.html, report_diff_html(diff, o.a, o.b));
  outputs.commit();
  std::fputs(report_diff_text(diff, o.a, o.b).c_str(), stdout);
  if (!o.html.empty()) std::printf("wrote %s\n", o.html.c_str());
}

}  // namespace

void add_diff_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "diff", "Compare two render reports (render --report): byte deltas per frame, category, pass and "
              "attachment, largest first, and the render-graph decisions that differ");
  auto o = std::make_shared<DiffOptions>();
  cmd->add_option("A", o->a, "The first report (the baseline)")->required();
  cmd->add_option("B", o->b, "The second report")->required();
  cmd->add_option("--html", o->html, "Also write the comparison as a self-contained HTML page");
  cmd->callback([o] { run_diff(*o); });
}

}  // namespace ontile::cli
