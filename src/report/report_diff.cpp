// Report comparison (see report_diff.h): reading two reports into matched byte rows.
#include "report/report_diff.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "util/error.h"

namespace ontile {
namespace {

using Json = nlohmann::json;

void check_report(const Json& report, const std::string& name) {
  if (!report.is_object() || report.value("format", "") != "ontile-report") {
    throw Error(name + ": not an ontile render report (no \"format\": \"ontile-report\")");
  }
  for (const char* key : {"frame", "passes"}) {
    if (!report.contains(key)) throw Error(name + ": report without \"" + std::string(key) + "\"");
  }
}

uint64_t bytes_of(const Json& object, const std::initializer_list<const char*> keys) {
  uint64_t sum = 0;
  for (const char* key : keys) sum += object.value(key, uint64_t{0});
  return sum;
}

// Pass names may repeat (a pipeline may run "blit" twice): the k-th "blit" is "blit #k" from the
// second on, so each pass of A meets its counterpart in B.
std::vector<std::string> unique_pass_names(const Json& passes) {
  std::map<std::string, int> seen;
  std::vector<std::string> names;
  for (const Json& p : passes) {
    const std::string name = p.value("name", "");
    const int k = ++seen[name];
    names.push_back(k == 1 ? name : name + " #" + std::to_string(k));
  }
  return names;
}

// Rows keyed by name, in the order they first appear (A's, then B's new ones).
class Rows {
 public:
  void add(const std::string& name, uint64_t bytes, bool from_a) {
    auto it = index_.find(name);
    if (it == index_.end()) {
      it = index_.emplace(name, rows_.size()).first;
      ByteDelta row;
      row.name = name;
      row.in_a = row.in_b = false;
      rows_.push_back(row);
    }
    ByteDelta& row = rows_[it->second];
    (from_a ? row.a : row.b) += bytes;
    (from_a ? row.in_a : row.in_b) = true;
  }
  // Largest change first; equal changes keep their report order.
  std::vector<ByteDelta> sorted() const {
    std::vector<ByteDelta> out = rows_;
    std::stable_sort(out.begin(), out.end(), [](const ByteDelta& x, const ByteDelta& y) {
      return std::llabs(x.delta()) > std::llabs(y.delta());
    });
    return out;
  }

 private:
  std::vector<ByteDelta> rows_;
  std::map<std::string, size_t> index_;
};

struct AllRows {
  Rows frame, categories, passes, attachments, attachment_totals;
};

void add_report(const Json& report, bool from_a, AllRows& rows) {
  Rows& frame = rows.frame;
  Rows& categories = rows.categories;
  Rows& passes = rows.passes;
  const Json& f = report["frame"];
  frame.add("bytes read", f.value("bytes_read", uint64_t{0}), from_a);
  frame.add("bytes written", f.value("bytes_written", uint64_t{0}), from_a);
  frame.add("bytes moved", bytes_of(f, {"bytes_read", "bytes_written"}), from_a);
  if (f.contains("by_category")) {
    for (const auto& [name, bytes] : f["by_category"].items()) categories.add(name, bytes.get<uint64_t>(), from_a);
  }
  const std::vector<std::string> names = unique_pass_names(report["passes"]);
  for (size_t i = 0; i < names.size(); ++i) {
    const Json& p = report["passes"][i];
    passes.add(names[i], bytes_of(p, {"bytes_read", "bytes_written"}), from_a);
    for (const Json& a : p.value("attachments", Json::array())) {
      const uint64_t bytes = bytes_of(a, {"bytes_loaded", "bytes_stored", "bytes_resolved"});
      rows.attachments.add(names[i] + " / " + a.value("name", ""), bytes, from_a);
      rows.attachment_totals.add(a.value("name", ""), bytes, from_a);
    }
  }
}

std::vector<std::string> decisions(const Json& report) {
  std::vector<std::string> out;
  if (!report.contains("graph")) return out;
  for (const Json& d : report["graph"].value("decisions", Json::array())) {
    std::string line = d.value("pass", "");
    if (d.contains("resource")) line += " [" + d.value("resource", "") + "]";
    out.push_back(line + ": " + d.value("decision", "") + ": " + d.value("reason", ""));
  }
  return out;
}

std::vector<std::string> only_in(const std::vector<std::string>& x, const std::vector<std::string>& y) {
  const std::multiset<std::string> others(y.begin(), y.end());
  std::vector<std::string> out;
  for (const std::string& s : x) {
    if (!others.count(s)) out.push_back(s);
  }
  return out;
}

// The "run" section flattened to key = value text; pipeline options as options.KEY.
std::map<std::string, std::string> run_fields(const Json& report) {
  std::map<std::string, std::string> fields;
  if (!report.contains("run")) return fields;
  for (const auto& [key, value] : report["run"].items()) {
    if (key == "options") {
      for (const auto& [option, text] : value.items()) fields["options." + option] = text.get<std::string>();
    } else {
      fields[key] = value.is_string() ? value.get<std::string>() : value.dump();
    }
  }
  return fields;
}

}  // namespace

std::string ByteDelta::percent() const {
  if (!in_b) return "gone";
  if (!in_a || (a == 0 && b != 0)) return "new";
  if (a == 0) return "+0.0%";
  char text[32];
  std::snprintf(text, sizeof text, "%+.1f%%", 100.0 * static_cast<double>(delta()) / static_cast<double>(a));
  return text;
}

ReportDiff diff_reports(const Json& a, const Json& b, const std::string& name_a, const std::string& name_b) {
  check_report(a, name_a);
  check_report(b, name_b);
  AllRows rows;
  add_report(a, true, rows);
  add_report(b, false, rows);
  ReportDiff diff;
  diff.frame = rows.frame.sorted();
  diff.categories = rows.categories.sorted();
  diff.passes = rows.passes.sorted();
  diff.attachments = rows.attachments.sorted();
  diff.attachment_totals = rows.attachment_totals.sorted();
  const std::vector<std::string> da = decisions(a), db = decisions(b);
  diff.decisions_only_in_a = only_in(da, db);
  diff.decisions_only_in_b = only_in(db, da);
  std::map<std::string, std::string> ra = run_fields(a), rb = run_fields(b);
  std::set<std::string> keys;
  for (const auto& [k, v] : ra) keys.insert(k);
  for (const auto& [k, v] : rb) keys.insert(k);
  for (const std::string& k : keys) {
    const std::string va = ra.count(k) ? ra[k] : "(absent)", vb = rb.count(k) ? rb[k] : "(absent)";
    if (va != vb) diff.run_changes.push_back({k, va, vb});
  }
  return diff;
}

}  // namespace ontile
