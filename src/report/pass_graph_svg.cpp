// Pass graph drawings (see pass_graph_svg.h). Both are laid out on a fixed grid, without a
// general graph layout: passes run in order, so order is the layout.
#include "report/pass_graph_svg.h"

#include <algorithm>
#include <map>

#include "charts/svg_writer.h"
#include "report/byte_text.h"

namespace ontile {
namespace {

const char* const kWriteColor = "#1f77b4";
const char* const kPixelReadColor = "#2ca02c";
const char* const kTextureReadColor = "#ff7f0e";
const char* const kMemoryColor = "#1f77b4";
const char* const kOnChipColor = "#2ca02c";

size_t index_of(std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it != names.end()) return static_cast<size_t>(it - names.begin());
  names.push_back(name);
  return names.size() - 1;
}

std::string shortened(const std::string& text, size_t max_chars) {
  return text.size() <= max_chars ? text : text.substr(0, max_chars - 1) + "\u2026";
}

SvgText text_style(double size_px, TextAnchor anchor = TextAnchor::Start, bool bold = false) {
  SvgText t;
  t.size_px = size_px;
  t.anchor = anchor;
  t.bold = bold;
  return t;
}

}  // namespace

std::string written_graph_svg(const GraphReport& graph) {
  std::vector<std::string> resources;
  for (const GraphReport::WrittenPass& p : graph.passes) {
    for (const auto* list : {&p.writes, &p.own_pixel_reads, &p.texture_reads}) {
      for (const std::string& r : *list) index_of(resources, r);
    }
  }
  constexpr double kLeft = 210, kRow = 26, kColumn = 28;
  // Room above the rows for the resource names, which rise at 50 degrees (about 0.6 em a character).
  size_t longest = 1;
  for (const std::string& r : resources) longest = std::max(longest, std::min<size_t>(r.size(), 22));
  const double kTop = 24 + 0.6 * 11 * longest * 0.77;
  const double width = std::max(kLeft + kColumn * std::max<size_t>(resources.size(), 1) + 20, 480.0);
  const double height = kTop + kRow * graph.passes.size() + 40;
  SvgWriter svg(width, height, "pass-graph written");
  for (size_t r = 0; r < resources.size(); ++r) {
    SvgText header = text_style(11);
    header.rotate_deg = -50;
    svg.text(kLeft + kColumn * r + kColumn / 2, kTop - 8, shortened(resources[r], 22), header);
  }
  auto cx = [&](size_t r) { return kLeft + kColumn * r + kColumn / 2; };
  auto cy = [&](size_t p) { return kTop + kRow * p + kRow / 2; };
  // Edges: each resource's line from its first to its last use, under the markers.
  for (size_t r = 0; r < resources.size(); ++r) {
    size_t first = graph.passes.size(), last = 0;
    for (size_t p = 0; p < graph.passes.size(); ++p) {
      const GraphReport::WrittenPass& pass = graph.passes[p];
      for (const auto* list : {&pass.writes, &pass.own_pixel_reads, &pass.texture_reads}) {
        if (std::find(list->begin(), list->end(), resources[r]) != list->end()) first = std::min(first, p), last = std::max(last, p);
      }
    }
    if (first < last) {
      svg.begin_group(resources[r] + ": used from " + graph.passes[first].name + " to " + graph.passes[last].name, "graph-edge");
      svg.line(cx(r), cy(first), cx(r), cy(last), SvgStyle::stroked("#9a9a9a", 2.0));
      svg.end_group();
    }
  }
  for (size_t p = 0; p < graph.passes.size(); ++p) {
    const GraphReport::WrittenPass& pass = graph.passes[p];
    svg.begin_group(pass.name + (pass.culled ? " (culled)" : ""), "graph-node");
    SvgStyle row = SvgStyle::filled(p % 2 ? "#f4f4f4" : "#ffffff");
    svg.rect(0, kTop + kRow * p, width, kRow, row);
    SvgText label = text_style(12);
    label.fill = pass.culled ? "#999" : "#222";
    svg.text(8, cy(p) + 4, shortened(pass.name, 26) + (pass.culled ? "  (culled)" : ""), label);
    for (const std::string& w : pass.writes) {
      svg.rect(cx(index_of(resources, w)) - 6, cy(p) - 6, 12, 12, SvgStyle::filled(pass.culled ? "#bbbbbb" : kWriteColor));
    }
    for (const std::string& rd : pass.own_pixel_reads) {
      SvgStyle ring = SvgStyle::stroked(kPixelReadColor, 2.5);
      ring.fill = "#ffffff";
      svg.circle(cx(index_of(resources, rd)), cy(p), 6, ring);
    }
    for (const std::string& rd : pass.texture_reads) {
      const double x = cx(index_of(resources, rd)), y = cy(p);
      SvgStyle diamond = SvgStyle::stroked(kTextureReadColor, 2.5);
      diamond.fill = "#ffffff";
      svg.polyline({{x, y - 7}, {x + 7, y}, {x, y + 7}, {x - 7, y}, {x, y - 7}}, diamond);
    }
    svg.end_group();
  }
  // Legend.
  const double ly = height - 16;
  SvgText legend = text_style(11);
  svg.rect(8, ly - 9, 10, 10, SvgStyle::filled(kWriteColor));
  svg.text(24, ly, "writes", legend);
  svg.circle(90, ly - 4, 5, SvgStyle::stroked(kPixelReadColor, 2.5));
  svg.text(100, ly, "reads its own pixel (input attachment)", legend);
  svg.polyline({{330, ly - 10}, {336, ly - 4}, {330, ly + 2}, {324, ly - 4}, {330, ly - 10}}, SvgStyle::stroked(kTextureReadColor, 2.5));
  svg.text(342, ly, "samples as a texture", legend);
  return svg.str();
}

