// Little-endian loads and stores of the packed words attachment formats keep in memory
// (Vulkan's packed formats are little-endian 16- and 32-bit words), shared by the per-pixel
// conversions and the row conversions so both write the same bytes.
#pragma once
#include <bit>
#include <cstdint>

namespace ontile::packed_bytes {

inline void store_u16(uint8_t* dst, uint32_t v) {
  dst[0] = static_cast<uint8_t>(v);
  dst[1] = static_cast<uint8_t>(v >> 8);
}
inline void store_u32(uint8_t* dst, uint32_t v) {
  for (int i = 0; i < 4; ++i) dst[i] = static_cast<uint8_t>(v >> (8 * i));
}
inline uint32_t load_u16(const uint8_t* src) { return src[0] | (uint32_t{src[1]} << 8); }
inline uint32_t load_u32(const uint8_t* src) {
  return src[0] | (uint32_t{src[1]} << 8) | (uint32_t{src[2]} << 16) | (uint32_t{src[3]} << 24);
}
inline void store_f32(uint8_t* dst, float v) { store_u32(dst, std::bit_cast<uint32_t>(v)); }
inline float load_f32(const uint8_t* src) { return std::bit_cast<float>(load_u32(src)); }

}  // namespace ontile::packed_bytes
