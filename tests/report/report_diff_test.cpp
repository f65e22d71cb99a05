// ontile diff's comparison of two reports: rows matched by name (repeated pass names by
// occurrence), sorted by the size of the change, percentages, graph decisions and run fields
// found in only one report, and refusal of a file that is not a render report.
#include <gtest/gtest.h>

#include "report/report_diff.h"
#include "util/error.h"

namespace ontile {
namespace {

using Json = nlohmann::json;

Json pass(const std::string& name, uint64_t read, uint64_t written, Json attachments = Json::array()) {
  return {{"name", name}, {"bytes_read", read}, {"bytes_written", written}, {"attachments", attachments}};
}

Json attachment(const std::string& name, uint64_t loaded, uint64_t stored) {
  return {{"name", name}, {"bytes_loaded", loaded}, {"bytes_stored", stored}, {"bytes_resolved", 0}};
}

Json report(Json passes, uint64_t read, uint64_t written, Json categories, Json run = Json::object()) {
  Json r = {{"format", "ontile-report"}, {"schema_version", 3},
            {"frame", {{"bytes_read", read}, {"bytes_written", written}, {"by_category", categories}}},
            {"passes", passes}};
  if (!run.empty()) r["run"] = run;
  return r;
}

TEST(ReportDiff, MatchesRowsAndSortsByTheSizeOfTheChange) {
  const Json a = report(Json::array({pass("gbuffer", 0, 800, Json::array({attachment("albedo", 0, 800)})),
                                     pass("blit", 100, 100), pass("blit", 10, 10)}),
                        110, 910, {{"attachment_store", 910}, {"texture", 110}},
                        {{"pipeline", "deferred-classic"}, {"options", {{"gbuffer", "unity"}}}});
  const Json b = report(Json::array({pass("gbuffer", 0, 200, Json::array({attachment("albedo", 0, 200)})),
                                     pass("blit", 100, 100), pass("tonemap", 5, 5)}),
                        105, 305, {{"attachment_store", 305}, {"texture", 105}},
                        {{"pipeline", "deferred-subpass"}, {"options", {{"gbuffer", "unity"}}}});
  const ReportDiff d = diff_reports(a, b, "a.json", "b.json");
  ASSERT_EQ(d.passes.size(), 4u);
  EXPECT_EQ(d.passes[0].name, "gbuffer");
  EXPECT_EQ(d.passes[0].delta(), -600);
  EXPECT_EQ(d.passes[0].percent(), "-75.0%");
  // The second "blit" of A has no counterpart in B; B's tonemap is new.
  EXPECT_EQ(d.passes[1].name, "blit #2");
  EXPECT_EQ(d.passes[1].percent(), "gone");
  EXPECT_EQ(d.passes[2].name, "tonemap");
  EXPECT_EQ(d.passes[2].percent(), "new");
  EXPECT_EQ(d.passes[3].name, "blit");
  EXPECT_EQ(d.passes[3].percent(), "+0.0%");
  ASSERT_EQ(d.attachments.size(), 1u);
  EXPECT_EQ(d.attachments[0].name, "gbuffer / albedo");
  EXPECT_EQ(d.attachments[0].delta(), -600);
  ASSERT_EQ(d.attachment_totals.size(), 1u);
  EXPECT_EQ(d.attachment_totals[0].name, "albedo");
  ASSERT_EQ(d.frame.size(), 3u);
  EXPECT_EQ(d.frame[0].name, "bytes moved");
  EXPECT_EQ(d.frame[0].delta(), 410 - 1020);
  EXPECT_EQ(d.categories[0].name, "attachment_store");
  ASSERT_EQ(d.run_changes.size(), 1u);
  EXPECT_EQ(d.run_changes[0].key, "pipeline");
  EXPECT_EQ(d.run_changes[0].b, "deferred-subpass");
  const std::string text = report_diff_text(d, "a.json", "b.json");
  EXPECT_NE(text.find("-600"), std::string::npos) << text;
  EXPECT_NE(text.find("pipeline: deferred-classic -> deferred-subpass"), std::string::npos) << text;
  const std::string html = report_diff_html(d, "a.json", "b.json");
  EXPECT_NE(html.find("<td>gbuffer / albedo</td>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos) << "the page needs no script";
}

TEST(ReportDiff, ListsGraphDecisionsFoundInOnlyOneReport) {
  Json a = report(Json::array({pass("p", 0, 0)}), 0, 0, Json::object());
  Json b = a;
  const Json merged = {{"pass", "lighting"}, {"decision", "merged"}, {"reason", "same size"}};
  const Json stored = {{"pass", "gbuffer"}, {"resource", "depth"}, {"decision", "stored"}, {"reason", "read later"}};
  // Json::array, not braces: a braced single element is a copy of it with some compilers.
  a["graph"]["decisions"] = Json::array({merged, stored});
  b["graph"]["decisions"] = Json::array({merged});
  const ReportDiff d = diff_reports(a, b, "a", "b");
  EXPECT_EQ(d.decisions_only_in_a, std::vector<std::string>{"gbuffer [depth]: stored: read later"});
  EXPECT_TRUE(d.decisions_only_in_b.empty());
}

TEST(ReportDiff, RefusesWhatIsNotARenderReport) {
  const Json good = report(Json::array({pass("p", 0, 0)}), 0, 0, Json::object());
  EXPECT_THROW(diff_reports(Json{{"asset", {{"version", "2.0"}}}}, good, "scene.gltf", "b"), Error);
  try {
    diff_reports(good, Json::array(), "a", "list.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("list.json: not an ontile render report"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ontile
