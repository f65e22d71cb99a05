// SIMD channel conversions (see pixel_format_simd.h), compiled per target by Highway's
// foreach_target. UNORM conversion runs in double exactly as the scalar float_to_unorm does
// (the product value * (2^bits - 1) is exact in double), 8-bit UNORM in exact integers; sRGB uses the scalar path's tables
// through gathers. Only IEEE operations and table reads: every target gives the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/pixel_format_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <bit>

#include "raster/pixel_format.h"
#include "raster/pixel_format_simd.h"
#include "raster/srgb8_tables.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// float_to_unorm on double lanes: 0 for NaN and v <= 0, max for v >= 1, else
// floor(v * max + 0.5) (round half up of the exact product). Returns the code as a double.
template <class DD>
hn::Vec<DD> unorm_code(DD dd, hn::Vec<DD> v, double max_code) {
  const auto code = hn::Floor(hn::Add(hn::Mul(v, hn::Set(dd, max_code)), hn::Set(dd, 0.5)));
  const auto clamped = hn::IfThenElse(hn::Ge(v, hn::Set(dd, 1.0)), hn::Set(dd, max_code), code);
  return hn::IfThenElseZero(hn::Gt(v, hn::Zero(dd)), clamped);
}

// unorm_code with a per-lane maximum code (channels of different widths).
template <class DD>
hn::Vec<DD> unorm_code(DD dd, hn::Vec<DD> v, hn::Vec<DD> max_code) {
  const auto code = hn::Floor(hn::Add(hn::Mul(v, max_code), hn::Set(dd, 0.5)));
  const auto clamped = hn::IfThenElse(hn::Ge(v, hn::Set(dd, 1.0)), max_code, code);
  return hn::IfThenElseZero(hn::Gt(v, hn::Zero(dd)), clamped);
}

// RGB10A2's maximum codes, R G B A repeated: a vector of up to 16 lanes starting at any
// channel (i % 4) loads from here.
alignas(64) constexpr double kRgb10a2MaxCodes[20] = {1023, 1023, 1023, 3, 1023, 1023, 1023, 3,
                                                     1023, 1023, 1023, 3, 1023, 1023, 1023, 3,
                                                     1023, 1023, 1023, 3};
constexpr int kPackedChunkPixels = 64;

void EncodeRgb10a2Kernel(const float* rgba, int pixels, uint8_t* dst) {
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const hn::Rebind<int32_t, decltype(dd)> di;
  const size_t n = hn::Lanes(dd);
  alignas(64) int32_t codes[4 * kPackedChunkPixels];
  for (int first = 0; first < pixels; first += kPackedChunkPixels) {
    const int chunk = std::min(kPackedChunkPixels, pixels - first);
    const float* values = rgba + 4 * static_cast<size_t>(first);
    const size_t count = 4 * static_cast<size_t>(chunk);
    size_t i = 0;
    for (; i + n <= count && n <= 16; i += n) {
      const auto max_code = hn::LoadU(dd, kRgb10a2MaxCodes + i % 4);
      const auto code = unorm_code(dd, hn::PromoteTo(dd, hn::LoadU(df, values + i)), max_code);
      hn::StoreU(hn::DemoteTo(di, code), di, codes + i);
    }
    for (; i < count; ++i) {
      codes[i] = static_cast<int32_t>(float_to_unorm(values[i], i % 4 == 3 ? 2 : 10));
    }
    uint8_t* out = dst + 4 * static_cast<size_t>(first);
    // Pixels' codes deinterleaved into R, G, B, A lanes and packed as R | G << 10 | B << 20 |
    // A << 30, stored in host order (little-endian, asserted below) as the scalar bytes are.
    const hn::ScalableTag<uint32_t> du;
    const size_t pixels_per_vector = hn::Lanes(du);
    const uint32_t* unsigned_codes = reinterpret_cast<const uint32_t*>(codes);
    int p = 0;
    for (; p + static_cast<int>(pixels_per_vector) <= chunk; p += static_cast<int>(pixels_per_vector)) {
      hn::Vec<decltype(du)> r, g, b, a;
      hn::LoadInterleaved4(du, unsigned_codes + 4 * p, r, g, b, a);
      const auto word = hn::Or(hn::Or(r, hn::ShiftLeft<10>(g)),
                               hn::Or(hn::ShiftLeft<20>(b), hn::ShiftLeft<30>(a)));
      hn::StoreU(word, du, reinterpret_cast<uint32_t*>(out + 4 * p));
    }
    for (; p < chunk; ++p) {
      const uint32_t word = static_cast<uint32_t>(codes[4 * p]) |
                            (static_cast<uint32_t>(codes[4 * p + 1]) << 10) |
                            (static_cast<uint32_t>(codes[4 * p + 2]) << 20) |
                            (static_cast<uint32_t>(codes[4 * p + 3]) << 30);
      for (int b = 0; b < 4; ++b) out[4 * p + b] = static_cast<uint8_t>(word >> (8 * b));
    }
  }
}

