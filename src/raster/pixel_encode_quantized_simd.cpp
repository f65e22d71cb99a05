// Encoding of already quantised values (see pixel_encode_quantized_simd.h), compiled per target
// by Highway's foreach_target. Candidates come from a table lookup or a rounded product; a
// vector is stored only when every lane's candidate decodes to the lane's value, and then the
// candidate is the exact code: each code decodes to a distinct value that encodes back to it
// (PixelRows.* checks every code on every target), and a value equal to a code's decoded value
// (or -0 for +0) encodes as that value does. Table reads, integer operations and IEEE float
// multiply and divide only: every target gives the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/pixel_encode_quantized_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <array>
#include <bit>
#include <cstddef>
#include <string>

#include <glm/glm.hpp>

#include "raster/pixel_encode_quantized_simd.h"
#include "raster/pixel_format.h"
#include "raster/srgb8_tables.h"
#include "util/error.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using Tables = QuantizedCodeTables;

// Per-lane table offsets of RGBA8_SRGB pixels (R, G, B sRGB, A linear UNORM), repeated for up
// to 16 lanes: a vector starts at a pixel, so lane i holds channel i % 4.
alignas(64) constexpr int32_t kSrgbCodeOffsets[16] = {
    0, 0, 0, Tables::kBuckets, 0, 0, 0, Tables::kBuckets,
    0, 0, 0, Tables::kBuckets, 0, 0, 0, Tables::kBuckets};
alignas(64) constexpr int32_t kSrgbDecodeOffsets[16] = {0, 0, 0, 256, 0, 0, 0, 256,
                                                        0, 0, 0, 256, 0, 0, 0, 256};

// Bytes of a 128-bit block holding, in 32-bit lane j, the bytes (c0[j], c1[j], c2[j], c3[j]) of
// four code vectors, reordered to c0[0..3], c1[0..3], c2[0..3], c3[0..3] (a 4x4 transpose).
alignas(64) constexpr uint8_t kTransposeBytes[64] = {
    0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15, 0, 4, 8, 12, 1, 5, 9, 13,
    2, 6, 10, 14, 3, 7, 11, 15, 0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15,
    0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15};

