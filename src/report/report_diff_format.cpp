// Report comparison as text (the CLI's output) and as one self-contained HTML page (see
// report_diff.h). Byte counts are printed with thousands separators so digits line up.
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "report/report_diff.h"

#include "charts/svg_writer.h"

namespace ontile {
namespace {

std::string grouped(long long value) {
  const std::string digits = std::to_string(std::llabs(value));
  std::string out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return (value < 0 ? "-" : "") + out;
}

std::string signed_grouped(int64_t value) { return (value > 0 ? "+" : "") + grouped(value); }

struct Section {
  const char* title;
  const std::vector<ByteDelta>* rows;
};

std::vector<Section> sections(const ReportDiff& d) {
  return {{"frame", &d.frame},
          {"categories", &d.categories},
          {"passes", &d.passes},
          {"attachments over all passes (loaded + stored + resolved)", &d.attachment_totals},
          {"attachments per pass (pass / attachment)", &d.attachments}};
}

std::string html_escape(const std::string& text) { return xml_escape(text); }

}  // namespace

std::string report_diff_text(const ReportDiff& diff, const std::string& name_a, const std::string& name_b) {
  std::ostringstream out;
  out << "A = " << name_a << "\nB = " << name_b << "\n";
  if (!diff.run_changes.empty()) {
    out << "\nrun differs\n";
    for (const RunChange& c : diff.run_changes) out << "  " << c.key << ": " << c.a << " -> " << c.b << "\n";
  }
  char line[512];
  for (const Section& s : sections(diff)) {
    out << "\n" << s.title << "\n";
    std::snprintf(line, sizeof line, "  %-44s %16s %16s %16s %8s\n", "", "A bytes", "B bytes", "B - A", "change");
    out << line;
    for (const ByteDelta& r : *s.rows) {
      std::snprintf(line, sizeof line, "  %-44s %16s %16s %16s %8s\n", r.name.c_str(),
                    r.in_a ? grouped(static_cast<long long>(r.a)).c_str() : "-",
                    r.in_b ? grouped(static_cast<long long>(r.b)).c_str() : "-", signed_grouped(r.delta()).c_str(),
                    r.percent().c_str());
      out << line;
    }
  }
  out << "\nrender-graph decisions only in A: " << diff.decisions_only_in_a.size() << "\n";
  for (const std::string& d : diff.decisions_only_in_a) out << "  " << d << "\n";
  out << "render-graph decisions only in B: " << diff.decisions_only_in_b.size() << "\n";
  for (const std::string& d : diff.decisions_only_in_b) out << "  " << d << "\n";
  return out.str();
}

std::string report_diff_html(const ReportDiff& diff, const std::string& name_a, const std::string& name_b) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>ontile diff</title>\n"
         "<style>body{font-family:sans-serif;margin:2em;color:#222}table{border-collapse:collapse;margin-bottom:"
         "1.5em}td,th{padding:2px 10px;border-bottom:1px solid #ddd}td.n{text-align:right;font-family:monospace}"
         ".up{color:#b00}.down{color:#070}.bar{display:inline-block;height:0.8em;background:#89b}</style>"
         "</head><body>\n<h1>ontile diff</h1>\n<p>A = <code>"
      << html_escape(name_a) << "</code><br>B = <code>" << html_escape(name_b) << "</code></p>\n";
  if (!diff.run_changes.empty()) {
    out << "<h2>run differs</h2><table><tr><th>field</th><th>A</th><th>B</th></tr>\n";
    for (const RunChange& c : diff.run_changes) {
      out << "<tr><td>" << html_escape(c.key) << "</td><td>" << html_escape(c.a) << "</td><td>" << html_escape(c.b)
          << "</td></tr>\n";
    }
    out << "</table>\n";
  }
  for (const Section& s : sections(diff)) {
    uint64_t largest = 1;
    for (const ByteDelta& r : *s.rows) largest = std::max<uint64_t>(largest, std::llabs(r.delta()));
    out << "<h2>" << html_escape(s.title) << "</h2><table><tr><th>name</th><th>A bytes</th><th>B bytes</th>"
           "<th>B - A</th><th>change</th><th></th></tr>\n";
    for (const ByteDelta& r : *s.rows) {
      const int width_px = static_cast<int>(200 * static_cast<double>(std::llabs(r.delta())) / largest);
      out << "<tr><td>" << html_escape(r.name) << "</td><td class=\"n\">"
          << (r.in_a ? grouped(static_cast<long long>(r.a)) : "-") << "</td><td class=\"n\">"
          << (r.in_b ? grouped(static_cast<long long>(r.b)) : "-") << "</td><td class=\"n "
          << (r.delta() > 0 ? "up" : r.delta() < 0 ? "down" : "") << "\">" << signed_grouped(r.delta())
          << "</td><td class=\"n\">" << r.percent() << "</td><td><span class=\"bar\" style=\"width:" << width_px
          << "px\"></span></td></tr>\n";
    }
    out << "</table>\n";
  }
  for (const auto& [title, list] : {std::pair{"render-graph decisions only in A", &diff.decisions_only_in_a},
                                    std::pair{"render-graph decisions only in B", &diff.decisions_only_in_b}}) {
    out << "<h2>" << title << " (" << list->size() << ")</h2><ul>\n";
    for (const std::string& d : *list) out << "<li>" << html_escape(d) << "</li>\n";
    out << "</ul>\n";
  }
  out << "</body></html>\n";
  return out.str();
}

}  // namespace ontile
