// Per-tile records that traffic models replay in tile-index order, so the counts never depend on
// which thread ran which tile: the 64-byte texture granules the tile's fetches touched (replayed
// as tiles complete), and (for the IMR model) every fragment's colour and depth accesses.
#pragma once
#include <cstddef>
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
  // The texture granules the tile's fetches touched (byte address / 64, consecutive repeats
  // removed), in the tile's own buffer: only its tile writes it, so once the tile ran any thread
  // may read it while other tiles still record (the streamed replay, texture_replay_stream.h).
  // Buffers come from a pool and go back to it once replayed (memory/granule_buffer_pool.h).
  std::vector<uint64_t> texture_granules;
  std::vector<FragmentAccess> fragments;  // filled only when fragment recording is on
};

}  // namespace ontile