// unorm_to_float of 10- and 2-bit codes as one float division: code / max rounded once to
// float equals the double quotient rounded to float for every code (checked for all 1028 codes
// by PixelRows.*, which decodes every code), so planar float lanes give the scalar bits.
void DecodeRgb10a2Kernel(const uint8_t* src, int pixels, float* rgba) {
  const hn::ScalableTag<uint32_t> du;
  const hn::Rebind<float, decltype(du)> df;
  const hn::Rebind<int32_t, decltype(du)> di;
  const size_t n = hn::Lanes(du);
  const auto ten_bits = hn::Set(du, 0x3FFu);
  const auto max10 = hn::Set(df, 1023.0f);
  const auto max2 = hn::Set(df, 3.0f);
  const auto to_float = [&](hn::Vec<decltype(du)> code) {
    return hn::ConvertTo(df, hn::BitCast(di, code));  // codes below 2^10: exact
  };
  int p = 0;
  for (; p + static_cast<int>(n) <= pixels; p += static_cast<int>(n)) {
    const auto word = hn::LoadU(du, reinterpret_cast<const uint32_t*>(src + 4 * static_cast<size_t>(p)));
    const auto r = hn::Div(to_float(hn::And(word, ten_bits)), max10);
    const auto g = hn::Div(to_float(hn::And(hn::ShiftRight<10>(word), ten_bits)), max10);
    const auto b = hn::Div(to_float(hn::And(hn::ShiftRight<20>(word), ten_bits)), max10);
    const auto a = hn::Div(to_float(hn::ShiftRight<30>(word)), max2);
    hn::StoreInterleaved4(r, g, b, a, df, rgba + 4 * static_cast<size_t>(p));
  }
  for (; p < pixels; ++p) {
    const uint8_t* in = src + 4 * static_cast<size_t>(p);
    const uint32_t word = in[0] | (uint32_t{in[1]} << 8) | (uint32_t{in[2]} << 16) |
                          (uint32_t{in[3]} << 24);
    float* out = rgba + 4 * static_cast<size_t>(p);
    out[0] = unorm_to_float(word & 0x3FFu, 10);
    out[1] = unorm_to_float((word >> 10) & 0x3FFu, 10);
    out[2] = unorm_to_float((word >> 20) & 0x3FFu, 10);
    out[3] = unorm_to_float(word >> 30, 2);
  }
}

