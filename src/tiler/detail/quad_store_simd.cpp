// SIMD quad write-back and plane fills (see quad_store_simd.h), compiled per target by
// Highway's foreach_target.
// Loads, shuffles, table reads and stores only, so every target writes the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tiler/detail/quad_store_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "tiler/detail/quad_store_simd.h"

#include <bit>
#include <cstring>

#include "raster/pixel_format.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Quad lanes f .. f + 3 of R, G, B, A as the four RGBA pixels top, top + 4 (floats), bottom and
// bottom + 4, each stored where its bit of `mask` is set: a 4x4 transpose on 128-bit lanes.
HWY_INLINE void store_quad_pixels(const float* const channels[4], int32_t f, float* top, float* bottom,
                                  uint32_t mask) {
  float* const dst[4] = {top, top + 4, bottom, bottom + 4};
#if HWY_TARGET == HWY_SCALAR
  for (int lane = 0; lane < 4; ++lane) {
    if (!((mask >> lane) & 1u)) continue;
    for (int c = 0; c < 4; ++c) dst[lane][c] = channels[c][f + lane];
  }
#else
  const hn::Full128<float> d;
  const auto r = hn::LoadU(d, channels[0] + f), g = hn::LoadU(d, channels[1] + f);
  const auto b = hn::LoadU(d, channels[2] + f), a = hn::LoadU(d, channels[3] + f);
  const auto rg_low = hn::InterleaveLower(d, r, g), ba_low = hn::InterleaveLower(d, b, a);
  const auto rg_high = hn::InterleaveUpper(d, r, g), ba_high = hn::InterleaveUpper(d, b, a);
  if (mask & 1u) hn::StoreU(hn::ConcatLowerLower(d, ba_low, rg_low), d, dst[0]);
  if (mask & 2u) hn::StoreU(hn::ConcatUpperUpper(d, ba_low, rg_low), d, dst[1]);
  if (mask & 4u) hn::StoreU(hn::ConcatLowerLower(d, ba_high, rg_high), d, dst[2]);
  if (mask & 8u) hn::StoreU(hn::ConcatUpperUpper(d, ba_high, rg_high), d, dst[3]);
#endif
}

void StoreFullQuadsKernel(const float* const channels[4], const int32_t* first_fragment,
                          const uint32_t* pixel, int quad_count, int row_pixels,
                          glm::vec4* plane) {
  static_assert(sizeof(glm::vec4) == 4 * sizeof(float), "a vec4 is four packed floats");
  // The plane as floats (four per pixel), not through a vec4's member.
  float* const floats = reinterpret_cast<float*>(plane);
  const size_t row_floats = 4 * static_cast<size_t>(row_pixels);
  for (int q = 0; q < quad_count; ++q) {
    float* top = floats + 4 * static_cast<size_t>(pixel[q]);
    store_quad_pixels(channels, first_fragment[q], top, top + row_floats, 0xFu);
  }
}

// StoreFullQuadsKernel with each pixel stored only where its lane bit is set.
void StoreQuadsKernel(const float* const channels[4], const int32_t* first_fragment,
                      const uint32_t* pixel, const uint8_t* lanes, int quad_count, int row_pixels,
                      glm::vec4* plane) {
  float* const floats = reinterpret_cast<float*>(plane);
  const size_t row_floats = 4 * static_cast<size_t>(row_pixels);
  for (int q = 0; q < quad_count; ++q) {
    float* top = floats + 4 * static_cast<size_t>(pixel[q]);
    store_quad_pixels(channels, first_fragment[q], top, top + row_floats, lanes[q]);
  }
}

