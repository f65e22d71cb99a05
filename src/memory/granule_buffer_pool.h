// A process-wide pool of texel-trace buffers (vectors of 64-byte granule ids): a tile takes one to
// record into, and the texture replay gives it back as soon as it replayed the tile, so a pass's
// traces circulate through a few buffers that stay in the CPU's caches instead of holding every
// tile's granules until the pass ends. Buffers keep their capacity: recording rarely allocates.
#pragma once
#include <cstdint>
#include <vector>

namespace ontile {

// An empty buffer, the one given back last (the warmest), or a new one.
std::vector<uint64_t> take_granule_buffer();
// Keeps `buffer`'s memory for a later take (emptied); `buffer` is left without any.
void give_back_granule_buffer(std::vector<uint64_t>& buffer);

}  // namespace ontile
