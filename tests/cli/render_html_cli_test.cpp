// `render --html` and `--dump-attachments [--tile-grid]` through the CLI: the page and the
// attachment files appear with the image, named by pass and attachment, in PNG or EXR by format,
// with the tile grid drawn when asked; the image and report stay what they are without them.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <nlohmann/json.hpp>

#include "io/image_io.h"
#include "support/cli_runner.h"

namespace ontile {
namespace {

namespace fs = std::filesystem;
using test::CliRun;
using test::run_cli;

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(RenderHtmlCli, WritesThePageAndEveryAttachmentWithTheImage) {
  const fs::path dir = test::temp_folder("ontile_render_html");
  const fs::path dumps = dir / "attachments";
  fs::remove_all(dumps);
  fs::create_directories(dumps);
  const std::string common = "render --scene " + kDemo + " --pipeline cartoon --size 64x40 --threads 2 ";
  const CliRun r = run_cli(common + "--out " + (dir / "a.png").string() + " --report " + (dir / "a.json").string() +
                           " --html " + (dir / "a.html").string() + " --dump-attachments " + dumps.string() + " --tile-grid");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("wrote " + (dir / "a.html").string()), std::string::npos) << r.output;
  // Cartoon: the MRT pass's four targets, then the edge blit's final image.
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dumps)) names.insert(entry.path().filename().string());
  const std::set<std::string> expected = {"0-toon_MRT-color.png", "0-toon_MRT-normals.exr", "0-toon_MRT-border.png",
                                          "0-toon_MRT-depth.exr", "1-blit_toon_edges-final.png"};
  EXPECT_EQ(names, expected);
  // The final attachment is the image itself, with magenta tile boundaries (16 px tiles) over it.
  int w = 0, h = 0, iw = 0, ih = 0;
  const std::vector<uint8_t> dumped = read_png_rgba8(dumps / "1-blit_toon_edges-final.png", w, h);
  const std::vector<uint8_t> image = read_png_rgba8(dir / "a.png", iw, ih);
  ASSERT_EQ(w, 64);
  ASSERT_EQ(h, 40);
  ASSERT_EQ(dumped.size(), image.size());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = (static_cast<size_t>(y) * w + x) * 4;
      if (x % 16 == 0 || y % 16 == 0) {
        EXPECT_EQ(dumped[i] * 65536 + dumped[i + 1] * 256 + dumped[i + 2], 0xFF00FF) << x << "," << y;
      } else {
        EXPECT_TRUE(std::equal(&dumped[i], &dumped[i + 4], &image[i])) << x << "," << y;
      }
    }
  }
  const ImageRGBA32F depth = read_image(dumps / "0-toon_MRT-depth.exr");
  EXPECT_EQ(depth.width, 64);
  const std::string page = read_text(dir / "a.html");
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("toon MRT"), std::string::npos);

  // Without the inspection options the image and the report's counters are the same bytes.
  const CliRun plain = run_cli(common + "--out " + (dir / "b.png").string() + " --report " + (dir / "b.json").string());
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_EQ(read_text(dir / "a.png"), read_text(dir / "b.png"));
  auto counters = [&](const fs::path& report) {
    nlohmann::json j = nlohmann::json::parse(read_text(report));
    j.erase("timing");
    return j;
  };
  EXPECT_EQ(counters(dir / "a.json"), counters(dir / "b.json"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ontile