void LoadFullQuadsKernel(const glm::vec4* plane, const uint32_t* pixel, int quad_count, int row_pixels,
                         float* const channels[4]) {
  const float* const floats = reinterpret_cast<const float*>(plane);
  const size_t row_floats = 4 * static_cast<size_t>(row_pixels);
  for (int q = 0; q < quad_count; ++q) {
    const float* top = floats + 4 * static_cast<size_t>(pixel[q]);
    const float* bottom = top + row_floats;
    const size_t f = 4 * static_cast<size_t>(q);
#if HWY_TARGET == HWY_SCALAR
    for (int lane = 0; lane < 4; ++lane) {
      const float* src = (lane < 2 ? top : bottom) + 4 * (lane & 1);
      for (int c = 0; c < 4; ++c) channels[c][f + lane] = src[c];
    }
#else
    // The inverse 4x4 transpose: four RGBA pixels into the quad's lanes of R, G, B, A.
    const hn::Full128<float> d;
    const auto p0 = hn::LoadU(d, top), p1 = hn::LoadU(d, top + 4);
    const auto p2 = hn::LoadU(d, bottom), p3 = hn::LoadU(d, bottom + 4);
    const auto xy_top = hn::InterleaveLower(d, p0, p1), xy_bottom = hn::InterleaveLower(d, p2, p3);
    const auto zw_top = hn::InterleaveUpper(d, p0, p1), zw_bottom = hn::InterleaveUpper(d, p2, p3);
    hn::StoreU(hn::ConcatLowerLower(d, xy_bottom, xy_top), d, channels[0] + f);
    hn::StoreU(hn::ConcatUpperUpper(d, xy_bottom, xy_top), d, channels[1] + f);
    hn::StoreU(hn::ConcatLowerLower(d, zw_bottom, zw_top), d, channels[2] + f);
    hn::StoreU(hn::ConcatUpperUpper(d, zw_bottom, zw_top), d, channels[3] + f);
#endif
  }
}

// Rows of side-by-side full quads with consecutive fragments (a whole-tile batch's row
// segments): segment s has quads[s] quads from batch quad first[s] on, its top left at plane
// pixel top[s]; the codes as 64-bit pixel pairs, even pairs to the top row and odd pairs to the
// bottom row. Copies only.
void StoreQuadRowsCodesKernel(const uint32_t* codes, const int32_t* first, const int32_t* quads,
                              const uint32_t* top, int segments, int row_pixels, uint32_t* plane) {
  for (int s = 0; s < segments; ++s) {
    const uint32_t* const src = codes + 4 * first[s];
    uint32_t* const top_row = plane + top[s];
    uint32_t* const bottom_row = top_row + row_pixels;
    int q = 0;
#if HWY_TARGET != HWY_SCALAR
    const hn::ScalableTag<uint64_t> d;
    const int n = static_cast<int>(hn::Lanes(d));  // quads per two vectors
    for (; q + n <= quads[s]; q += n) {
      const uint64_t* pairs = reinterpret_cast<const uint64_t*>(src + 4 * q);
      const auto low = hn::LoadU(d, pairs), high = hn::LoadU(d, pairs + n);
      hn::StoreU(hn::ConcatEven(d, high, low), d, reinterpret_cast<uint64_t*>(top_row + 2 * q));
      hn::StoreU(hn::ConcatOdd(d, high, low), d, reinterpret_cast<uint64_t*>(bottom_row + 2 * q));
    }
#endif
    for (; q < quads[s]; ++q) {
      std::memcpy(top_row + 2 * q, src + 4 * q, 2 * sizeof(uint32_t));
      std::memcpy(bottom_row + 2 * q, src + 4 * q + 2, 2 * sizeof(uint32_t));
    }
  }
}

