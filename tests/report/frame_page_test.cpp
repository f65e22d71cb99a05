// The HTML frame report and what feeds it: the context's pass observer sees every pass without
// changing a bit of the frame, the captured attachments are the surfaces' contents, and the page
// holds every section, every pass and attachment by name, embedded images and no network link.
#include <gtest/gtest.h>

#include <map>

#include <filesystem>

#include "pipelines/kit/render_frame.h"
#include "report/frame_page.h"
#include "report/pass_capture.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace ontile {
namespace {

const Scene& demo() {
  static const Scene scene = load_gltf(std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb");
  return scene;
}

RenderedFrame render(const std::string& pipeline, PassObserver* observer, RenderGraphMode mode = RenderGraphMode::Off) {
  RenderSettings s;
  s.pipeline = pipeline;
  s.width_px = 96;
  s.height_px = 54;
  s.context.threads = 2;
  s.context.render_graph = mode;
  s.context.pass_observer = observer;
  return render_frame(demo(), s);
}

nlohmann::json counters(const FrameReport& report) {
  nlohmann::json j = frame_report_json(report);
  j.erase("timing");
  return j;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(PassCapture, SeesEveryPassAndChangesNothing) {
  PassCapture capture;
  const RenderedFrame observed = render("cartoon-multipass", &capture, RenderGraphMode::Merge);
  const RenderedFrame plain = render("cartoon-multipass", nullptr, RenderGraphMode::Merge);
  EXPECT_EQ(counters(observed.outputs.report), counters(plain.outputs.report));
  EXPECT_EQ(observed.outputs.color->bytes(), plain.outputs.color->bytes());

  const std::vector<PassReport>& passes = observed.outputs.report.passes;
  ASSERT_EQ(capture.passes().size(), passes.size());
  bool saw_transient = false, saw_final = false;
  for (size_t i = 0; i < passes.size(); ++i) {
    const CapturedPass& c = capture.passes()[i];
    EXPECT_EQ(c.index, i);
    EXPECT_EQ(c.name, passes[i].name);
    ASSERT_EQ(c.attachments.size(), passes[i].attachments.size()) << c.name;
    for (size_t a = 0; a < c.attachments.size(); ++a) {
      EXPECT_EQ(c.attachments[a].name, passes[i].attachments[a].name);
      EXPECT_EQ(c.attachments[a].transient, passes[i].attachments[a].transient);
      EXPECT_NE(c.attachments[a].contents, nullptr) << "transient ones from the tiles' copies";
      saw_transient |= c.attachments[a].transient;
      // The frame's image is the last thing written into its surface: the copy equals it.
      if (c.attachments[a].contents && c.attachments[a].name == observed.outputs.color->name() && i + 1 == passes.size()) {
        EXPECT_EQ(c.attachments[a].contents->bytes(), observed.outputs.color->bytes());
        saw_final = true;
      }
    }
  }
  EXPECT_TRUE(saw_transient) << "merge keeps the G-buffer in tile memory";
  EXPECT_TRUE(saw_final);

  // A transient attachment's copy is what its tiles held: the G-buffer that the passes as
  // written (render graph off) store to memory, byte for byte.
  PassCapture written;
  render("cartoon-multipass", &written, RenderGraphMode::Off);
  std::map<std::string, std::vector<uint8_t>> stored;
  for (const CapturedPass& p : written.passes()) {
    for (const CapturedAttachment& a : p.attachments) {
      if (a.contents && !stored.count(a.name)) stored[a.name] = a.contents->bytes();
    }
  }
  size_t compared = 0;
  for (const CapturedPass& p : capture.passes()) {
    for (const CapturedAttachment& a : p.attachments) {
      if (!a.transient || !stored.count(a.name)) continue;
      EXPECT_EQ(a.contents->bytes(), stored[a.name]) << p.name << " / " << a.name;
      ++compared;
    }
  }
  EXPECT_GT(compared, 0u);

  // A second frame through the same observer replaces the first.
  render("cartoon-multipass", &capture, RenderGraphMode::Merge);
  EXPECT_EQ(capture.passes().size(), passes.size());
}

TEST(FramePage, HoldsEverySectionPassAndAttachmentSelfContained) {
  PassCapture capture;
  const RenderedFrame frame = render("cartoon-multipass", &capture, RenderGraphMode::Merge);
  FramePage page;
  page.title = "demo <test>";
  page.run = {{"pipeline", "cartoon-multipass"}};
  page.report = &frame.outputs.report;
  page.passes = &capture.passes();
  page.final_image = frame.outputs.color;
  const std::string html = frame_page_html(page);
  EXPECT_EQ(html, frame_page_html(page));  // the same bytes every time

  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<title>demo &lt;test&gt;</title>"), std::string::npos);
  for (const char* id : {"id=\"final-image\"", "id=\"pass-graph\"", "id=\"passes\"", "id=\"traffic\""}) {
    EXPECT_NE(html.find(id), std::string::npos) << id;
  }
  EXPECT_NE(html.find("passes as written"), std::string::npos);
  EXPECT_NE(html.find("native passes as executed"), std::string::npos);
  const FrameReport& report = frame.outputs.report;
  size_t surfaces = 0;
  for (size_t i = 0; i < report.passes.size(); ++i) {
    EXPECT_NE(html.find("id=\"pass-" + std::to_string(i) + "\""), std::string::npos);
    EXPECT_NE(html.find(report.passes[i].name), std::string::npos);
    for (const CapturedAttachment& a : capture.passes()[i].attachments) {
      EXPECT_NE(html.find("<b>" + a.name + "</b>"), std::string::npos) << a.name;
      surfaces += (a.contents != nullptr) + (a.resolved != nullptr);
    }
  }
  for (const GraphReport::WrittenPass& p : report.graph->passes) EXPECT_NE(html.find(p.name), std::string::npos);
  // The final image, every surface after every pass and three heatmaps per pass, all embedded.
  EXPECT_EQ(count(html, "src=\"data:image/png;base64,"), 1 + surfaces);
  EXPECT_EQ(count(html, "<svg width=") - count(html, "class=\"heatmap\""), 2u);  // the two graphs
  EXPECT_EQ(count(html, "class=\"heatmap\""), 3 * report.passes.size());
  EXPECT_EQ(count(html, "<image "), 3 * report.passes.size());
  EXPECT_EQ(count(html, "class=\"graph-node\""), report.graph->passes.size() + report.passes.size());
  EXPECT_GT(count(html, "class=\"graph-edge\""), report.passes.size());
  EXPECT_EQ(count(html, "class=\"summary\""), report.passes.size());
  // Nothing to fetch: no links out, no external scripts or styles.
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);

  page.final_image = nullptr;
  EXPECT_THROW(frame_page_html(page), Error);
}

}  // namespace
}  // namespace ontile
