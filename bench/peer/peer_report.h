// The peer benchmark's results: one row per pipeline, scene and thread count, printed as a
// plain-text or Markdown table per pipeline with the agreement columns that pipeline has
// (primitive ids for lambert, edge decisions for cartoon; colour for both).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "frame_times.h"
#include "peer_compare.h"

namespace ontile::peer {

struct PeerRow {
  std::string pipeline, scene;
  uint64_t triangles = 0;
  int threads = 0;
  FrameTimes ontile, llvmpipe;
  IdAgreement ids;      // lambert
  EdgeAgreement edges;  // cartoon
  ColorAgreement color;
};

// The rows of `pipeline` as a table; the ratios are ontile / llvmpipe of the median wall times
// and of the CPU times per frame.
std::string peer_table(const std::vector<PeerRow>& rows, const std::string& pipeline, bool markdown);

// The one-line summary printed as each row completes.
std::string peer_row_line(const PeerRow& row);

}  // namespace ontile::peer