// Each quad's four codes: (R, G, B, A) of lane = table lookups of its bytes (sRGB or UNORM
// colour table, UNORM alpha table).
void LoadFullQuadCodesKernel(const uint32_t* plane, const uint32_t* pixel, int quad_count,
                             int row_pixels, bool srgb, float* const channels[4]) {
  const float* const unorm = unorm8_decode_table().data();
  const float* const colour = srgb ? srgb8_decode_table().data() : unorm;
  for (int q = 0; q < quad_count; ++q) {
    const uint32_t* top = plane + pixel[q];
    const uint32_t* bottom = top + row_pixels;
    const size_t f = 4 * static_cast<size_t>(q);
#if HWY_TARGET == HWY_SCALAR
    const uint32_t quad[4] = {top[0], top[1], bottom[0], bottom[1]};
    for (int lane = 0; lane < 4; ++lane) {
      for (int c = 0; c < 4; ++c) {
        channels[c][f + lane] = (c == 3 ? unorm : colour)[(quad[lane] >> (8 * c)) & 0xFFu];
      }
    }
#else
    const hn::Full128<float> df;
    const hn::Full128<int32_t> di;
    const hn::Full64<int32_t> dh;
    const auto codes = hn::Combine(di, hn::LoadU(dh, reinterpret_cast<const int32_t*>(bottom)),
                                   hn::LoadU(dh, reinterpret_cast<const int32_t*>(top)));
    const auto byte = hn::Set(di, 0xFF);
    hn::StoreU(hn::GatherIndex(df, colour, hn::And(codes, byte)), df, channels[0] + f);
    hn::StoreU(hn::GatherIndex(df, colour, hn::And(hn::ShiftRight<8>(codes), byte)), df, channels[1] + f);
    hn::StoreU(hn::GatherIndex(df, colour, hn::And(hn::ShiftRight<16>(codes), byte)), df, channels[2] + f);
    hn::StoreU(hn::GatherIndex(df, unorm, hn::And(hn::ShiftRight<24>(codes), byte)), df, channels[3] + f);
#endif
  }
}

// Whole vectors of the value repeated (a vec4 per 128-bit block), four per iteration; copies
// only, so every target writes the same bits.
void FillPlaneKernel(glm::vec4* plane, size_t count, glm::vec4 value) {
  float* const floats = reinterpret_cast<float*>(plane);
  const size_t total = 4 * count;
  size_t i = 0;
#if HWY_TARGET != HWY_SCALAR
  const hn::ScalableTag<float> d;
  const size_t n = hn::Lanes(d);
  if (n % 4 == 0) {
    alignas(64) float repeated[64];
    for (size_t k = 0; k < n && k < 64; ++k) repeated[k] = value[static_cast<int>(k % 4)];
    if (n <= 64) {
      const auto v = hn::Load(d, repeated);
      for (; i + 4 * n <= total; i += 4 * n) {
        hn::StoreU(v, d, floats + i);
        hn::StoreU(v, d, floats + i + n);
        hn::StoreU(v, d, floats + i + 2 * n);
        hn::StoreU(v, d, floats + i + 3 * n);
      }
      for (; i + n <= total; i += n) hn::StoreU(v, d, floats + i);
    }
  }
#endif
  for (; i < total; ++i) floats[i] = value[static_cast<int>(i % 4)];
}

// plane[0..count) = value, four vectors per step (depth planes and 8-bit code planes).
template <typename T>
HWY_INLINE void FillLanes(T* plane, size_t count, T value) {
  size_t i = 0;
#if HWY_TARGET != HWY_SCALAR
  const hn::ScalableTag<T> d;
  const size_t n = hn::Lanes(d);
  const auto v = hn::Set(d, value);
  for (; i + 4 * n <= count; i += 4 * n) {
    hn::StoreU(v, d, plane + i);
    hn::StoreU(v, d, plane + i + n);
    hn::StoreU(v, d, plane + i + 2 * n);
    hn::StoreU(v, d, plane + i + 3 * n);
  }
#endif
  for (; i < count; ++i) plane[i] = value;
}

void FillDepthKernel(float* depth, size_t count, float value) { FillLanes(depth, count, value); }

void FillCodesKernel(uint32_t* plane, size_t count, uint32_t code) { FillLanes(plane, count, code); }

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(StoreFullQuadsKernel);
HWY_EXPORT(StoreQuadsKernel);
HWY_EXPORT(LoadFullQuadsKernel);
HWY_EXPORT(LoadFullQuadCodesKernel);
HWY_EXPORT(StoreQuadRowsCodesKernel);
HWY_EXPORT(FillPlaneKernel);
HWY_EXPORT(FillDepthKernel);
HWY_EXPORT(FillCodesKernel);

void load_full_quads(const glm::vec4* plane, const uint32_t* pixel, int quad_count, int row_pixels,
                     float* const channels[4]) {
  HWY_DYNAMIC_DISPATCH(LoadFullQuadsKernel)(plane, pixel, quad_count, row_pixels, channels);
}

