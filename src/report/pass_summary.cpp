// Pass summaries (see pass_summary.h).
#include "report/pass_summary.h"

#include <cstdio>

#include "report/byte_text.h"

namespace ontile {
namespace {

std::string joined(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i ? separator : "") + items[i];
  return out;
}

}  // namespace

PassSummary summarize_pass(const PassReport& p, const CapturedPass* captured, const GraphReport* graph) {
  PassSummary s;
  const bool imr = p.architecture == "imr";
  std::vector<std::string> transient, cleared, discarded;
  for (size_t a = 0; a < p.attachments.size(); ++a) {
    const AttachmentTraffic& t = p.attachments[a];
    const CapturedAttachment* c = captured && a < captured->attachments.size() ? &captured->attachments[a] : nullptr;
    if (t.transient) {
      transient.push_back(t.name);
      continue;
    }
    if (c && c->load != "load") cleared.push_back(t.name + (c->load == "clear" ? " (clear)" : " (dont-care)"));
    if (c && (c->store == "dont-care" || c->store == "resolve")) discarded.push_back(t.name);
  }
  if (!transient.empty()) {
    s.on_chip.push_back("transient " + joined(transient, ", ") +
                        (imr ? " (no memory backing)" : ": lived in tile memory only, never loaded or stored"));
  }
  if (captured && captured->subpasses > 1) {
    std::string names;
    if (graph) {
      for (const GraphReport::ExecutedPass& n : graph->native_passes) {
        if (n.name == p.name) names = ": " + joined(n.subpasses, " + ");
      }
    }
    s.on_chip.push_back(std::to_string(captured->subpasses) + " subpasses merged into one native pass" + names +
                        "; what one subpass wrote and the next read stayed in tile memory");
  }
  if (!cleared.empty() && !imr) s.on_chip.push_back("not loaded: " + joined(cleared, ", ") + ", initialised in tile memory");
  if (!discarded.empty() && !imr) s.on_chip.push_back("not stored: " + joined(discarded, ", ") + " (store: dont-care or resolve only)");
  const double pixels = static_cast<double>(p.width_px) * p.height_px;
  if (!imr && pixels > 0 && p.tiles.fragments_shaded > 0) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%.2f fragments per pixel shaded and blended in tile memory", p.tiles.fragments_shaded / pixels);
    s.on_chip.push_back(buf);
  }
  if (imr) {
    s.on_chip.push_back("immediate mode: render-target cache " + std::to_string(p.render_target_cache_hits) + " hits, " +
                        std::to_string(p.render_target_cache_misses) + " misses");
  }
  for (const AttachmentTraffic& t : p.attachments) {
    if (t.bytes_loaded) s.to_memory.push_back("loaded " + t.name + " " + bytes_text(t.bytes_loaded));
    if (t.bytes_stored) s.to_memory.push_back("stored " + t.name + " " + bytes_text(t.bytes_stored));
    if (t.bytes_resolved) s.to_memory.push_back("resolved " + t.name + " " + bytes_text(t.bytes_resolved));
  }
  if (p.texture.bytes_read) {
    std::vector<std::string> sources;
    for (const TextureSourceTraffic& t : p.texture_sources) {
      if (t.bytes_read) sources.push_back(t.name + (t.render_target ? " (render target) " : " ") + bytes_text(t.bytes_read));
    }
    s.to_memory.push_back("texture reads " + bytes_text(p.texture.bytes_read) + " (" + std::to_string(p.texture.misses) +
                          " cache misses of " + std::to_string(p.texture.accesses) + " lookups" +
                          (sources.empty() ? std::string() : ": " + joined(sources, ", ")) + ")");
  }
  if (p.geometry.parameter_bytes_written || p.tiles.parameter_bytes_read) {
    s.to_memory.push_back("parameter buffer written " + bytes_text(p.geometry.parameter_bytes_written) + ", read " +
                          bytes_text(p.tiles.parameter_bytes_read));
  }
  const uint64_t vertex_index = p.geometry.index_bytes_read + p.geometry.vertex_bytes_read;
  if (vertex_index) s.to_memory.push_back("vertices and indices " + bytes_text(vertex_index));
  return s;
}

std::string pass_summary_text(const PassSummary& s) {
  return "On chip: " + (s.on_chip.empty() ? std::string("nothing of note") : joined(s.on_chip, "; ")) +
         ". Memory: " + (s.to_memory.empty() ? std::string("no traffic") : joined(s.to_memory, "; ")) + ".";
}

}  // namespace ontile
