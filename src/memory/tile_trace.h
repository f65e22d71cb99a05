// Per-tile records that traffic models replay after all tiles ran, in tile-index order, so the
// counts never depend on which thread ran which tile: the 64-byte texture granules the tile's
// fetches touched, and (for the IMR model) every fragment's colour and depth accesses.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
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

// A tile's texture granules (byte address / 64, consecutive repeats removed): the range
// [begin, end) of the buffer its thread recorded them in, which holds the thread's other tiles
// too (tiler/trace_buffers.h), so a tile allocates nothing. Valid once every tile has run.
struct GranuleRange {
  const std::vector<uint64_t>* buffer = nullptr;
  size_t begin = 0, end = 0;
  std::span<const uint64_t> granules() const {
    if (buffer == nullptr) return {};
    return std::span<const uint64_t>(*buffer).subspan(begin, end - begin);
  }
};

struct TileTrace {
  GranuleRange texture_granules;
  std::vector<FragmentAccess> fragments;  // filled only when fragment recording is on
};

}  // namespace ontile
