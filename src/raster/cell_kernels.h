// The cell kernels behind cell_coverage and interpolate_and_test_cell_depth as plain function
// pointers for the SIMD target chosen now: the tile loop calls them a few times per triangle,
// and one dispatch per tile costs less than one per call (~35 instructions each).
#pragma once
#include <cstdint>

#include "raster/cell_raster.h"

namespace ontile {

// Bit i set where e0[k] + a[k] * lx_i + b[k] * ly_i >= 0 for every edge k < edges, for the
// rows holding bits [first_bit, end_bit) (others may be set or not): cell_coverage's int32
// lanes. Every partial sum must fit int32.
using CoverageLanesKernel = uint64_t (*)(const int32_t* e0, const int32_t* a, const int32_t* b,
                                         int edges, int first_bit, int end_bit);
// interpolate_and_test_cell_depth(depth, sx, sy, ...) is this kernel given
// sample_centre_offset(sx), sample_centre_offset(sy) and the other arguments as they are.
using CellDepthTestKernelFn = CellMask (*)(const CellPlane& depth, float off_x, float off_y,
                                           int first_row, int end_row, float* z, CompareOp op,
                                           bool test, bool write, float* stored, int stride,
                                           int rows, CellMask candidates, float* range_lo,
                                           float* range_hi);

// The kernels of the SIMD target chosen now; valid until the next force_simd_target.
CoverageLanesKernel coverage_lanes_kernel();
CellDepthTestKernelFn cell_depth_test_kernel();

// A sample offset in 1/256 px from the pixel's top-left corner as an offset from its centre in
// px (what the depth kernels take).
float sample_centre_offset(int32_t s);

}  // namespace ontile
