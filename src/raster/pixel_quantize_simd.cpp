// Batch quantisation kernels (see pixel_quantize_simd.h), compiled per target by Highway's
// foreach_target. UNORM: a candidate code from the float product (within one of the exact code,
// since the product's rounding error is below 2^-14), corrected exactly by two threshold
// compares, then code / max as one IEEE float division (equal to unorm_to_float's double path
// for every 2-, 8- and 10-bit code; PixelRows.* decodes every code). sRGB: the bucket table of
// srgb8_tables.h and one threshold step. Table reads, compares, integer operations and IEEE
// float multiply and divide only: every target gives the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/pixel_quantize_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "raster/pixel_encode_quantized_simd.h"
#include "raster/pixel_format.h"
#include "raster/pixel_quantize_simd.h"
#include "raster/srgb8_tables.h"
#include "util/error.h"


HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The exact UNORM code of v (float_to_unorm): 0 for NaN and v <= 0, max for v >= 1.
template <class DF>
HWY_INLINE hn::Vec<hn::RebindToSigned<DF>> unorm_code(DF df, hn::Vec<DF> v, hn::Vec<DF> max,
                                                      const float* at) {
  const hn::RebindToSigned<DF> di;
  // The product clamped to [0, max] (0 for NaN) before rounding, so every lane converts a
  // value in range.
  const auto product = hn::IfThenElseZero(hn::Gt(v, hn::Zero(df)), hn::Min(hn::Mul(v, max), max));
  // Rounded to an integer by adding 2^23 (the sum's last mantissa bit weighs 1), read from the
  // sum's bits: cheaper than a conversion with out-of-range fixups, which no lane needs here.
  const auto candidate = hn::Sub(hn::BitCast(di, hn::Add(product, hn::Set(df, 8388608.0f))),
                                 hn::Set(di, 0x4B000000));
  const auto below = hn::RebindMask(di, hn::Lt(v, hn::GatherIndex(df, at, candidate)));
  const auto above = hn::RebindMask(di, hn::Ge(v, hn::GatherIndex(df, at + 1, candidate)));
  // A true mask is -1 as a vector: adding it steps down, subtracting it steps up.
  return hn::Sub(hn::Add(candidate, hn::VecFromMask(di, below)), hn::VecFromMask(di, above));
}

template <class DF>
HWY_INLINE hn::Vec<DF> quantize_unorm(DF df, hn::Vec<DF> v, hn::Vec<DF> max, const float* at) {
  return hn::Div(hn::ConvertTo(df, unorm_code(df, v, max, at)), max);
}

// linear_to_srgb8 then its decode: bucket start (buckets below 2^-13 clamp to the first, whose
// start is 0 and whose values stay below thresholds[0]; values from 1 up to the extra bucket,
// code 255), one step up the thresholds (srgb8_tables.h: buckets are narrower than the
// spacing of thresholds), and 0 for NaN, zeros and negatives.
template <class DF>
HWY_INLINE hn::Vec<hn::RebindToSigned<DF>> srgb8_code(DF df, hn::Vec<DF> v, const SrgbQuantizeTables& t) {
  const hn::RebindToSigned<DF> di;
  const hn::RebindToUnsigned<DF> du;
  const auto offset = hn::BitCast(di, hn::Sub(hn::BitCast(du, v), hn::Set(du, kSrgb8BucketLowestBits)));
  const auto bucket = hn::Min(hn::Max(hn::ShiftRight<23 - kSrgb8BucketMantissaBits>(offset), hn::Zero(di)),
                              hn::Set(di, kSrgb8BucketCount));
  auto code = hn::GatherIndex(di, t.bucket_start, bucket);
  const auto above = hn::RebindMask(di, hn::Ge(v, hn::GatherIndex(df, t.thresholds, code)));
  code = hn::Sub(code, hn::VecFromMask(di, above));
  return hn::IfThenElseZero(hn::RebindMask(di, hn::Gt(v, hn::Zero(df))), code);
}

