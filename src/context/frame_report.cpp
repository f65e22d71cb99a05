// Frame report totals, JSON and table (see frame_report.h).
#include "context/frame_report.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace ontile {

uint64_t FrameReport::bytes_read() const {
  uint64_t sum = 0;
  for (const PassReport& p : passes) sum += p.bytes_read();
  return sum;
}

uint64_t FrameReport::bytes_written() const {
  uint64_t sum = 0;
  for (const PassReport& p : passes) sum += p.bytes_written();
  return sum;
}

std::map<std::string, uint64_t> FrameReport::bytes_by_category() const {
  std::map<std::string, uint64_t> c{{"attachment_load", 0}, {"attachment_store", 0},
                                    {"resolve", 0}, {"vertex_index", 0}, {"texture", 0},
                                    {"parameter_buffer_write", 0}, {"parameter_buffer_read", 0}};
  for (const PassReport& p : passes) {
    for (const AttachmentTraffic& a : p.attachments) {
      c["attachment_load"] += a.bytes_loaded;
      c["attachment_store"] += a.bytes_stored;
      c["resolve"] += a.bytes_resolved;
    }
    c["vertex_index"] += p.geometry.index_bytes_read + p.geometry.vertex_bytes_read;
    c["texture"] += p.texture.bytes_read;
    c["parameter_buffer_write"] += p.geometry.parameter_bytes_written;
    c["parameter_buffer_read"] += p.tiles.parameter_bytes_read;
  }
  return c;
}

namespace {

nlohmann::json geometry_json(const GeometryCounters& g) {
  return {{"triangles_submitted", g.triangles_submitted},
          {"triangles_binned", g.triangles_binned},
          {"triangles_culled", g.triangles_culled},
          {"triangles_clipped", g.triangles_clipped},
          {"triangles_outside", g.triangles_outside},
          {"triangles_zero_area", g.triangles_zero_area},
          {"triangles_non_finite", g.triangles_non_finite},
          {"vertices_shaded", g.vertices_shaded},
          {"varyings_sanitized", g.varyings_sanitized},
          {"tile_list_entries", g.tile_list_entries}};
}

nlohmann::json texture_sources_json(const PassReport& p) {
  nlohmann::json sources = nlohmann::json::array();
  for (const TextureSourceTraffic& t : p.texture_sources) {
    sources.push_back({{"name", t.name},
                       {"kind", t.render_target ? "render_target" : "texture"},
                       {"misses", t.misses},
                       {"bytes_read", t.bytes_read}});
  }
  return sources;
}

// One column of the pass's per-tile statistics, tile index order.
template <typename Field>
nlohmann::json tile_column(const PassReport& p, Field field) {
  nlohmann::json column = nlohmann::json::array();
  for (const TileStats& t : p.tile_stats) column.push_back(field(t));
  return column;
}

nlohmann::json tile_stats_json(const PassReport& p) {
  return {{"tiles_x", p.tiles_x()},
          {"tiles_y", p.tiles_y()},
          {"triangles", tile_column(p, [](const TileStats& t) { return t.triangles; })},
          {"fragments_shaded", tile_column(p, [](const TileStats& t) { return t.fragments_shaded; })},
          {"fragments_depth_rejected", tile_column(p, [](const TileStats& t) { return t.fragments_depth_rejected; })},
          {"cells_rasterized", tile_column(p, [](const TileStats& t) { return t.cells_rasterized; })},
          {"cells_hiz_rejected", tile_column(p, [](const TileStats& t) { return t.cells_hiz_rejected; })},
          {"parameter_bytes_read", tile_column(p, [](const TileStats& t) { return t.parameter_bytes_read; })},
          {"bytes_loaded", tile_column(p, [](const TileStats& t) { return t.bytes_loaded; })},
          {"bytes_stored", tile_column(p, [](const TileStats& t) { return t.bytes_stored; })},
          {"texture_bytes_read", tile_column(p, [](const TileStats& t) { return t.texture_bytes_read; })}};
}

nlohmann::json pass_json(const PassReport& p) {
  nlohmann::json attachments = nlohmann::json::array();
  for (const AttachmentTraffic& a : p.attachments) {
    attachments.push_back({{"name", a.name},
                           {"format", format_name(a.format)},
                           {"transient", a.transient},
                           {"bytes_loaded", a.bytes_loaded},
                           {"bytes_stored", a.bytes_stored},
                           {"bytes_resolved", a.bytes_resolved},
                           {"afbc", a.afbc},
                           {"afbc_bytes_saved", a.afbc_bytes_saved},
                           {"te_tiles_eliminated", a.te_tiles_eliminated},
                           {"te_bytes_saved", a.te_bytes_saved}});
  }
  const uint64_t pixels = static_cast<uint64_t>(p.width_px) * p.height_px;
  return {{"name", p.name},
          {"architecture", p.architecture},
          {"width_px", p.width_px},
          {"height_px", p.height_px},
          {"samples", p.samples},
          {"tile_size_px", {p.tile_width_px, p.tile_height_px}},
          {"tile_size_reduced", p.tile_size_reduced},
          {"transaction_elimination", p.transaction_elimination},
          {"color_bits_per_px", p.color_bits_per_px},
          {"tiles", p.tiles_total},
          {"tiles_executed", p.tiles.tiles_executed},
          {"bytes_read", p.bytes_read()},
          {"bytes_written", p.bytes_written()},
          {"parameter_buffer", {{"bytes_written", p.geometry.parameter_bytes_written},
                                {"position_bytes_written", p.geometry.parameter_position_bytes_written},
                                {"varying_bytes_written", p.geometry.parameter_varying_bytes_written},
                                {"bytes_read", p.tiles.parameter_bytes_read},
                                {"cache", {{"accesses", p.parameter_cache.accesses},
                                           {"hits", p.parameter_cache.hits},
                                           {"misses", p.parameter_cache.misses}}}}},
          {"vertex_index_bytes_read", p.geometry.index_bytes_read + p.geometry.vertex_bytes_read},
          {"texture", {{"accesses", p.texture.accesses}, {"hits", p.texture.hits},
                       {"misses", p.texture.misses}, {"bytes_read", p.texture.bytes_read},
                       {"sources", texture_sources_json(p)}}},
          {"render_target_cache", {{"hits", p.render_target_cache_hits},
                                   {"misses", p.render_target_cache_misses}}},
          {"fragments_shaded", p.tiles.fragments_shaded},
          {"fragments_depth_rejected", p.tiles.fragments_depth_rejected},
          {"cells_rasterized", p.tiles.cells_rasterized},
          {"cells_hiz_rejected", p.tiles.cells_hiz_rejected},
          {"overdraw", pixels ? static_cast<double>(p.tiles.fragments_shaded) / pixels : 0.0},
          {"geometry", geometry_json(p.geometry)},
          {"attachments", attachments}};
}

std::string mib(uint64_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return buf;
}

}  // namespace

