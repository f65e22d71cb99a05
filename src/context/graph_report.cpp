// Render-graph decisions as JSON and as a table (see graph_report.h).
#include "context/graph_report.h"

#include <cstdio>
#include <sstream>

namespace ontile {

const char* graph_decision_name(GraphReason reason) {
  switch (reason) {
    case GraphReason::Merged: return "merged";
    case GraphReason::TextureReadOfOutput:
    case GraphReason::WritesSampledTexture:
    case GraphReason::SizeDiffers:
    case GraphReason::SampleCountDiffers:
    case GraphReason::DepthDiffers:
    case GraphReason::ClearsHeldAttachment:
    case GraphReason::TileBudgetExceeded:
    case GraphReason::ExternalPass: return "not merged";
    case GraphReason::CulledUnread:
    case GraphReason::CulledUnreadAttachment: return "culled";
    case GraphReason::StoredReadLater:
    case GraphReason::StoredOutput: return "stored";
    case GraphReason::TransientNotReadLater: return "transient";
    case GraphReason::LoadCleared:
    case GraphReason::LoadDontCare:
    case GraphReason::LoadKept: return "load";
  }
  return "?";
}

const char* graph_reason_name(GraphReason reason) {
  switch (reason) {
    case GraphReason::Merged: return "only own-pixel reads of earlier outputs";
    case GraphReason::TextureReadOfOutput: return "texture read of an earlier output";
    case GraphReason::WritesSampledTexture: return "writes a texture an earlier subpass samples";
    case GraphReason::SizeDiffers: return "size differs";
    case GraphReason::SampleCountDiffers: return "sample count differs";
    case GraphReason::DepthDiffers: return "depth attachment differs";
    case GraphReason::ClearsHeldAttachment: return "clears an attachment an earlier subpass holds";
    case GraphReason::TileBudgetExceeded: return "tile budget exceeded";
    case GraphReason::ExternalPass: return "external pass";
    case GraphReason::CulledUnread: return "unread";
    case GraphReason::CulledUnreadAttachment: return "attachment unread";
    case GraphReason::StoredReadLater: return "read later";
    case GraphReason::StoredOutput: return "frame output";
    case GraphReason::TransientNotReadLater: return "not read later";
    case GraphReason::LoadCleared: return "cleared";
    case GraphReason::LoadDontCare: return "dont-care";
    case GraphReason::LoadKept: return "written earlier";
  }
  return "?";
}

nlohmann::json graph_report_json(const GraphReport& report) {
  nlohmann::json passes = nlohmann::json::array();
  for (const GraphReport::WrittenPass& p : report.passes) {
    passes.push_back({{"name", p.name}, {"writes", p.writes}, {"own_pixel_reads", p.own_pixel_reads},
                      {"texture_reads", p.texture_reads}, {"culled", p.culled}});
  }
  nlohmann::json native = nlohmann::json::array();
  for (const GraphReport::ExecutedPass& p : report.native_passes) {
    nlohmann::json attachments = nlohmann::json::array();
    for (const auto& a : p.attachments) {
      attachments.push_back({{"resource", a.resource}, {"load", a.load}, {"store", a.store},
                             {"memoryless", a.memoryless}});
    }
    native.push_back({{"name", p.name}, {"subpasses", p.subpasses}, {"attachments", attachments},
                      {"external", p.external}});
  }
  nlohmann::json decisions = nlohmann::json::array();
  for (const GraphDecision& d : report.decisions) {
    nlohmann::json entry = {{"pass", d.pass}, {"decision", graph_decision_name(d.reason)},
                            {"reason", graph_reason_name(d.reason)}};
    if (!d.resource.empty()) entry["resource"] = d.resource;
    decisions.push_back(entry);
  }
  return {{"mode", report.mode}, {"passes", passes}, {"native_passes", native}, {"decisions", decisions}};
}

std::string graph_report_table(const GraphReport& report) {
  std::ostringstream out;
  char line[320];
  out << "render graph (" << report.mode << "): " << report.passes.size() << " passes as written, "
      << report.native_passes.size() << " render passes executed\n";
  for (const GraphReport::ExecutedPass& p : report.native_passes) {
    out << "  " << p.name << (p.external ? " (external)" : "") << ":";
    for (const auto& a : p.attachments) {
      out << " " << a.resource << " (" << a.load << "/" << a.store << (a.memoryless ? ", memoryless" : "") << ")";
    }
    out << "\n";
  }
  std::snprintf(line, sizeof line, "  %-24s %-16s %-11s %s\n", "pass", "attachment", "decision", "reason");
  out << line;
  for (const GraphDecision& d : report.decisions) {
    std::snprintf(line, sizeof line, "  %-24s %-16s %-11s %s\n", d.pass.c_str(),
                  d.resource.empty() ? "-" : d.resource.c_str(), graph_decision_name(d.reason),
                  graph_reason_name(d.reason));
    out << line;
  }
  return out.str();
}

}  // namespace ontile