template <class DF>
HWY_INLINE hn::Vec<DF> quantize_srgb8(DF df, hn::Vec<DF> v, const SrgbQuantizeTables& t,
                                      const float* decode) {
  return hn::GatherIndex(df, decode, srgb8_code(df, v, t));
}

void QuantizeSrgb8AlphaKernel(float* r, float* g, float* b, float* a, int count) {
  const hn::ScalableTag<float> df;
  const size_t n = hn::Lanes(df);
  const SrgbQuantizeTables& t = srgb_quantize_tables();
  const float* decode = srgb8_tables().decode.data();
  const float* at = unorm_thresholds(8).at.data();
  const auto max = hn::Set(df, 255.0f);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    hn::StoreU(quantize_srgb8(df, hn::LoadU(df, r + i), t, decode), df, r + i);
    hn::StoreU(quantize_srgb8(df, hn::LoadU(df, g + i), t, decode), df, g + i);
    hn::StoreU(quantize_srgb8(df, hn::LoadU(df, b + i), t, decode), df, b + i);
    hn::StoreU(quantize_unorm(df, hn::LoadU(df, a + i), max, at), df, a + i);
  }
  for (; i < static_cast<size_t>(count); ++i) {
    r[i] = decode[linear_to_srgb8(r[i])];
    g[i] = decode[linear_to_srgb8(g[i])];
    b[i] = decode[linear_to_srgb8(b[i])];
    a[i] = unorm_to_float(float_to_unorm(a[i], 8), 8);
  }
}

void QuantizeUnormRgbaKernel(float* r, float* g, float* b, float* a, int count, int bits) {
  const int rgb_bits = bits & 0xFF, alpha_bits = bits >> 8;
  const hn::ScalableTag<float> df;
  const size_t n = hn::Lanes(df);
  const float* rgb_at = unorm_thresholds(rgb_bits).at.data();
  const float* alpha_at = unorm_thresholds(alpha_bits).at.data();
  const auto rgb_max = hn::Set(df, static_cast<float>((1u << rgb_bits) - 1));
  const auto alpha_max = hn::Set(df, static_cast<float>((1u << alpha_bits) - 1));
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    hn::StoreU(quantize_unorm(df, hn::LoadU(df, r + i), rgb_max, rgb_at), df, r + i);
    hn::StoreU(quantize_unorm(df, hn::LoadU(df, g + i), rgb_max, rgb_at), df, g + i);
    hn::StoreU(quantize_unorm(df, hn::LoadU(df, b + i), rgb_max, rgb_at), df, b + i);
    hn::StoreU(quantize_unorm(df, hn::LoadU(df, a + i), alpha_max, alpha_at), df, a + i);
  }
  for (; i < static_cast<size_t>(count); ++i) {
    r[i] = unorm_to_float(float_to_unorm(r[i], rgb_bits), rgb_bits);
    g[i] = unorm_to_float(float_to_unorm(g[i], rgb_bits), rgb_bits);
    b[i] = unorm_to_float(float_to_unorm(b[i], rgb_bits), rgb_bits);
    a[i] = unorm_to_float(float_to_unorm(a[i], alpha_bits), alpha_bits);
  }
}

