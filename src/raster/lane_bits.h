// Bit i for SIMD lane i, for the kernels that turn a fragment bit set into a lane mask (AND with
// this table, compare with zero) or a mask back into bits. x86 vectors hold at most 16 32-bit lanes.
#pragma once
#include <cstdint>

namespace ontile {

alignas(64) inline constexpr int32_t kLaneBit[16] = {1 << 0, 1 << 1, 1 << 2,  1 << 3,  1 << 4,  1 << 5,
                                                     1 << 6, 1 << 7, 1 << 8,  1 << 9,  1 << 10, 1 << 11,
                                                     1 << 12, 1 << 13, 1 << 14, 1 << 15};

}  // namespace ontile
