// The HTML report in a real browser (issue 14, item 6): the demo rendered with --html, opened in
// headless Chromium. The page's own script counts what was drawn and records every error into
// attributes of <body> (frame_page_assets.h), read back with --dump-dom; a screenshot must be
// neither empty nor one flat colour. Skipped when /usr/bin/chromium is absent
// (scripts/install_deps.sh installs Debian's chromium).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <set>

#include "io/image_io.h"
#include "support/cli_runner.h"

namespace ontile {
namespace {

namespace fs = std::filesystem;

const char* const kChromium = "/usr/bin/chromium";

std::string run_command(const std::string& command) {
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return output;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) output.append(buf.data(), n);
  pclose(pipe);
  return output;
}

// Headless Chromium as a test runner may start it: as root (CI) without the sandbox, no GPU, no
// network services, a fresh profile. `timeout` bounds a browser that would not exit.
std::string chromium(const fs::path& profile, const std::string& args) {
  return "timeout 120 " + std::string(kChromium) +
         " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking "
         "--disable-component-update --disable-sync --user-data-dir=" + profile.string() + " " + args;
}

long body_attribute(const std::string& dom, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(dom, m, std::regex("<body[^>]*\\s" + name + "=\"(-?[0-9]+)\""))) return -1;
  return std::stol(m[1]);
}

TEST(HtmlBrowser, TheDemoPageDrawsWithoutErrors) {
  if (!fs::exists(kChromium)) GTEST_SKIP() << kChromium << " not found (scripts/install_deps.sh installs chromium)";
  const fs::path dir = test::temp_folder("ontile_html_browser");
  const fs::path page = dir / "demo.html", shot = dir / "shot.png";
  fs::remove(shot);
  const test::CliRun r = test::run_cli("render --scene " + std::string(ONTILE_SOURCE_DIR) +
                                 "/scenes/demo.glb --pipeline cartoon-multipass --render-graph merge --size 320x180 "
                                 "--threads 2 --out " + (dir / "demo.png").string() + " --html " + page.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string url = "file://" + fs::absolute(page).string();

  // The script's verdict after the page loaded (a virtual-time budget lets the load event run).
  const std::string dom = run_command(chromium(dir / "profile-dom", "--virtual-time-budget=5000 --dump-dom " + url) + " 2>/dev/null");
  ASSERT_EQ(body_attribute(dom, "data-ready"), 1) << dom.substr(0, 2000);
  EXPECT_EQ(body_attribute(dom, "data-errors"), 0) << dom.substr(dom.find("data-error-text"), 400);
  EXPECT_GE(body_attribute(dom, "data-heatmaps"), 3) << "three heatmaps per pass, each drawn with a size";
  EXPECT_GE(body_attribute(dom, "data-graph-nodes"), 2);
  EXPECT_GE(body_attribute(dom, "data-graph-edges"), 2);
  EXPECT_GE(body_attribute(dom, "data-images"), 2);

  // A screenshot of the top of the page: the title, the final image and the graph.
  run_command(chromium(dir / "profile-shot", "--screenshot=" + shot.string() + " --window-size=1200,1600 " + url) + " 2>&1");
  ASSERT_TRUE(fs::exists(shot)) << "no screenshot";
  int width = 0, height = 0;
  const std::vector<uint8_t> rgba = read_png_rgba8(shot, width, height);
  EXPECT_EQ(width, 1200);
  EXPECT_EQ(height, 1600);
  std::set<uint32_t> colours;
  for (size_t i = 0; i + 3 < rgba.size() && colours.size() < 64; i += 4 * 7) {
    colours.insert(rgba[i] << 16 | rgba[i + 1] << 8 | rgba[i + 2]);
  }
  EXPECT_GE(colours.size(), 64u) << "the screenshot is nearly one flat colour";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ontile