// The codes of quantize_srgb8_alpha_simd / quantize_unorm_rgba_simd (8 bits) packed as the
// pixel's four bytes (R lowest): what encode_pixel writes, without the decode.
void QuantizeRgba8CodesKernel(const float* r, const float* g, const float* b, const float* a,
                              int count, bool srgb, uint32_t* codes) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const size_t n = hn::Lanes(df);
  const SrgbQuantizeTables& t = srgb_quantize_tables();
  const float* at = unorm_thresholds(8).at.data();
  const auto max = hn::Set(df, 255.0f);
  const auto rgb_code = [&](hn::Vec<decltype(df)> v) {
    return srgb ? srgb8_code(df, v, t) : unorm_code(df, v, max, at);
  };
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto cr = rgb_code(hn::LoadU(df, r + i));
    const auto cg = rgb_code(hn::LoadU(df, g + i));
    const auto cb = rgb_code(hn::LoadU(df, b + i));
    const auto ca = unorm_code(df, hn::LoadU(df, a + i), max, at);
    const auto packed = hn::Or(hn::Or(cr, hn::ShiftLeft<8>(cg)),
                               hn::Or(hn::ShiftLeft<16>(cb), hn::ShiftLeft<24>(ca)));
    hn::StoreU(packed, di, reinterpret_cast<int32_t*>(codes + i));
  }
  const PixelFormat format = srgb ? PixelFormat::RGBA8_SRGB : PixelFormat::RGBA8_UNORM;
  for (; i < static_cast<size_t>(count); ++i) {
    uint8_t bytes[4];
    encode_pixel(format, glm::vec4(r[i], g[i], b[i], a[i]), bytes);
    codes[i] = bytes[0] | (uint32_t{bytes[1]} << 8) | (uint32_t{bytes[2]} << 16) | (uint32_t{bytes[3]} << 24);
  }
}