// binary16 (Vulkan "16-bit floating-point numbers") on 32-bit lanes, operation for operation as
// pixel_format.cpp's encode_small_float<10, true> / decode_small_float<10, true>: integer
// rebiasing with round to nearest even, subnormals through an exact scaling and one float
// round-to-integer, NaN payloads kept (never Inf). Returns / takes the code in the low 16 bits.
template <class DI>
HWY_INLINE hn::Vec<DI> half_code(DI di, hn::Vec<DI> f) {
  const hn::Rebind<float, DI> df;
  const auto sign = hn::ShiftLeft<15>(hn::ShiftRight<31>(hn::BitCast(hn::RebindToUnsigned<DI>(), f)));
  const auto magnitude = hn::And(f, hn::Set(di, 0x7FFFFFFF));
  const auto exponent_all_ones = hn::Set(di, 0x7C00);
  auto payload = hn::And(hn::ShiftRight<13>(magnitude), hn::Set(di, 0x3FF));
  payload = hn::IfThenElse(hn::Eq(payload, hn::Zero(di)), hn::Set(di, 0x200), payload);
  const auto nan_code = hn::Or(exponent_all_ones, payload);
  // Only subnormal-range lanes go through the float rounding (the others as 0), so no lane
  // converts a NaN or an out-of-range value to int (undefined in C++, on Highway's EMU128).
  const auto is_subnormal = hn::Lt(magnitude, hn::Set(di, 0x38800000));
  const auto subnormal_magnitude = hn::IfThenElseZero(is_subnormal, magnitude);
  const auto scaled =
      hn::Mul(hn::BitCast(df, subnormal_magnitude), hn::Set(df, 16777216.0f));  // 2^(14+10)
  const auto rounded_float =
      hn::Sub(hn::Add(scaled, hn::Set(df, 8388608.0f)), hn::Set(df, 8388608.0f));
  const auto subnormal_code = hn::ConvertTo(di, rounded_float);
  const auto rebased = hn::Sub(magnitude, hn::Set(di, 112 << 23));
  const auto rounded = hn::Add(hn::Add(rebased, hn::Set(di, 0xFFF)),
                               hn::And(hn::ShiftRight<13>(rebased), hn::Set(di, 1)));
  const auto code = hn::ShiftRight<13>(rounded);
  const auto normal_code = hn::IfThenElse(hn::Gt(code, hn::Set(di, 0x7BFF)), exponent_all_ones, code);
  auto result = hn::IfThenElse(is_subnormal, subnormal_code, normal_code);
  result = hn::IfThenElse(hn::Eq(magnitude, hn::Set(di, 0x7F800000)), exponent_all_ones, result);
  result = hn::IfThenElse(hn::Gt(magnitude, hn::Set(di, 0x7F800000)), nan_code, result);
  return hn::Or(hn::BitCast(di, sign), result);
}

template <class DI>
HWY_INLINE hn::Vec<DI> half_value_bits(DI di, hn::Vec<DI> code) {
  const hn::Rebind<float, DI> df;
  const auto sign = hn::ShiftLeft<16>(hn::And(code, hn::Set(di, 0x8000)));
  const auto exponent = hn::And(hn::ShiftRight<10>(code), hn::Set(di, 0x1F));
  const auto mantissa = hn::And(code, hn::Set(di, 0x3FF));
  const auto inf_nan = hn::Or(hn::Set(di, 0x7F800000), hn::ShiftLeft<13>(mantissa));
  const auto subnormal =
      hn::BitCast(di, hn::Mul(hn::ConvertTo(df, mantissa), hn::Set(df, 1.0f / 16777216.0f)));
  const auto normal = hn::Or(hn::ShiftLeft<23>(hn::Add(exponent, hn::Set(di, 112))),
                             hn::ShiftLeft<13>(mantissa));
  auto result = hn::IfThenElse(hn::Eq(exponent, hn::Zero(di)), subnormal, normal);
  result = hn::IfThenElse(hn::Eq(exponent, hn::Set(di, 31)), inf_nan, result);
  return hn::Or(sign, result);
}

// F16C, on every x86 target from AVX2 up, converts binary16 with IEEE round to nearest even
// (an immediate rounding mode, not MXCSR) and widens exactly: for every float that is not a NaN
// and every code that is not a NaN it gives the bits of the integer path above (all 2^32 floats
// and 65536 codes were compared; PixelRows.* checks ties, subnormals and overflow on every
// target). NaNs keep the integer path, whose payload rule the hardware does not follow: a
// vector holding one is converted wholly by the integer path.
#undef ONTILE_HALF_F16C
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2 && !defined(HWY_DISABLE_F16C)
#define ONTILE_HALF_F16C 1
#else
#define ONTILE_HALF_F16C 0
#endif

void QuantizeHalfKernel(float* values, int count) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const size_t n = hn::Lanes(df);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto v = hn::LoadU(df, values + i);
#if ONTILE_HALF_F16C
    if (hn::AllFalse(df, hn::IsNaN(v))) {
      const hn::Rebind<hwy::float16_t, decltype(df)> df16;
      hn::StoreU(hn::PromoteTo(df, hn::DemoteTo(df16, v)), df, values + i);
      continue;
    }
#endif
    const auto code = half_code(di, hn::BitCast(di, v));
    hn::StoreU(hn::BitCast(df, half_value_bits(di, code)), df, values + i);
  }
  for (; i < static_cast<size_t>(count); ++i) {
    values[i] = half_bits_to_float(float_to_half_bits(values[i]));
  }
}

