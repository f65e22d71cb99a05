// The HTML frame report (see frame_page.h): sections in reading order, each drawn from the
// frame's report and the captured passes.
#include "report/frame_page.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "charts/svg_writer.h"
#include "io/image_io.h"
#include "report/attachment_images.h"
#include "report/byte_text.h"
#include "report/frame_page_assets.h"
#include "report/pass_graph_svg.h"
#include "report/pass_summary.h"
#include "report/tile_heatmaps.h"
#include "util/error.h"

namespace ontile {
namespace {

std::string esc(const std::string& text) { return xml_escape(text); }

std::string number_cell(uint64_t bytes) { return "<td class=\"n\">" + grouped_bytes(bytes) + "</td>"; }

std::string image_tag(const Rgba8Image& image, const std::string& alt, const std::string& css_class = "") {
  return "<img src=\"" + png_data_uri(image.width, image.height, image.rgba) + "\" width=\"" +
         std::to_string(image.width) + "\" height=\"" + std::to_string(image.height) + "\" alt=\"" + esc(alt) + "\"" +
         (css_class.empty() ? "" : " class=\"" + css_class + "\"") + ">";
}

void run_section(std::ostringstream& out, const FramePage& page) {
  const FrameReport& r = *page.report;
  out << "<h1>" << esc(page.title) << "</h1>\n<p>External traffic: <b>" << bytes_text(r.bytes_read()) << "</b> read, <b>"
      << bytes_text(r.bytes_written()) << "</b> written over " << r.passes.size() << " render passes.</p>\n";
  if (!page.run.empty()) {
    out << "<details><summary>run settings</summary><table>\n";
    for (const auto& [key, value] : page.run.items()) {
      out << "<tr><td>" << esc(key) << "</td><td>" << esc(value.is_string() ? value.get<std::string>() : value.dump())
          << "</td></tr>\n";
    }
    out << "</table></details>\n";
  }
}

void final_image_section(std::ostringstream& out, const FramePage& page) {
  out << "<h2 id=\"final-image\">final image</h2>\n<div class=\"final\">"
      << image_tag(display_image(*page.final_image), "final image: " + page.final_image->name()) << "</div>\n";
}

void graph_section(std::ostringstream& out, const FramePage& page) {
  const FrameReport& r = *page.report;
  out << "<h2 id=\"pass-graph\">pass graph</h2>\n";
  if (r.graph) {
    out << "<h3>passes as written (render graph, --render-graph " << esc(r.graph->mode) << ")</h3>\n<div class=\"scroll\">"
        << written_graph_svg(*r.graph) << "</div>\n";
  } else {
    out << "<p>No render graph was compiled (a pipeline written as a render graph, run with --render-graph cull or "
           "merge, shows its passes as written here); the passes below ran as recorded.</p>\n";
  }
  out << "<h3>native passes as executed</h3>\n<p>Each box is a render pass the tiler ran, with its attachments (load "
         "&#8594; store action; green: transient, in tile memory only; blue: backed by memory). Arrows are external-memory "
         "traffic: down (red) written, up (blue) read, labelled with their bytes.</p>\n<div class=\"scroll\">"
      << executed_graph_svg(r, *page.passes) << "</div>\n";
}

void attachment_figures(std::ostringstream& out, const FramePage& page, const CapturedPass& pass) {
  out << "<div class=\"thumbs\">\n";
  for (const CapturedAttachment& a : pass.attachments) {
    out << "<figure>";
    const double aspect = pass.width_px > 0 ? static_cast<double>(pass.height_px) / pass.width_px : 0.5625;
    if (a.contents) {
      Rgba8Image thumb = downscale(display_image(*a.contents), page.thumbnail_width_px);
      out << image_tag(thumb, pass.name + " / " + a.name, "attachment");
    } else {
      const int w = std::min(page.thumbnail_width_px, pass.width_px);
      out << "<div class=\"transient-box\" style=\"width:" << w << "px;height:" << static_cast<int>(w * aspect)
          << "px\">transient: in tile memory only,<br>nothing left in memory</div>";
    }
    out << "<figcaption><b>" << esc(a.name) << "</b> " << format_name(a.format) << ", " << esc(a.load) << " &#8594; "
        << esc(a.store) << (a.transient ? ", transient" : ", memory");
    if (a.contents && a.transient) out << "<br><i>what the tiles held at the end of the pass; never written to memory</i>";
    if (a.contents) out << "<br><i>" << esc(view_description(a.format)) << "</i>";
    out << "</figcaption></figure>\n";
    if (a.resolved) {
      out << "<figure>" << image_tag(downscale(display_image(*a.resolved), page.thumbnail_width_px), a.resolved->name(), "attachment")
          << "<figcaption><b>" << esc(a.resolved->name()) << "</b> " << format_name(a.resolved->format())
          << ", resolve target of " << esc(a.name) << "</figcaption></figure>\n";
    }
  }
  out << "</div>\n";
}

void passes_section(std::ostringstream& out, const FramePage& page) {
  const FrameReport& r = *page.report;
  out << "<h2 id=\"passes\">passes</h2>\n";
  for (size_t i = 0; i < r.passes.size(); ++i) {
    const PassReport& p = r.passes[i];
    const CapturedPass* captured = i < page.passes->size() ? &(*page.passes)[i] : nullptr;
    out << "<div class=\"pass\" id=\"pass-" << i << "\"><h3>" << i << ": " << esc(p.name) << "</h3>\n<p class=\"summary\">"
        << esc(pass_summary_text(summarize_pass(p, captured, r.graph ? &*r.graph : nullptr))) << "</p>\n";
    if (captured) attachment_figures(out, page, *captured);
    const std::vector<std::string> maps = tile_heatmaps_svg(p, i, page.heatmap_width_px);
    if (maps.empty()) {
      out << "<p>No per-tile statistics for this pass (" << esc(p.architecture) << ").</p>\n";
    } else {
      out << "<p>Tiles of " << p.tile_width_px << "x" << p.tile_height_px << " px; hover a tile for its value.</p>\n"
          << "<div class=\"heatmaps\">\n";
      for (const std::string& m : maps) out << m;
      out << "</div>\n";
    }
    out << "</div>\n";
  }
}

void traffic_section(std::ostringstream& out, const FrameReport& r) {
  out << "<h2 id=\"traffic\">traffic</h2>\n<h3>frame</h3><table><tr><th></th><th>bytes</th></tr>\n<tr><td>read</td>"
      << number_cell(r.bytes_read()) << "</tr><tr><td>written</td>" << number_cell(r.bytes_written())
      << "</tr></table>\n<h3>categories</h3><table><tr><th>category</th><th>bytes</th></tr>\n";
  for (const auto& [name, bytes] : r.bytes_by_category()) out << "<tr><td>" << esc(name) << "</td>" << number_cell(bytes) << "</tr>\n";
  out << "</table>\n<h3>passes</h3><table><tr><th>pass</th><th>tile</th><th>tiles</th><th>read</th><th>written</th>"
         "<th>fragments</th><th>overdraw</th></tr>\n";
  for (const PassReport& p : r.passes) {
    const double pixels = static_cast<double>(p.width_px) * p.height_px;
    char overdraw[32];
    std::snprintf(overdraw, sizeof overdraw, "%.2f", pixels > 0 ? p.tiles.fragments_shaded / pixels : 0.0);
    out << "<tr><td>" << esc(p.name) << "</td><td>"
        << (p.architecture == "imr" ? std::string("IMR") : std::to_string(p.tile_width_px) + "x" + std::to_string(p.tile_height_px))
        << "</td>" << number_cell(p.tiles_total) << number_cell(p.bytes_read()) << number_cell(p.bytes_written())
        << number_cell(p.tiles.fragments_shaded) << "<td class=\"n\">" << overdraw << "</td></tr>\n";
  }
  out << "</table>\n<h3>attachments</h3><table><tr><th>pass</th><th>attachment</th><th>format</th><th>kept in</th>"
         "<th>loaded</th><th>stored</th><th>resolved</th></tr>\n";
  for (const PassReport& p : r.passes) {
    for (const AttachmentTraffic& a : p.attachments) {
      out << "<tr><td>" << esc(p.name) << "</td><td>" << esc(a.name) << "</td><td>" << format_name(a.format) << "</td><td>"
          << (a.transient ? "tile memory (transient)" : "memory") << "</td>" << number_cell(a.bytes_loaded)
          << number_cell(a.bytes_stored) << number_cell(a.bytes_resolved) << "</tr>\n";
    }
  }
  out << "</table>\n";
}

}  // namespace

std::string frame_page_html(const FramePage& page) {
  if (!page.report || !page.passes || !page.final_image) throw Error("HTML report: no frame to show");
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>" << esc(page.title)
      << "</title>\n<script>" << kFramePageErrorHook << "</script>\n<style>" << kFramePageStyle << "</style>\n</head><body>\n";
  run_section(out, page);
  out << "<p><a href=\"#final-image\">final image</a> &middot; <a href=\"#pass-graph\">pass graph</a> &middot; "
         "<a href=\"#passes\">passes</a> &middot; <a href=\"#traffic\">traffic</a></p>\n";
  final_image_section(out, page);
  graph_section(out, page);
  passes_section(out, page);
  traffic_section(out, *page.report);
  out << "<div id=\"tip\"></div>\n<script>" << kFramePageScript << "</script>\n</body></html>\n";
  return out.str();
}

}  // namespace ontile
