// `ontile diff` as a user runs it: two reports of the demo (classic vs subpass deferred) give
// the byte deltas and exit 0; --html writes one self-contained page; a file that is not a report
// is one error line and exit 2, with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "support/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using ontile::test::CliRun;
using ontile::test::run_cli;

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

fs::path render_report(const fs::path& folder, const std::string& pipeline) {
  const fs::path report = folder / (pipeline + ".json");
  const CliRun r = run_cli("render --scene " + kDemo + " --pipeline " + pipeline + " --size 160x90 --threads 2 --out " +
                           (folder / (pipeline + ".png")).string() + " --report " + report.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return report;
}

TEST(DiffCli, ComparesClassicAndSubpassDeferred) {
  const fs::path folder = ontile::test::temp_folder("ontile_diff_cli_test");
  const fs::path classic = render_report(folder, "deferred-classic");
  const fs::path subpass = render_report(folder, "deferred-subpass");
  const fs::path html = folder / "diff.html";
  const CliRun r = run_cli("diff " + classic.string() + " " + subpass.string() + " --html " + html.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("pipeline: deferred-classic -> deferred-subpass"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("attachment_store"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("gone"), std::string::npos) << "classic's lighting pass has no counterpart\n" << r.output;
  std::ifstream page(html);
  const std::string text((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<table>"), std::string::npos);
  EXPECT_NE(text.find("deferred-subpass"), std::string::npos);
}

TEST(DiffCli, ANonReportIsAnInputError) {
  const fs::path folder = ontile::test::temp_folder("ontile_diff_cli_test");
  const fs::path report = render_report(folder, "lambert");
  const fs::path html = folder / "never.html";
  const CliRun r = run_cli("diff " + report.string() + " " + kDemo + " --html " + html.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("error: ", 0), 0u) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(fs::exists(html));
}

}  // namespace