static_assert(std::endian::native == std::endian::little, "binary16 rows store host-order u16");

void EncodeHalfKernel(const float* values, int count, uint8_t* dst) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::Rebind<uint16_t, decltype(di)> d16;
  const size_t n = hn::Lanes(df);
  size_t i = 0;
  // Codes are 0..0xFFFF, so the saturating demotion keeps them; stored in host order, which is
  // the scalar path's little-endian (asserted below).
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto v = hn::LoadU(df, values + i);
#if ONTILE_HALF_F16C
    if (hn::AllFalse(df, hn::IsNaN(v))) {
      const hn::Rebind<hwy::float16_t, decltype(df)> df16;
      hn::StoreU(hn::BitCast(d16, hn::DemoteTo(df16, v)), d16,
                 reinterpret_cast<uint16_t*>(dst + 2 * i));
      continue;
    }
#endif
    const auto code = half_code(di, hn::BitCast(di, v));
    hn::StoreU(hn::DemoteTo(d16, code), d16, reinterpret_cast<uint16_t*>(dst + 2 * i));
  }
  for (; i < static_cast<size_t>(count); ++i) {
    const uint16_t code = float_to_half_bits(values[i]);
    dst[2 * i] = static_cast<uint8_t>(code);
    dst[2 * i + 1] = static_cast<uint8_t>(code >> 8);
  }
}

void DecodeHalfKernel(const uint8_t* src, int count, float* values) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::Rebind<uint16_t, decltype(di)> d16;
  const size_t n = hn::Lanes(df);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto code = hn::PromoteTo(di, hn::LoadU(d16, reinterpret_cast<const uint16_t*>(src + 2 * i)));
#if ONTILE_HALF_F16C
    // NaN codes: exponent all ones and a non-zero mantissa, i.e. |code| above 0x7C00.
    if (hn::AllFalse(di, hn::Gt(hn::And(code, hn::Set(di, 0x7FFF)), hn::Set(di, 0x7C00)))) {
      const hn::Rebind<hwy::float16_t, decltype(df)> df16;
      hn::StoreU(hn::PromoteTo(df, hn::LoadU(df16, reinterpret_cast<const hwy::float16_t*>(src + 2 * i))),
                 df, values + i);
      continue;
    }
#endif
    hn::StoreU(hn::BitCast(df, half_value_bits(di, code)), df, values + i);
  }
  for (; i < static_cast<size_t>(count); ++i) {
    values[i] = half_bits_to_float(static_cast<uint16_t>(src[2 * i] | (src[2 * i + 1] << 8)));
  }
}

// float_to_unorm(v, 8) on 32-bit lanes, exactly, as integers: a positive normal v below 1 is
// m 2^(E - 150) (m the 24-bit significand, E the biased exponent), so 255 v = x / 2^sh with
// x = 255 m < 2^32 and sh = 150 - E, and floor(255 v + 1/2) = floor((floor(x / 2^(sh - 1)) + 1)
// / 2) (adding 1 before halving commutes with the floor). Below 2^-9 (E < 118, where the shift
// would pass 31) 255 v < 1/2 gives 0; NaN, v <= 0 and subnormals give 0; v >= 1 gives 255.
template <class DF>
hn::Vec<hn::RebindToSigned<DF>> unorm8_code(DF df, hn::Vec<DF> v) {
  const hn::RebindToSigned<DF> di;
  const hn::RebindToUnsigned<DF> du;
  const auto bits = hn::BitCast(di, v);
  const auto exponent = hn::ShiftRight<23>(bits);  // the sign bit only where v <= 0 (zeroed below)
  const auto significand = hn::BitCast(du, hn::Or(hn::And(bits, hn::Set(di, 0x7FFFFF)),
                                                  hn::Set(di, 0x800000)));
  const auto scaled = hn::Mul(significand, hn::Set(du, 255u));
  const auto in_range = hn::Gt(exponent, hn::Set(di, 117));
  // 149 - E, in [0, 31] for E in [118, 149]; clamped there for the other lanes (their code is
  // replaced), so no lane shifts by 32 or more (undefined on the scalar targets).
  const auto shift = hn::BitCast(
      du, hn::Min(hn::Max(hn::Sub(hn::Set(di, 149), exponent), hn::Zero(di)), hn::Set(di, 31)));
  const auto code = hn::BitCast(di, hn::ShiftRight<1>(hn::Add(hn::Shr(scaled, shift), hn::Set(du, 1u))));
  const auto saturated = hn::RebindMask(di, hn::Ge(v, hn::Set(df, 1.0f)));  // false for NaN
  const auto positive = hn::RebindMask(di, hn::Gt(v, hn::Zero(df)));      // false for NaN
  return hn::IfThenElseZero(positive, hn::IfThenElse(saturated, hn::Set(di, 255),
                                                     hn::IfThenElseZero(in_range, code)));
}