// RGBA8 (sRGB or UNORM) rows, n pixels (four vectors) at a time: each lane's code is the one
// whose value lies in the float's bucket (values below 2^-13, negative or NaN clamp to the last
// bucket, which holds no code: 0). The four code vectors are packed into bytes by shifting and
// ORing, a transpose inside each 128-bit block and a permutation of 32-bit lanes that puts
// block b's bytes of vector k at lane k * blocks + b. Pixels of a row past the last whole group
// are encoded one by one. Returns the rows encoded before the first whose values are not all
// quantised (that row is left partly written).
int EncodeQuantized8Kernel(const float* rgba, size_t src_row_floats, int pixels, int rows,
                           bool srgb, uint8_t* dst, size_t dst_row_bytes) {
#if HWY_TARGET == HWY_SCALAR
  (void)rgba, (void)src_row_floats, (void)pixels, (void)dst, (void)dst_row_bytes, (void)srgb;
  (void)rows;
  return 0;  // one lane: no pixel-aligned vectors
#else
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::RebindToUnsigned<decltype(df)> du;
  const hn::Repartition<uint8_t, decltype(du)> d8;
  const size_t n = hn::Lanes(df);
  if (n < 4 || n > 16) return 0;  // lanes must start at a pixel and fit the offset patterns
  const Tables& t = quantized_code_tables();
  const int32_t* codes = reinterpret_cast<const int32_t*>(t.codes);  // read as 4-byte words
  const auto code_offset = srgb ? hn::LoadU(di, kSrgbCodeOffsets) : hn::Set(di, Tables::kBuckets);
  const auto decode_offset = srgb ? hn::LoadU(di, kSrgbDecodeOffsets) : hn::Set(di, 256);
  const auto lowest = hn::Set(du, Tables::kLowestBits);
  const auto last_bucket = hn::Set(du, Tables::kBuckets - 1);
  const auto transpose = hn::LoadU(d8, kTransposeBytes);
  alignas(64) int32_t lane_order[16];
  const size_t blocks = n / 4;
  for (size_t o = 0; o < n; ++o) lane_order[o] = static_cast<int32_t>(4 * (o % blocks) + o / blocks);
  const auto permutation = hn::SetTableIndices(du, lane_order);
  // UNORM: the candidate round(v * 255) clamped to a code, checked by one division (the
  // table's value for every code: unorm8_decodes_by_division), no gathers. A value decoded from
  // code c is within c * 2^-24 of c once multiplied, so its candidate is c.
  const bool by_division = !srgb && unorm8_decodes_by_division();
  const auto max_code = hn::Set(df, 255.0f);
  const auto code_of = [&](hn::Vec<decltype(df)> v, hn::Mask<decltype(df)>& ok) {
    if (by_division) {
      const auto code = hn::Min(hn::Max(hn::ConvertTo(di, hn::Round(hn::Mul(v, max_code))), hn::Zero(di)),
                                hn::Set(di, 255));
      ok = hn::And(ok, hn::Eq(hn::Div(hn::ConvertTo(df, code), max_code), v));
      return hn::BitCast(du, code);
    }
    const auto bucket = hn::Min(
        hn::ShiftRight<23 - Tables::kBucketMantissaBits>(hn::Sub(hn::BitCast(du, v), lowest)),
        last_bucket);
    const auto code = hn::And(
        hn::GatherOffset(di, codes, hn::Add(hn::BitCast(di, bucket), code_offset)), hn::Set(di, 0xFF));
    ok = hn::And(ok, hn::Eq(hn::GatherIndex(df, t.decode, hn::Add(code, decode_offset)), v));
    return hn::BitCast(du, code);
  };
  const size_t group_pixels = n;  // four vectors of n / 4 pixels
  for (int y = 0; y < rows; ++y) {
    const float* in = rgba + y * src_row_floats;
    uint8_t* out = dst + y * dst_row_bytes;
    size_t p = 0;
    for (; p + group_pixels <= static_cast<size_t>(pixels); p += group_pixels) {
      const float* v = in + 4 * p;
      auto ok = hn::FirstN(df, n);
      const auto c0 = code_of(hn::LoadU(df, v), ok);
      const auto c1 = code_of(hn::LoadU(df, v + n), ok);
      const auto c2 = code_of(hn::LoadU(df, v + 2 * n), ok);
      const auto c3 = code_of(hn::LoadU(df, v + 3 * n), ok);
      if (!hn::AllTrue(df, ok)) return y;
      const auto words = hn::Or(hn::Or(c0, hn::ShiftLeft<8>(c1)),
                                hn::Or(hn::ShiftLeft<16>(c2), hn::ShiftLeft<24>(c3)));
      const auto blocks_transposed = hn::BitCast(du, hn::TableLookupBytes(hn::BitCast(d8, words), transpose));
      hn::StoreU(hn::TableLookupLanes(blocks_transposed, permutation), du,
                 reinterpret_cast<uint32_t*>(out + 4 * p));
    }
    for (; p < static_cast<size_t>(pixels); ++p) {
      const float* v = in + 4 * p;
      const PixelFormat format = srgb ? PixelFormat::RGBA8_SRGB : PixelFormat::RGBA8_UNORM;
      encode_pixel(format, glm::vec4(v[0], v[1], v[2], v[3]), out + 4 * p);
    }
  }
  return rows;
#endif
}

// RGB10A2's maximum codes and packing shifts, R G B A repeated for up to 16 lanes.
alignas(64) constexpr float kRgb10a2MaxFloat[16] = {1023, 1023, 1023, 3, 1023, 1023, 1023, 3,
                                                    1023, 1023, 1023, 3, 1023, 1023, 1023, 3};
alignas(64) constexpr uint32_t kRgb10a2Shift[16] = {0, 10, 20, 30, 0, 10, 20, 30,
                                                    0, 10, 20, 30, 0, 10, 20, 30};

