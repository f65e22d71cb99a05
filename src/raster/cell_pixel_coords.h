// The pixel column and row of each bit of a cell mask (bit = row * 8 + column), as lane
// tables for the cell kernels' SIMD loads (cell_raster.cpp, cell_depth_simd.cpp).
#pragma once
#include <cstdint>

#include "raster/cell_raster.h"

namespace ontile {

alignas(64) inline constexpr int32_t kCellLx[kCellPixels] = {
    0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7,
    0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7};
alignas(64) inline constexpr int32_t kCellLy[kCellPixels] = {
    0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3, 3,
    4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 5, 5, 5, 5, 5, 6, 6, 6, 6, 6, 6, 6, 6, 7, 7, 7, 7, 7, 7, 7, 7};

}  // namespace ontile