nlohmann::json frame_report_json(const FrameReport& frame, const FrameReportOptions& options) {
  nlohmann::json passes = nlohmann::json::array();
  nlohmann::json timing_passes = nlohmann::json::array();
  for (const PassReport& p : frame.passes) {
    passes.push_back(pass_json(p));
    nlohmann::json timing = {{"name", p.name}, {"binning_ms", p.binning_ms}, {"tiles_ms", p.tiles_ms}};
    if (options.tiles) {
      passes.back()["tile_stats"] = tile_stats_json(p);
      timing["tile_thread"] = tile_column(p, [](const TileStats& t) { return t.thread; });
      timing["tile_order"] = tile_column(p, [](const TileStats& t) { return t.order; });
    }
    timing_passes.push_back(std::move(timing));
  }
  nlohmann::json categories = nlohmann::json::object();
  for (const auto& [name, bytes] : frame.bytes_by_category()) categories[name] = bytes;
  nlohmann::json report = {{"format", "ontile-report"},
                            {"schema_version", 5},  // docs/report.schema.json
                            {"frame", {{"bytes_read", frame.bytes_read()},
                                       {"bytes_written", frame.bytes_written()},
                                       {"by_category", categories}}},
                            {"passes", passes},
                            {"timing", {{"threads", frame.threads}, {"total_ms", frame.total_ms},
                                        {"passes", timing_passes}}}};
  if (frame.graph) report["graph"] = graph_report_json(*frame.graph);
  return report;
}

