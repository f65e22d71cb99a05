// Encoding of values that are already quantised to their format (tile memory holds exactly
// such values): each lane's code is found cheaply (a table lookup by the float's bits, or a
// rounded product) and verified by decoding it, so the fast path is exact for any input.
#pragma once
#include <cstddef>
#include <cstdint>

namespace ontile {

// The codes of RGBA8 pixels by lookup: the float bits' bucket (exponent and top mantissa bits)
// holds at most one quantised value of each table, so a bucket maps to one candidate code.
struct QuantizedCodeTables {
  static constexpr uint32_t kLowestBits = 0x39000000u;  // 2^-13, below every non-zero code
  static constexpr int kBucketMantissaBits = 9;          // finer than 8-bit UNORM's spacing
  static constexpr int kBuckets = 14 << kBucketMantissaBits;  // the octaves [2^-13, 2)
  // [0, kBuckets): sRGB codes, [kBuckets, 2 kBuckets): 8-bit UNORM codes; 0 where no code's
  // value lies (its decoded 0 matches only a zero). Read as 4-byte words: 4 bytes of padding.
  alignas(64) uint8_t codes[2 * kBuckets + 4];
  alignas(64) float decode[512];  // the sRGB decode table, then the 8-bit UNORM one
  QuantizedCodeTables();
};
const QuantizedCodeTables& quantized_code_tables();

// Encodes `rows` rows of `pixels` RGBA pixels (rows src_row_floats floats and dst_row_bytes
// bytes apart) as encode_pixel does, row after row, while every value of a row is the decoded
// value of one of its format's codes. Returns the rows encoded: fewer than `rows` when the next
// row holds another value (that row may be partly written; the caller encodes it and goes on).
int encode_quantized_rgba8_rows_simd(const float* rgba, size_t src_row_floats, int pixels,
                                     int rows, bool srgb, uint8_t* dst, size_t dst_row_bytes);
int encode_quantized_rgb10a2_rows_simd(const float* rgba, size_t src_row_floats, int pixels,
                                       int rows, uint8_t* dst, size_t dst_row_bytes);

}  // namespace ontile
