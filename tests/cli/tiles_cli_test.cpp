// `ontile render --tiles`: per-tile statistics of every pass in the JSON report (columns of
// tiles_x x tiles_y values that sum to the pass's counters; which thread ran each tile under
// "timing"), texture bytes per source in every report, and --tiles without --report refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numeric>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using ontile::test::CliRun;
using ontile::test::run_cli;

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

fs::path temp_folder() { return ontile::test::temp_folder("ontile_tiles_cli_test"); }

uint64_t sum(const nlohmann::json& column) {
  uint64_t total = 0;
  for (const auto& v : column) total += v.get<uint64_t>();
  return total;
}

TEST(TilesCli, ReportCarriesPerTileColumnsThatSumToEachPass) {
  const fs::path out = temp_folder() / "tiles.png", report = temp_folder() / "tiles.json";
  const CliRun r = run_cli("render --scene " + kDemo + " --pipeline deferred-classic --size 200x120 --tile 32 "
                           "--threads 2 --tiles --out " + out.string() + " --report " + report.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;  // run_cli also validates the report against the schema
  nlohmann::json j;
  std::ifstream(report) >> j;
  EXPECT_TRUE(j["run"]["tiles"].get<bool>());
  ASSERT_GE(j["passes"].size(), 2u);
  for (size_t i = 0; i < j["passes"].size(); ++i) {
    const nlohmann::json& pass = j["passes"][i];
    const nlohmann::json& tiles = pass["tile_stats"];
    const std::string name = pass["name"];
    // 200x120 in 32x32 tiles (unless the colour budget shrank them): 7 x 4 tiles.
    const int tile_w = pass["tile_size_px"][0], tile_h = pass["tile_size_px"][1];
    EXPECT_EQ(tiles["tiles_x"].get<int>(), (200 + tile_w - 1) / tile_w) << name;
    EXPECT_EQ(tiles["tiles_y"].get<int>(), (120 + tile_h - 1) / tile_h) << name;
    const size_t count = pass["tiles"].get<size_t>();
    for (const char* column : {"triangles", "fragments_shaded", "fragments_depth_rejected", "cells_rasterized",
                               "cells_hiz_rejected", "parameter_bytes_read", "bytes_loaded", "bytes_stored",
                               "texture_bytes_read"}) {
      EXPECT_EQ(tiles[column].size(), count) << name << " " << column;
    }
    EXPECT_EQ(sum(tiles["triangles"]), pass["geometry"]["tile_list_entries"].get<uint64_t>()) << name;
    EXPECT_EQ(sum(tiles["fragments_shaded"]), pass["fragments_shaded"].get<uint64_t>()) << name;
    EXPECT_EQ(sum(tiles["texture_bytes_read"]), pass["texture"]["bytes_read"].get<uint64_t>()) << name;
    uint64_t stored = 0, loaded = 0;
    for (const auto& a : pass["attachments"]) {
      stored += a["bytes_stored"].get<uint64_t>() + a["bytes_resolved"].get<uint64_t>();
      loaded += a["bytes_loaded"].get<uint64_t>();
    }
    EXPECT_EQ(sum(tiles["bytes_stored"]), stored) << name;
    EXPECT_EQ(sum(tiles["bytes_loaded"]), loaded) << name;
    const nlohmann::json& timing = j["timing"]["passes"][i];
    EXPECT_EQ(timing["tile_thread"].size(), count) << name;
    EXPECT_EQ(timing["tile_order"].size(), count) << name;
    uint64_t source_bytes = 0;
    for (const auto& s : pass["texture"]["sources"]) source_bytes += s["bytes_read"].get<uint64_t>();
    EXPECT_EQ(source_bytes, pass["texture"]["bytes_read"].get<uint64_t>()) << name;
  }
}

TEST(TilesCli, ReportsWithoutTilesHaveNoTileColumnsButDoNameTextureSources) {
  const fs::path out = temp_folder() / "plain.png", report = temp_folder() / "plain.json";
  const CliRun r = run_cli("render --scene " + kDemo + " --pipeline cartoon --size 160x90 --out " +
                           out.string() + " --report " + report.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  nlohmann::json j;
  std::ifstream(report) >> j;
  EXPECT_FALSE(j["run"]["tiles"].get<bool>());
  bool render_target_source = false;
  for (const auto& pass : j["passes"]) {
    EXPECT_FALSE(pass.contains("tile_stats"));
    for (const auto& s : pass["texture"]["sources"]) render_target_source |= s["kind"] == "render_target";
  }
  EXPECT_TRUE(render_target_source) << "the cartoon Sobel pass samples the geometry pass's targets";
  // The table names the sources too.
  EXPECT_NE(r.output.find("render target"), std::string::npos) << r.output;
}

TEST(TilesCli, TilesWithoutAReportIsAUsageError) {
  const fs::path out = temp_folder() / "none.png";
  const CliRun r = run_cli("render --scene " + kDemo + " --size 64x64 --tiles --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("error:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--report"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
