// The deferred bandwidth study: every variant's attachment traffic is the analytic formula of
// its design (whole tiles are loaded and stored whatever the scene covers), and the Markdown
// carries both our figures and the published Mali-G76 ones.
#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "studies/deferred_study.h"

namespace ontile {
namespace {

// The demo at 160x96 with 4 lights, on 2 threads.
StudySettings small_study() {
  StudySettings s;
  s.width_px = 160;
  s.height_px = 96;
  s.threads = 2;
  s.lights = 4;
  return s;
}

TEST(DeferredStudy, AttachmentTrafficOfEveryVariantIsAnalytic) {
  const Scene scene = load_gltf(std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb");
  const StudySettings s = small_study();
  const std::vector<StudyRow> rows = run_study(scene, s, deferred_study_variants(s.lights));
  ASSERT_EQ(rows.size(), 9u);
  const uint64_t px = uint64_t(s.width_px) * s.height_px;
  auto store = [](const StudyRow& r) { return r.bytes_by_category.at("attachment_store"); };
  auto load = [](const StudyRow& r) { return r.bytes_by_category.at("attachment_load"); };
  auto resolve = [](const StudyRow& r) { return r.bytes_by_category.at("resolve"); };
  // Two render passes, as the sample: the geometry pass stores light, depth, albedo and normal
  // (4 B/px each), the lighting pass loads all four and stores the light again.
  EXPECT_EQ(store(rows[0]), 20 * px);
  EXPECT_EQ(load(rows[0]), 16 * px);
  EXPECT_EQ(rows[0].bytes_by_category.at("texture"), rows[1].bytes_by_category.at("texture"))
      << "the G-buffer comes back as loads, not texture reads";
  EXPECT_EQ(rows[0].passes, 2);
  EXPECT_EQ(rows[0].tiles, 2 * rows[1].tiles);  // each pass walks every tile
  // The classic renderer: albedo, normal, depth and light stored, the G-buffer sampled.
  EXPECT_EQ(store(rows[8]), 16 * px);
  EXPECT_EQ(load(rows[8]), 0u);
  EXPECT_GT(rows[8].bytes_by_category.at("texture"), rows[1].bytes_by_category.at("texture"));
  // Subpasses: only the light target.
  EXPECT_EQ(store(rows[1]), 4 * px);
  // Transient attachments off with store op DONT_CARE: memory behind them, nothing written.
  EXPECT_EQ(store(rows[2]), 4 * px);
  // G-buffer and depth stored: written back as well.
  EXPECT_EQ(store(rows[3]), 16 * px);
  // G-buffer over budget: tiles halve, only the light is stored.
  EXPECT_EQ(store(rows[4]), 4 * px);
  EXPECT_EQ(rows[4].tile_width_px * rows[4].tile_height_px, 128);
  // Forward, then 4x MSAA resolved on tile (only the resolve write), then separately (the 4
  // samples stored and loaded back, 16 B/px each way, plus the resolve write).
  EXPECT_EQ(store(rows[5]), 4 * px);
  EXPECT_EQ(store(rows[6]) + load(rows[6]), 0u);
  EXPECT_EQ(resolve(rows[6]), 4 * px);
  EXPECT_EQ(store(rows[7]), 16 * px);
  EXPECT_EQ(load(rows[7]), 16 * px);
  EXPECT_EQ(resolve(rows[7]), 4 * px);
  for (const StudyRow& r : rows) EXPECT_GT(r.bytes_by_category.at("parameter_buffer_read"), 0u) << r.variant.label;

  // A modelled L2 in front of the parameter buffer only lowers its reads.
  StudySettings cached = s;
  cached.parameter_cache_kib = 64;
  const std::vector<StudyRow> with_cache = run_study(scene, cached, {deferred_study_variants(s.lights)[1]});
  EXPECT_LT(with_cache[0].bytes_by_category.at("parameter_buffer_read"), rows[1].bytes_by_category.at("parameter_buffer_read"));
  EXPECT_EQ(with_cache[0].bytes_written, rows[1].bytes_written);
  EXPECT_EQ(with_cache[0].bytes_read - with_cache[0].bytes_by_category.at("parameter_buffer_read"),
            rows[1].bytes_read - rows[1].bytes_by_category.at("parameter_buffer_read"));

  // The JSON carries every variant and the two-passes-over-subpasses ratios of their bytes.
  const nlohmann::json json = deferred_study_json(rows, s, "demo.glb");
  ASSERT_EQ(json["variants"].size(), rows.size());
  EXPECT_EQ(json["variants"][0]["bytes_written"].get<uint64_t>(), rows[0].bytes_written);
  EXPECT_EQ(json["variants"][7]["by_category"]["attachment_load"].get<uint64_t>(), 16 * px);
  EXPECT_DOUBLE_EQ(json["ratios"]["read"].get<double>(), double(rows[0].bytes_read) / double(rows[1].bytes_read));
  EXPECT_DOUBLE_EQ(json["ratios"]["write"].get<double>(), double(rows[0].bytes_written) / double(rows[1].bytes_written));
  EXPECT_DOUBLE_EQ(json["ratios"]["total"].get<double>(),
                   double(rows[0].bytes_read + rows[0].bytes_written) / double(rows[1].bytes_read + rows[1].bytes_written));
  EXPECT_GT(json["ratios"]["write"].get<double>(), 1.0);  // the G-buffer round trip
  EXPECT_DOUBLE_EQ(json["ratios"]["published_mali_g76"]["write"].get<double>(), 3.93);
  EXPECT_FALSE(deferred_study_json({rows[0]}, s, "demo.glb").contains("ratios"));

  const std::string md = deferred_study_markdown(rows, s, "demo.glb");
  for (const char* expected : {"| two render passes | 2 |", "949.4", "389.0", "| on tile |", "| separate pass |"}) {
    EXPECT_NE(md.find(expected), std::string::npos) << expected;
  }
}

// With --gpu mali-g76 (transaction elimination on one CRC target per pass) a static view's
// subpass frame stores no colour at all, while the two-pass frame's geometry pass writes albedo
// and normal (AFBC-compressed; the CRCs go to the light target, its first render target) besides
// the uncompressed depth, and the lighting pass loads them back compressed. fp16 varyings only
// shrink the parameter buffer.
TEST(DeferredStudy, MaliG76ComparesOneGBufferTargetPerPass) {
  const Scene scene = load_gltf(std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb");
  StudySettings s = small_study();
  s.gpu = "mali-g76";
  const std::vector<StudyVariant> variants = deferred_study_variants(s.lights);
  const std::vector<StudyRow> rows = run_study(scene, s, {variants[0], variants[1]});
  const uint64_t px = uint64_t(s.width_px) * s.height_px;
  auto store = [](const StudyRow& r) { return r.bytes_by_category.at("attachment_store"); };
  auto load = [](const StudyRow& r) { return r.bytes_by_category.at("attachment_load"); };
  EXPECT_EQ(store(rows[1]), 0u) << "the light target is eliminated, the G-buffer transient";
  EXPECT_GT(store(rows[0]), 4 * px) << "depth (D32F, never compressed), albedo and normal";
  EXPECT_LT(store(rows[0]), 12 * px) << "albedo and normal compressed, the light target eliminated";
  EXPECT_GT(load(rows[0]), 4 * px) << "depth is loaded uncompressed";
  EXPECT_LT(load(rows[0]), 16 * px) << "colour targets are loaded compressed";

  StudySettings half = s;
  half.varying_precision = VaryingPrecision::Fp16;
  const std::vector<StudyRow> fp16 = run_study(scene, half, {variants[1]});
  EXPECT_LT(fp16[0].bytes_by_category.at("parameter_buffer_write"),
            rows[1].bytes_by_category.at("parameter_buffer_write"));
  EXPECT_EQ(fp16[0].bytes_read, rows[1].bytes_read - (rows[1].bytes_by_category.at("parameter_buffer_read") -
                                                       fp16[0].bytes_by_category.at("parameter_buffer_read")));
  EXPECT_EQ(deferred_study_json(fp16, half, "demo.glb")["varying_precision"], "fp16");
}

}  // namespace
}  // namespace ontile
