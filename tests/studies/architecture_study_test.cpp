// The architecture study (TBDR at several tile sizes vs IMR): attachment bytes of a TBDR frame
// do not depend on the tile size (whole tiles cover the target once), the tile lists grow as
// tiles shrink, the IMR frame moves more bytes than any TBDR one (depth never leaves the tile),
// once the target outgrows the IMR's render-target cache (at 160x96 the 128 KiB cache holds colour
// and depth whole and the IMR moves less), and the JSON's ratios and best tile size are those of
// the rows.
#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "studies/architecture_study.h"

namespace ontile {
namespace {

TEST(ArchitectureStudy, RowsRatiosAndBestTileSizeFollowTheFrames) {
  const Scene scene = load_gltf(std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb");
  ArchitectureStudySettings s;
  s.width_px = 640;  // colour alone is 900 KiB, 7x the render-target cache
  s.height_px = 360;
  s.threads = 2;
  s.tile_sizes_px = {8, 16, 32};
  s.pipelines = {"lambert", "cartoon"};
  const std::vector<ArchitectureRow> rows = run_architecture_study(scene, s);
  ASSERT_EQ(rows.size(), 8u);
  const uint64_t px = uint64_t(s.width_px) * s.height_px;
  for (int p = 0; p < 2; ++p) {
    const ArchitectureRow* tbdr = &rows[p * 4];
    const ArchitectureRow& imr = rows[p * 4 + 3];
    ASSERT_TRUE(imr.imr);
    for (int t = 0; t < 3; ++t) {
      EXPECT_FALSE(tbdr[t].imr);
      EXPECT_EQ(tbdr[t].tile_size_px, s.tile_sizes_px[t]);
      EXPECT_EQ(tbdr[t].bytes_by_category.at("attachment_store"), tbdr[0].bytes_by_category.at("attachment_store"));
      EXPECT_GT(imr.total(), tbdr[t].total()) << tbdr[t].pipeline << " " << tbdr[t].tile_size_px;
    }
    EXPECT_GT(tbdr[0].tile_list_entries, tbdr[1].tile_list_entries);
    EXPECT_GT(tbdr[1].tile_list_entries, tbdr[2].tile_list_entries);
    EXPECT_EQ(imr.tile_list_entries, 0u);
  }
  EXPECT_EQ(rows[0].bytes_by_category.at("attachment_store"), 4 * px);  // lambert: the sRGB colour target

  const nlohmann::json json = architecture_study_json(rows, s, "demo.glb");
  ASSERT_EQ(json["rows"].size(), rows.size());
  const nlohmann::json& lambert = json["pipelines"]["lambert"];
  int best = rows[0].tile_size_px;
  uint64_t best_total = rows[0].total();
  for (int t = 0; t < 3; ++t) {
    EXPECT_DOUBLE_EQ(lambert["imr_over_tbdr"][std::to_string(rows[t].tile_size_px)].get<double>(),
                     double(rows[3].total()) / double(rows[t].total()));
    if (rows[t].total() < best_total) {
      best_total = rows[t].total();
      best = rows[t].tile_size_px;
    }
  }
  EXPECT_EQ(lambert["best_tile_size_px"].get<int>(), best);
  EXPECT_DOUBLE_EQ(json["published"]["imr_over_tbdr"].get<double>(), 1.96);

  const std::string md = architecture_study_markdown(rows, s, "demo.glb");
  for (const char* expected : {"| lambert | TBDR | 8x8 |", "| cartoon | IMR | - |", "fewest bytes", "1.96"}) {
    EXPECT_NE(md.find(expected), std::string::npos) << expected;
  }
}

}  // namespace
}  // namespace ontile
