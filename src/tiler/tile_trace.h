// Per-tile records that traffic models replay after all tiles ran, in tile-index order, so the
// counts never depend on which thread ran which tile: the 64-byte texture granules the tile's
// fetches touched, and (for the IMR model) every fragment's colour and depth accesses.
#pragma once
#include <cstdint>
#include <vector>

namespace ontile {

enum FragmentAccessFlags : uint8_t {
  kDepthRead = 1,     // the depth test read the stored depth
  kDepthWritten = 2,
  kColorWritten = 4,
  kColorRead = 8,     // blending read the destination colour
};

struct FragmentAccess {
  uint32_t triangle_ref = 0;  // parameter-buffer reference, increasing in submission order
  uint16_t x_px = 0, y_px = 0;
  uint8_t covered_samples = 0;  // sample mask the triangle covered
  uint8_t written_samples = 0;  // samples that passed every test and were written
  uint8_t flags = 0;            // FragmentAccessFlags
  uint8_t subpass = 0;          // index of the triangle's subpass (whose colour outputs it writes)
};

struct TileTrace {
  std::vector<uint64_t> texture_granules;  // byte address / 64, consecutive repeats removed
  std::vector<FragmentAccess> fragments;   // filled only when fragment recording is on
};

}  // namespace ontile