// QuantizeRgba8CodesKernel for values that are decoded codes of the format (a functor's
// BatchOutput::output0_codes_of promise), found without the threshold steps: UNORM by the
// rounded product (a decoded code c times 255 is within c * 2^-24 of c), sRGB by the float
// bits' bucket (pixel_encode_quantized_simd.h: at most one code's value per bucket; values below
// the first bucket, zeros included, clamp to the last, which holds code 0).
void Rgba8CodesOfDecodedKernel(const float* r, const float* g, const float* b, const float* a,
                               int count, bool srgb, uint32_t* codes) {
  using Tables = QuantizedCodeTables;
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::RebindToUnsigned<decltype(df)> du;
  const size_t n = hn::Lanes(df);
  const Tables& t = quantized_code_tables();
  const int32_t* srgb_codes = reinterpret_cast<const int32_t*>(t.codes);  // read as 4-byte words
  const auto max = hn::Set(df, 255.0f);
  const auto lowest = hn::Set(du, Tables::kLowestBits);
  const auto last_bucket = hn::Set(du, Tables::kBuckets - 1);
  const auto byte = hn::Set(di, 0xFF);
  // Rounded to an integer by adding 2^23 (its last mantissa bit weighs 1; ties to even, as no
  // decoded code's product is near one): the code is the sum's low byte, and shifting the sum
  // left by 8 or more drops its exponent bits, so only R needs the mask.
  const auto two_23 = hn::Set(df, 8388608.0f);
  const auto unorm = [&](hn::Vec<decltype(df)> v) { return hn::BitCast(di, hn::Add(hn::Mul(v, max), two_23)); };
  const auto rgb_code = [&](hn::Vec<decltype(df)> v) {
    if (!srgb) return unorm(v);
    const auto bucket = hn::Min(
        hn::ShiftRight<23 - Tables::kBucketMantissaBits>(hn::Sub(hn::BitCast(du, v), lowest)), last_bucket);
    return hn::And(hn::GatherOffset(di, srgb_codes, hn::BitCast(di, bucket)), byte);
  };
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto cr = rgb_code(hn::LoadU(df, r + i));
    const auto cg = rgb_code(hn::LoadU(df, g + i));
    const auto cb = rgb_code(hn::LoadU(df, b + i));
    const auto ca = unorm(hn::LoadU(df, a + i));
    const auto packed = hn::Or(hn::Or(hn::And(cr, byte), hn::ShiftLeft<8>(cg)),
                               hn::Or(hn::ShiftLeft<16>(cb), hn::ShiftLeft<24>(ca)));
    hn::StoreU(packed, di, reinterpret_cast<int32_t*>(codes + i));
  }
  if (i < static_cast<size_t>(count)) {
    QuantizeRgba8CodesKernel(r + i, g + i, b + i, a + i, count - static_cast<int>(i), srgb, codes + i);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

UnormThresholds::UnormThresholds(int bits_) : bits(bits_) {
  const uint32_t max_code = (1u << bits) - 1;
  at.resize(max_code + 2);
  at[0] = -std::numeric_limits<float>::infinity();
  at[max_code + 1] = std::numeric_limits<float>::quiet_NaN();
  // float_to_unorm is non-decreasing in the value, and on [0, 1] so are the float bits: binary
  // search of the bits for the first value reaching each code.
  for (uint32_t k = 1; k <= max_code; ++k) {
    uint32_t lo = 0, hi = std::bit_cast<uint32_t>(1.0f);  // float_to_unorm(1) = max >= k
    while (lo < hi) {
      const uint32_t mid = lo + (hi - lo) / 2;
      if (float_to_unorm(std::bit_cast<float>(mid), bits) >= k) {
        hi = mid;
      } else {
        lo = mid + 1;
      }
    }
    at[k] = std::bit_cast<float>(lo);
  }
}

// One guarded static per table, chosen first: asked once per quantised batch, where checking
// the guards of all three tables cost ~45 instructions a call.
const UnormThresholds& unorm_thresholds(int bits) {
  switch (bits) {
    case 2: {
      static const UnormThresholds two(2);
      return two;
    }
    case 8: {
      static const UnormThresholds eight(8);
      return eight;
    }
    case 10: {
      static const UnormThresholds ten(10);
      return ten;
    }
    default: throw Error("unorm_thresholds: no table for " + std::to_string(bits) + " bits");
  }
}

SrgbQuantizeTables::SrgbQuantizeTables() {
  const Srgb8Tables& t = srgb8_tables();
  for (int bucket = 0; bucket < kSrgb8BucketCount; ++bucket) {
    bucket_start[bucket] = t.bucket_start[bucket];
    // One step must reach the code: at most one threshold inside each bucket.
    const int next = bucket + 1 < kSrgb8BucketCount ? t.bucket_start[bucket + 1] : 255;
    if (next - t.bucket_start[bucket] > 1) {
      throw Error("srgb quantize tables: bucket " + std::to_string(bucket) + " holds two thresholds");
    }
  }
  bucket_start[kSrgb8BucketCount] = 255;
  for (int c = 0; c < 255; ++c) thresholds[c] = t.thresholds[c];
  thresholds[255] = std::numeric_limits<float>::quiet_NaN();
}

const SrgbQuantizeTables& srgb_quantize_tables() {
  static const SrgbQuantizeTables tables;
  return tables;
}

HWY_EXPORT(QuantizeSrgb8AlphaKernel);
HWY_EXPORT(QuantizeUnormRgbaKernel);
HWY_EXPORT(QuantizeRgba8CodesKernel);
HWY_EXPORT(Rgba8CodesOfDecodedKernel);

void quantize_srgb8_alpha_simd(float* r, float* g, float* b, float* a, int count) {
  HWY_DYNAMIC_DISPATCH(QuantizeSrgb8AlphaKernel)(r, g, b, a, count);
}
void quantize_unorm_rgba_simd(float* r, float* g, float* b, float* a, int count, int bits) {
  HWY_DYNAMIC_DISPATCH(QuantizeUnormRgbaKernel)(r, g, b, a, count, bits);
}

void quantize_rgba8_codes_simd(const float* r, const float* g, const float* b, const float* a,
                               int count, bool srgb, uint32_t* codes) {
  HWY_DYNAMIC_DISPATCH(QuantizeRgba8CodesKernel)(r, g, b, a, count, srgb, codes);
}

void rgba8_codes_of_decoded_simd(const float* r, const float* g, const float* b, const float* a,
                                 int count, bool srgb, uint32_t* codes) {
  HWY_DYNAMIC_DISPATCH(Rgba8CodesOfDecodedKernel)(r, g, b, a, count, srgb, codes);
}

}  // namespace ontile
#endif  // HWY_ONCE