// 8-bit UNORM quantisation on float lanes: the code as above, then code / 255 as one IEEE float
// division, which rounds as unorm_to_float's double division does followed by the rounding to
// float (c / 255 for 0 < c < 255 is no float midpoint and lies more than 2^-40 relatively from
// every one, far beyond double's 2^-53, so the double rounding cannot move it).
void QuantizeUnorm8Lanes(float* values, int count) {
  const hn::ScalableTag<float> df;
  const size_t n = hn::Lanes(df);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto code = unorm8_code(df, hn::LoadU(df, values + i));
    hn::StoreU(hn::Div(hn::ConvertTo(df, code), hn::Set(df, 255.0f)), df, values + i);
  }
  for (; i < static_cast<size_t>(count); ++i) {
    values[i] = unorm_to_float(float_to_unorm(values[i], 8), 8);
  }
}

void QuantizeUnormKernel(float* values, int count, int bits) {
  if (bits == 8) {
    QuantizeUnorm8Lanes(values, count);
    return;
  }
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const size_t n = hn::Lanes(dd);
  const double max_code = static_cast<double>((1u << bits) - 1);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto code = unorm_code(dd, hn::PromoteTo(dd, hn::LoadU(df, values + i)), max_code);
    hn::StoreU(hn::DemoteTo(df, hn::Div(code, hn::Set(dd, max_code))), df, values + i);
  }
  for (; i < static_cast<size_t>(count); ++i) {
    values[i] = unorm_to_float(float_to_unorm(values[i], bits), bits);
  }
}

void EncodeUnorm8Kernel(const float* values, int count, uint8_t* dst) {
  const hn::ScalableTag<float> df;
  const hn::Rebind<uint8_t, decltype(df)> d8;
  const size_t n = hn::Lanes(df);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    hn::StoreU(hn::DemoteTo(d8, unorm8_code(df, hn::LoadU(df, values + i))), d8, dst + i);
  }
  for (; i < static_cast<size_t>(count); ++i) {
    dst[i] = static_cast<uint8_t>(float_to_unorm(values[i], 8));
  }
}

// linear_to_srgb8 on float lanes: bucket start, then at most one step up the thresholds (see
// srgb8_tables.h); a second step is taken anyway so that a table change cannot go unnoticed.
template <class DF>
hn::Vec<hn::RebindToSigned<DF>> srgb8_code(DF df, hn::Vec<DF> v, const Srgb8Tables& t) {
  const hn::RebindToSigned<DF> di;
  const auto in_range = hn::And(hn::Ge(v, hn::Set(df, std::bit_cast<float>(kSrgb8BucketLowestBits))),
                                hn::Lt(v, hn::Set(df, 1.0f)));
  const auto bits = hn::BitCast(di, v);
  const auto bucket = hn::ShiftRight<23 - kSrgb8BucketMantissaBits>(
      hn::Sub(bits, hn::Set(di, static_cast<int32_t>(kSrgb8BucketLowestBits))));
  const auto in_range_i = hn::RebindMask(di, in_range);
  auto code = hn::GatherIndex(di, t.bucket_start.data(), hn::IfThenElseZero(in_range_i, bucket));
  for (int step = 0; step < 2; ++step) {
    const auto above = hn::Ge(v, hn::GatherIndex(df, t.thresholds.data(), code));
    code = hn::Add(code, hn::IfThenElseZero(hn::RebindMask(di, above), hn::Set(di, 1)));
  }
  const auto saturated = hn::RebindMask(di, hn::Ge(v, hn::Set(df, 1.0f)));  // false for NaN
  return hn::IfThenElse(saturated, hn::Set(di, 255), hn::IfThenElseZero(in_range_i, code));
}