void load_full_quad_codes(const uint32_t* plane, const uint32_t* pixel, int quad_count,
                          int row_pixels, bool srgb, float* const channels[4]) {
  HWY_DYNAMIC_DISPATCH(LoadFullQuadCodesKernel)(plane, pixel, quad_count, row_pixels, srgb, channels);
}

void store_full_quad_codes(const uint32_t* codes, const int32_t* first_fragment,
                           const uint32_t* pixel, int quad_count, int row_pixels, uint32_t* plane) {
  for (int q = 0; q < quad_count; ++q) {
    uint32_t* top = plane + pixel[q];
    const uint32_t* src = codes + first_fragment[q];
    std::memcpy(top, src, 2 * sizeof(uint32_t));
    std::memcpy(top + row_pixels, src + 2, 2 * sizeof(uint32_t));
  }
}

void store_quad_rows_codes(const uint32_t* codes, const int32_t* first, const int32_t* quads,
                           const uint32_t* top, int segments, int row_pixels, uint32_t* plane) {
  HWY_DYNAMIC_DISPATCH(StoreQuadRowsCodesKernel)(codes, first, quads, top, segments, row_pixels, plane);
}

// A quad row (two adjacent pixels) as one 64-bit word, lane x in the low half (little-endian
// x86): the written lanes blended in, the others stored back as they were, so a quad costs the
// same whatever its lanes (full and partial quads come in about equal numbers, unpredictably).
void store_quad_codes(const uint32_t* codes, const int32_t* first_fragment, const uint32_t* pixel,
                      const uint8_t* lanes, int quad_count, int row_pixels, uint32_t* plane) {
  static_assert(std::endian::native == std::endian::little, "pixel x of a pair is its low half");
  static constexpr uint64_t kPairMask[4] = {0, 0xFFFFFFFFull, 0xFFFFFFFF00000000ull, ~uint64_t{0}};
  for (int q = 0; q < quad_count; ++q) {
    uint32_t* const top = plane + pixel[q];
    uint32_t* const bottom = top + row_pixels;
    const uint32_t* const src = codes + first_fragment[q];
    const uint64_t top_mask = kPairMask[lanes[q] & 3u], bottom_mask = kPairMask[(lanes[q] >> 2) & 3u];
    uint64_t new_top, new_bottom, old_top, old_bottom;
    std::memcpy(&new_top, src, sizeof(uint64_t));
    std::memcpy(&new_bottom, src + 2, sizeof(uint64_t));
    std::memcpy(&old_top, top, sizeof(uint64_t));
    std::memcpy(&old_bottom, bottom, sizeof(uint64_t));
    old_top = (old_top & ~top_mask) | (new_top & top_mask);
    old_bottom = (old_bottom & ~bottom_mask) | (new_bottom & bottom_mask);
    std::memcpy(top, &old_top, sizeof(uint64_t));
    std::memcpy(bottom, &old_bottom, sizeof(uint64_t));
  }
}

void fill_plane(glm::vec4* plane, size_t count, glm::vec4 value) {
  HWY_DYNAMIC_DISPATCH(FillPlaneKernel)(plane, count, value);
}
void fill_depth(float* depth, size_t count, float value) {
  HWY_DYNAMIC_DISPATCH(FillDepthKernel)(depth, count, value);
}
void fill_codes(uint32_t* plane, size_t count, uint32_t code) {
  HWY_DYNAMIC_DISPATCH(FillCodesKernel)(plane, count, code);
}

void store_quads(const float* const channels[4], const int32_t* first_fragment, const uint32_t* pixel,
                 const uint8_t* lanes, int quad_count, int row_pixels, glm::vec4* plane) {
  HWY_DYNAMIC_DISPATCH(StoreQuadsKernel)(channels, first_fragment, pixel, lanes, quad_count, row_pixels, plane);
}

void store_full_quads(const float* const channels[4], const int32_t* first_fragment,
                      const uint32_t* pixel, int quad_count, int row_pixels, glm::vec4* plane) {
  HWY_DYNAMIC_DISPATCH(StoreFullQuadsKernel)(channels, first_fragment, pixel, quad_count,
                                             row_pixels, plane);
}

}  // namespace ontile
#endif  // HWY_ONCE