std::string frame_report_table(const FrameReport& frame) {
  std::ostringstream out;
  char line[256];
  std::snprintf(line, sizeof line, "%-22s %8s %6s %14s %14s %12s %10s\n", "pass", "tile", "tiles",
                "read", "written", "fragments", "overdraw");
  out << line;
  for (const PassReport& p : frame.passes) {
    const double pixels = static_cast<double>(p.width_px) * p.height_px;
    // An immediate-mode pass has no tiles (its traffic goes through the render-target cache,
    // shown below); the tile columns say so instead of the simulator's internal work split.
    const bool imr = p.architecture == "imr";
    char tile[32] = "     IMR", tiles[32] = "-";
    if (!imr) {
      std::snprintf(tile, sizeof tile, "%5dx%-2d", p.tile_width_px, p.tile_height_px);
      std::snprintf(tiles, sizeof tiles, "%llu", static_cast<unsigned long long>(p.tiles_total));
    }
    std::snprintf(line, sizeof line, "%-22s %8s %6s %14s %14s %12llu %10.2f\n", p.name.c_str(), tile,
                  tiles, mib(p.bytes_read()).c_str(), mib(p.bytes_written()).c_str(),
                  static_cast<unsigned long long>(p.tiles.fragments_shaded),
                  pixels > 0 ? p.tiles.fragments_shaded / pixels : 0.0);
    out << line;
    if (imr) {
      std::snprintf(line, sizeof line, "  %-20s %llu hits, %llu misses\n", "render-target cache",
                    static_cast<unsigned long long>(p.render_target_cache_hits),
                    static_cast<unsigned long long>(p.render_target_cache_misses));
      out << line;
    }
    for (const AttachmentTraffic& a : p.attachments) {
      const std::string te = a.te_tiles_eliminated
                                 ? "  TE skipped " + std::to_string(a.te_tiles_eliminated) + " tiles, " + mib(a.te_bytes_saved)
                                 : "";
      std::snprintf(line, sizeof line, "  %-20s %-10s %-9s load %12s  store %12s  resolve %12s%s%s\n",
                    a.name.c_str(), format_name(a.format), a.transient ? "transient" : "memory",
                    mib(a.bytes_loaded).c_str(), mib(a.bytes_stored).c_str(),
                    mib(a.bytes_resolved).c_str(),
                    a.afbc ? ("  AFBC saved " + mib(static_cast<uint64_t>(std::max<int64_t>(a.afbc_bytes_saved, 0)))).c_str() : "",
                    te.c_str());
      out << line;
    }
    std::snprintf(line, sizeof line, "  %-20s %llu accesses, %llu hits, %llu misses, read %s\n", "texture cache",
                  static_cast<unsigned long long>(p.texture.accesses),
                  static_cast<unsigned long long>(p.texture.hits),
                  static_cast<unsigned long long>(p.texture.misses), mib(p.texture.bytes_read).c_str());
    out << line;
    // Where the texture bytes came from, largest first; the rest summed on one line.
    constexpr size_t kSourcesShown = 5;
    uint64_t rest_bytes = 0;
    for (size_t i = 0; i < p.texture_sources.size(); ++i) {
      const TextureSourceTraffic& t = p.texture_sources[i];
      if (i >= kSourcesShown) {
        rest_bytes += t.bytes_read;
        continue;
      }
      std::snprintf(line, sizeof line, "    from %-34s %-13s %12s\n", t.name.c_str(),
                    t.render_target ? "render target" : "texture", mib(t.bytes_read).c_str());
      out << line;
    }
    if (p.texture_sources.size() > kSourcesShown) {
      std::snprintf(line, sizeof line, "    from %-34s %-13s %12s\n",
                    ("(" + std::to_string(p.texture_sources.size() - kSourcesShown) + " more)").c_str(),
                    "", mib(rest_bytes).c_str());
      out << line;
    }
    std::snprintf(line, sizeof line, "  %-20s %llu 8x8 cells rasterized, %llu skipped by hierarchical Z\n",
                  "raster", static_cast<unsigned long long>(p.tiles.cells_rasterized),
                  static_cast<unsigned long long>(p.tiles.cells_hiz_rejected));
    out << line;
  }
  out << "frame: read " << mib(frame.bytes_read()) << " (" << frame.bytes_read() << " B), written "
      << mib(frame.bytes_written()) << " (" << frame.bytes_written() << " B)\n";
  for (const auto& [name, bytes] : frame.bytes_by_category()) {
    std::snprintf(line, sizeof line, "  %-24s %14s\n", name.c_str(), mib(bytes).c_str());
    out << line;
  }
  if (frame.graph) out << graph_report_table(*frame.graph);
  return out.str();
}

}  // namespace ontile
