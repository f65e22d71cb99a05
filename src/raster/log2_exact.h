// log2 of a float without a libm call, bit for bit what glibc's log2f returns for every float
// that is not a NaN or negative (those go to std::log2): the sampler's level of detail takes
// one per quad and read, where the call and its register spills cost more than the function.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>

namespace ontile {

// The algorithm and tables of glibc's and musl's log2f (ARM optimized-routines, Szabolcs Nagy,
// MIT): x = 2^k z, z in [0x1.66p-1, 0x1.66p0) split in 16 intervals of centre c,
// log2(x) = k + log2(c) + poly(z / c - 1), in double, rounded once to float. Evaluated with
// separate multiplies and adds (the project compiles without contraction), it gives the same
// bits as glibc's FMA and non-FMA builds for all 2^32 inputs but NaNs and negatives
// (tests/raster/log2_exact_test.cpp checks a sample; the exhaustive check is in its header).
namespace log2_exact_detail {
// Per interval: 1 / c and log2(c), interleaved (entry i at [2 i], [2 i + 1]) so that lanes can
// gather both from one table (texture_quad_lod-inl.h).
inline constexpr double kInvcLogc[32] = {
    0x1.661ec79f8f3bep+0, -0x1.efec65b963019p-2, 0x1.571ed4aaf883dp+0, -0x1.b0b6832d4fca4p-2,
    0x1.49539f0f010bp+0,  -0x1.7418b0a1fb77bp-2, 0x1.3c995b0b80385p+0, -0x1.39de91a6dcf7bp-2,
    0x1.30d190c8864a5p+0, -0x1.01d9bf3f2b631p-2, 0x1.25e227b0b8eap+0,  -0x1.97c1d1b3b7afp-3,
    0x1.1bb4a4a1a343fp+0, -0x1.2f9e393af3c9fp-3, 0x1.12358f08ae5bap+0, -0x1.960cbbf788d5cp-4,
    0x1.0953f419900a7p+0, -0x1.a6f9db6475fcep-5, 0x1p+0,                0x0p+0,
    0x1.e608cfd9a47acp-1, 0x1.338ca9f24f53dp-4,  0x1.ca4b31f026aap-1,  0x1.476a9543891bap-3,
    0x1.b2036576afce6p-1, 0x1.e840b4ac4e4d2p-3,  0x1.9c2d163a1aa2dp-1, 0x1.40645f0c6651cp-2,
    0x1.886e6037841edp-1, 0x1.88e9c2c1b9ff8p-2,  0x1.767dcf5534862p-1, 0x1.ce0a44eb17bccp-2,
};
inline constexpr double kPoly[4] = {-0x1.712b6f70a7e4dp-2, 0x1.ecabf496832ep-2, -0x1.715479ffae3dep-1,
                                    0x1.715475f35c8b8p0};
}  // namespace log2_exact_detail

inline float log2_exact(float x) {
  using log2_exact_detail::kInvcLogc;
  using log2_exact_detail::kPoly;
  uint32_t ix;
  std::memcpy(&ix, &x, sizeof(ix));
  if (ix == 0x3f800000u) return 0.0f;
  if (ix - 0x00800000u >= 0x7f800000u - 0x00800000u) {  // zero, subnormal, inf, NaN, negative
    if (ix * 2u == 0u) return -INFINITY;
    if (ix == 0x7f800000u) return x;
    if ((ix & 0x80000000u) || ix * 2u >= 0xff000000u) return std::log2(x);
    const float normalised = x * 0x1p23f;  // subnormal: scale into the normal range
    std::memcpy(&ix, &normalised, sizeof(ix));
    ix -= 23u << 23;
  }
  const uint32_t tmp = ix - 0x3f330000u;
  const double* e = kInvcLogc + 2 * ((tmp >> 19) % 16);
  const uint32_t iz = ix - (tmp & 0xff800000u);
  const int k = static_cast<int32_t>(tmp) >> 23;
  float zf;
  std::memcpy(&zf, &iz, sizeof(zf));
  const double r = static_cast<double>(zf) * e[0] - 1.0;
  const double y0 = e[1] + static_cast<double>(k);
  const double r2 = r * r;
  double y = kPoly[1] * r + kPoly[2];
  y = kPoly[0] * r2 + y;
  const double p = kPoly[3] * r + y0;
  y = y * r2 + p;
  return static_cast<float>(y);
}

}  // namespace ontile