std::string executed_graph_svg(const FrameReport& frame, const std::vector<CapturedPass>& captured) {
  const bool have_actions = captured.size() == frame.passes.size();
  // Memory lanes: surfaces in order of first use, then textures and the parameter buffer.
  std::vector<std::string> lanes;
  for (size_t i = 0; i < frame.passes.size(); ++i) {
    for (size_t a = 0; a < frame.passes[i].attachments.size(); ++a) {
      const AttachmentTraffic& t = frame.passes[i].attachments[a];
      if (!t.transient) index_of(lanes, t.name);
      if (have_actions && a < captured[i].attachments.size() && captured[i].attachments[a].resolved) {
        index_of(lanes, captured[i].attachments[a].resolved->name());
      }
    }
  }
  for (const PassReport& p : frame.passes) {
    for (const TextureSourceTraffic& t : p.texture_sources) {
      if (t.render_target) index_of(lanes, t.name);
    }
  }
  const size_t texture_lane = index_of(lanes, "scene textures");
  const size_t parameter_lane = index_of(lanes, "parameter buffer");
  constexpr double kLeft = 150, kColumn = 260, kBoxWidth = 236, kLine = 15, kLane = 34;
  double box_height = 0;
  for (const PassReport& p : frame.passes) box_height = std::max(box_height, 46 + kLine * p.attachments.size());
  // Room under the boxes for the edge labels, which read upwards from just above the first lane.
  const double lanes_top = 20 + box_height + 100;
  const double width = kLeft + kColumn * std::max<size_t>(frame.passes.size(), 1) + 20;
  const double height = lanes_top + kLane * lanes.size() + 10;
  SvgWriter svg(width, height, "pass-graph executed");
  auto lane_y = [&](size_t lane) { return lanes_top + kLane * lane; };
  for (size_t l = 0; l < lanes.size(); ++l) {
    svg.line(kLeft - 10, lane_y(l), width - 10, lane_y(l), SvgStyle::stroked("#c8c8c8", 1.0, "4 3"));
    svg.text(8, lane_y(l) + 4, shortened(lanes[l], 22), text_style(11));
  }
  for (size_t i = 0; i < frame.passes.size(); ++i) {
    const PassReport& p = frame.passes[i];
    const double x = kLeft + kColumn * i, top = 20;
    svg.begin_group(p.name, "graph-node");
    svg.rect(x, top, kBoxWidth, box_height, SvgStyle::stroked("#444444", 1.2), 6);
    svg.text(x + 8, top + 16, std::to_string(i) + ": " + shortened(p.name, 30), text_style(12, TextAnchor::Start, true));
    const std::string shape = std::to_string(p.width_px) + "x" + std::to_string(p.height_px) +
                              (p.samples > 1 ? ", " + std::to_string(p.samples) + "x MSAA" : "") +
                              (have_actions && captured[i].subpasses > 1 ? ", " + std::to_string(captured[i].subpasses) + " subpasses" : "");
    SvgText small = text_style(10);
    small.fill = "#555";
    svg.text(x + 8, top + 31, shape, small);
    for (size_t a = 0; a < p.attachments.size(); ++a) {
      const AttachmentTraffic& t = p.attachments[a];
      const double y = top + 48 + kLine * a;
      svg.rect(x + 8, y - 9, 10, 10, SvgStyle::filled(t.transient ? kOnChipColor : kMemoryColor));
      std::string actions;
      if (have_actions && a < captured[i].attachments.size()) {
        actions = captured[i].attachments[a].load + " \u2192 " + captured[i].attachments[a].store;
      } else {
        actions = std::string(t.bytes_loaded ? "load" : "-") + " \u2192 " + (t.bytes_stored + t.bytes_resolved ? "store" : "-");
      }
      svg.text(x + 22, y, shortened(t.name, 16) + " " + format_name(t.format) + "  " + actions, text_style(10));
    }
    svg.end_group();
    // Edges to and from memory, one column each, left to right across the box.
    double edge_x = x + 14;
    auto edge = [&](size_t lane, bool to_memory, uint64_t bytes, const std::string& what) {
      if (!bytes) return;
      const double y0 = top + box_height, y1 = lane_y(lane);
      svg.begin_group(p.name + (to_memory ? " \u2192 " : " \u2190 ") + lanes[lane] + ": " + what + " " +
                          grouped_bytes(bytes) + " B", "graph-edge");
      const SvgStyle style = SvgStyle::stroked(to_memory ? "#c0392b" : "#2471a3", 1.6);
      if (to_memory) svg.arrow(edge_x, y0, edge_x, y1 - 2, style); else svg.arrow(edge_x, y1, edge_x, y0 + 2, style);
      SvgText label = text_style(9);
      label.rotate_deg = -90;
      label.fill = to_memory ? "#c0392b" : "#2471a3";
      svg.text(edge_x - 3, y0 + 90, what + " " + bytes_text(bytes), label);
      svg.end_group();
      edge_x = std::min(edge_x + 16, x + kBoxWidth - 8);
    };
    for (size_t a = 0; a < p.attachments.size(); ++a) {
      const AttachmentTraffic& t = p.attachments[a];
      const bool resolve_named = have_actions && a < captured[i].attachments.size() && captured[i].attachments[a].resolved;
      if (!t.transient) {
        edge(index_of(lanes, t.name), false, t.bytes_loaded, "load");
        edge(index_of(lanes, t.name), true, t.bytes_stored, "store");
      }
      // A transient multisampled attachment still resolves to a single-sample surface in memory.
      if (resolve_named || !t.transient) {
        edge(index_of(lanes, resolve_named ? captured[i].attachments[a].resolved->name() : t.name), true,
             t.bytes_resolved, "resolve");
      }
    }
    // Texture reads by source: a render target an earlier pass wrote reads back from its own
    // lane (classic deferred's G-buffer read-back shows there); scene textures share one lane.
    uint64_t scene_texture_bytes = p.texture.bytes_read;
    for (const TextureSourceTraffic& t : p.texture_sources) {
      if (!t.render_target) continue;
      edge(index_of(lanes, t.name), false, t.bytes_read, "texture");
      scene_texture_bytes -= std::min(scene_texture_bytes, t.bytes_read);
    }
    edge(texture_lane, false, scene_texture_bytes, "texture");
    edge(parameter_lane, true, p.geometry.parameter_bytes_written, "bin");
    edge(parameter_lane, false, p.tiles.parameter_bytes_read, "tile lists");
  }
  return svg.str();
}

}  // namespace ontile
