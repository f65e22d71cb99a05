// Tables and per-row lines of the peer benchmark (see peer_report.h).
#include "peer_report.h"

#include <cstdio>

namespace ontile::peer {

std::string peer_table(const std::vector<PeerRow>& rows, const std::string& pipeline, bool markdown) {
  const bool cartoon = pipeline == "cartoon";
  const char* agreement = cartoon ? "edge decisions equal" : "primitive ids equal";
  std::string out;
  char line[640];
  if (markdown) {
    std::snprintf(line, sizeof line,
                  "| scene | triangles | threads | ontile median ms | ontile min ms | ontile CPU ms | "
                  "llvmpipe median ms | llvmpipe min ms | llvmpipe CPU ms | ontile / llvmpipe (median) | "
                  "ontile / llvmpipe (CPU) | %s | colour within %d/255 |\n"
                  "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n",
                  agreement, kColorTolerance);
  } else {
    std::snprintf(line, sizeof line, "%-14s %9s %7s | %10s %8s %8s | %10s %8s %8s | %6s %6s | %10s %9s\n", "scene",
                  "triangles", "threads", "ontile med", "min", "CPU", "llvmpipe", "min", "CPU", "ratio", "CPU",
                  cartoon ? "edges eq" : "ids equal", "colour ok");
  }
  out += line;
  for (const PeerRow& r : rows) {
    if (r.pipeline != pipeline) continue;
    const char* fmt = markdown
        ? "| %s | %llu | %d | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.2f | %.2f | %.3f %% | %.2f %% |\n"
        : "%-14s %9llu %7d | %10.1f %8.1f %8.1f | %10.1f %8.1f %8.1f | %6.2f %6.2f | %9.3f%% %8.2f%%\n";
    std::snprintf(line, sizeof line, fmt, r.scene.c_str(), static_cast<unsigned long long>(r.triangles), r.threads,
                  r.ontile.median_ms, r.ontile.min_ms, r.ontile.cpu_ms_per_frame, r.llvmpipe.median_ms,
                  r.llvmpipe.min_ms, r.llvmpipe.cpu_ms_per_frame, r.ontile.median_ms / r.llvmpipe.median_ms,
                  r.ontile.cpu_ms_per_frame / r.llvmpipe.cpu_ms_per_frame,
                  cartoon ? r.edges.percent() : r.ids.percent(), r.color.percent());
    out += line;
  }
  return out;
}

std::string peer_row_line(const PeerRow& r) {
  char line[768];
  int n = std::snprintf(line, sizeof line, "%s, %s, %d thread(s): ontile %.1f ms, llvmpipe %.1f ms (medians; %.2f and "
                        "%.2f cores busy); ",
                        r.pipeline.c_str(), r.scene.c_str(), r.threads, r.ontile.median_ms, r.llvmpipe.median_ms,
                        r.ontile.cores_busy, r.llvmpipe.cores_busy);
  if (r.pipeline == "cartoon") {
    n += std::snprintf(line + n, sizeof line - n,
                       "edge decisions equal on %.3f%% (edge pixels: ontile %llu, llvmpipe %llu; only ontile %llu, "
                       "only llvmpipe %llu, of which %llu next to an edge of the other); ",
                       r.edges.percent(), static_cast<unsigned long long>(r.edges.ontile_edges),
                       static_cast<unsigned long long>(r.edges.llvmpipe_edges),
                       static_cast<unsigned long long>(r.edges.only_ontile),
                       static_cast<unsigned long long>(r.edges.only_llvmpipe),
                       static_cast<unsigned long long>(r.edges.shifted));
  } else {
    n += std::snprintf(line + n, sizeof line - n,
                       "primitive ids equal on %.3f%% (%llu pixels differ in coverage, %llu in id, of which %llu are "
                       "boundaries shifted by a pixel); ",
                       r.ids.percent(), static_cast<unsigned long long>(r.ids.coverage_differs),
                       static_cast<unsigned long long>(r.ids.id_differs),
                       static_cast<unsigned long long>(r.ids.boundary_shifts));
  }
  std::snprintf(line + n, sizeof line - n, "colour within %d/255 on %.2f%% (mean |diff| %.3f)\n", kColorTolerance,
                r.color.percent(), r.color.mean_abs_diff);
  return line;
}

}  // namespace ontile::peer