// RGBA8_SRGB pixels: R, G, B through linear_to_srgb8, alpha (always linear) through
// float_to_unorm(a, 8), each on its own deinterleaved lanes.
void EncodeSrgb8AlphaKernel(const float* rgba, int pixels, uint8_t* dst) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::Rebind<uint8_t, decltype(di)> d8;
  const size_t n = hn::Lanes(df);
  const Srgb8Tables& t = srgb8_tables();
  int p = 0;
  for (; p + static_cast<int>(n) <= pixels; p += static_cast<int>(n)) {
    hn::Vec<decltype(df)> r, g, b, a;
    hn::LoadInterleaved4(df, rgba + 4 * static_cast<size_t>(p), r, g, b, a);
    hn::StoreInterleaved4(hn::DemoteTo(d8, srgb8_code(df, r, t)), hn::DemoteTo(d8, srgb8_code(df, g, t)),
                          hn::DemoteTo(d8, srgb8_code(df, b, t)), hn::DemoteTo(d8, unorm8_code(df, a)),
                          d8, dst + 4 * static_cast<size_t>(p));
  }
  for (; p < pixels; ++p) {
    const float* in = rgba + 4 * static_cast<size_t>(p);
    uint8_t* out = dst + 4 * static_cast<size_t>(p);
    for (int c = 0; c < 3; ++c) out[c] = linear_to_srgb8(in[c]);
    out[3] = static_cast<uint8_t>(float_to_unorm(in[3], 8));
  }
}

void DecodeTable8Kernel(const uint8_t* src, int count, const float* table, float* dst) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::Rebind<uint8_t, decltype(di)> d8;
  const size_t n = hn::Lanes(df);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto index = hn::PromoteTo(di, hn::LoadU(d8, src + i));
    hn::StoreU(hn::GatherIndex(df, table, index), df, dst + i);
  }
  for (; i < static_cast<size_t>(count); ++i) dst[i] = table[src[i]];
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(QuantizeUnormKernel);
HWY_EXPORT(EncodeUnorm8Kernel);
HWY_EXPORT(EncodeSrgb8AlphaKernel);
HWY_EXPORT(DecodeTable8Kernel);
HWY_EXPORT(EncodeRgb10a2Kernel);
HWY_EXPORT(QuantizeHalfKernel);
HWY_EXPORT(EncodeHalfKernel);
HWY_EXPORT(DecodeHalfKernel);
HWY_EXPORT(DecodeRgb10a2Kernel);

void quantize_unorm_simd(float* values, int count, int bits) {
  HWY_DYNAMIC_DISPATCH(QuantizeUnormKernel)(values, count, bits);
}
void encode_unorm8_simd(const float* values, int count, uint8_t* dst) {
  HWY_DYNAMIC_DISPATCH(EncodeUnorm8Kernel)(values, count, dst);
}
void encode_srgb8_alpha_simd(const float* rgba, int pixels, uint8_t* dst) {
  HWY_DYNAMIC_DISPATCH(EncodeSrgb8AlphaKernel)(rgba, pixels, dst);
}
void decode_table8_simd(const uint8_t* src, int count, const float* table, float* dst) {
  HWY_DYNAMIC_DISPATCH(DecodeTable8Kernel)(src, count, table, dst);
}
void quantize_half_simd(float* values, int count) {
  HWY_DYNAMIC_DISPATCH(QuantizeHalfKernel)(values, count);
}
void encode_half_simd(const float* values, int count, uint8_t* dst) {
  HWY_DYNAMIC_DISPATCH(EncodeHalfKernel)(values, count, dst);
}
void decode_half_simd(const uint8_t* src, int count, float* values) {
  HWY_DYNAMIC_DISPATCH(DecodeHalfKernel)(src, count, values);
}
void encode_rgb10a2_simd(const float* rgba, int pixels, uint8_t* dst) {
  HWY_DYNAMIC_DISPATCH(EncodeRgb10a2Kernel)(rgba, pixels, dst);
}
void decode_rgb10a2_simd(const uint8_t* src, int pixels, float* rgba) {
  HWY_DYNAMIC_DISPATCH(DecodeRgb10a2Kernel)(src, pixels, rgba);
}

}  // namespace ontile
#endif  // HWY_ONCE