// RGB10A2 rows, n pixels (four vectors) at a time: candidate round(v * max) of v clamped to
// [0, 1], checked by unorm_to_float as one float division (the decode of DecodeRgb10a2Kernel,
// equal to the double path for every code), then each pixel's four shifted codes are ORed
// together by two rounds of even/odd lane pairing, which leaves the words in pixel order.
// Returns as EncodeQuantized8Kernel.
int EncodeQuantizedRgb10a2Kernel(const float* rgba, size_t src_row_floats, int pixels, int rows,
                                 uint8_t* dst, size_t dst_row_bytes) {
#if HWY_TARGET == HWY_SCALAR
  (void)rgba, (void)src_row_floats, (void)pixels, (void)rows, (void)dst, (void)dst_row_bytes;
  return 0;  // one lane: no pixel-aligned vectors
#else
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::RebindToUnsigned<decltype(df)> du;
  const size_t n = hn::Lanes(df);
  if (n < 4 || n > 16) return 0;
  const auto max_float = hn::LoadU(df, kRgb10a2MaxFloat);
  const auto shift = hn::LoadU(du, kRgb10a2Shift);
  const auto candidate = [&](hn::Vec<decltype(df)> v, hn::Mask<decltype(df)>& ok) {
    // v * max clamped to [0, max] (NaN lanes may keep a NaN: their check fails whatever the
    // code) and rounded by adding 2^23, whose sum's bits hold the integer.
    const auto product = hn::Min(hn::Max(hn::Mul(v, max_float), hn::Zero(df)), max_float);
    const auto code = hn::Sub(hn::BitCast(di, hn::Add(product, hn::Set(df, 8388608.0f))),
                              hn::Set(di, 0x4B000000));
    ok = hn::And(ok, hn::Eq(hn::Div(hn::ConvertTo(df, code), max_float), v));
    return hn::Shl(hn::BitCast(du, code), shift);
  };
  const auto pair = [&](hn::Vec<decltype(du)> hi, hn::Vec<decltype(du)> lo) {
    return hn::Or(hn::ConcatEven(du, hi, lo), hn::ConcatOdd(du, hi, lo));
  };
  for (int y = 0; y < rows; ++y) {
    const float* row = rgba + y * src_row_floats;
    uint8_t* out = dst + y * dst_row_bytes;
    size_t p = 0;
    for (; p + n <= static_cast<size_t>(pixels); p += n) {
      const float* in = row + 4 * p;
      auto ok = hn::FirstN(df, n);
      const auto c0 = candidate(hn::LoadU(df, in), ok);
      const auto c1 = candidate(hn::LoadU(df, in + n), ok);
      const auto c2 = candidate(hn::LoadU(df, in + 2 * n), ok);
      const auto c3 = candidate(hn::LoadU(df, in + 3 * n), ok);
      if (!hn::AllTrue(df, ok)) return y;
      hn::StoreU(pair(pair(c3, c2), pair(c1, c0)), du, reinterpret_cast<uint32_t*>(out + 4 * p));
    }
    for (; p < static_cast<size_t>(pixels); ++p) {
      const float* in = row + 4 * p;
      encode_pixel(PixelFormat::RGB10A2_UNORM, glm::vec4(in[0], in[1], in[2], in[3]), out + 4 * p);
    }
  }
  return rows;
#endif
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

static_assert(std::endian::native == std::endian::little,
              "codes are read as little-endian words and packed words stored in host order");

QuantizedCodeTables::QuantizedCodeTables() : codes{}, decode{} {
  const std::array<float, 256>* decodes[2] = {&srgb8_tables().decode, &unorm8_decode_table()};
  for (int table = 0; table < 2; ++table) {
    for (int c = 0; c < 256; ++c) decode[256 * table + c] = (*decodes[table])[c];
    for (int c = 1; c < 256; ++c) {
      const uint32_t bits = std::bit_cast<uint32_t>((*decodes[table])[c]);
      const uint32_t bucket = (bits - kLowestBits) >> (23 - kBucketMantissaBits);
      uint8_t& slot = codes[table * kBuckets + bucket];
      if (bits < kLowestBits || bucket >= kBuckets - 1 || slot != 0) {
        throw Error("quantized code tables: code " + std::to_string(c) + " has no bucket of its own");
      }
      slot = static_cast<uint8_t>(c);
    }
  }
}

const QuantizedCodeTables& quantized_code_tables() {
  static const QuantizedCodeTables tables;
  return tables;
}

HWY_EXPORT(EncodeQuantized8Kernel);
HWY_EXPORT(EncodeQuantizedRgb10a2Kernel);

int encode_quantized_rgba8_rows_simd(const float* rgba, size_t src_row_floats, int pixels,
                                     int rows, bool srgb, uint8_t* dst, size_t dst_row_bytes) {
  return HWY_DYNAMIC_DISPATCH(EncodeQuantized8Kernel)(rgba, src_row_floats, pixels, rows, srgb,
                                                      dst, dst_row_bytes);
}
int encode_quantized_rgb10a2_rows_simd(const float* rgba, size_t src_row_floats, int pixels,
                                       int rows, uint8_t* dst, size_t dst_row_bytes) {
  return HWY_DYNAMIC_DISPATCH(EncodeQuantizedRgb10a2Kernel)(rgba, src_row_floats, pixels, rows,
                                                            dst, dst_row_bytes);
}

}  // namespace ontile
#endif  // HWY_ONCE
