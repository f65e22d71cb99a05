// SIMD code conversions of the packed and 16/24-bit formats (see pixel_packed_simd.h), compiled
// per target by Highway's foreach_target. Operation for operation as pixel_format.cpp: UNORM in
// double (the product value * (2^bits - 1) is exact there), small floats by integer rebiasing
// with round to nearest even and subnormals through one exact scaling and a float round. Only
// IEEE operations: every target gives the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/pixel_packed_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>

#include "raster/pixel_format.h"
#include "raster/pixel_packed_simd.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// encode_small_float<kMantissaBits, false> of pixel_format.cpp on 32-bit lanes.
template <int kMantissaBits, class DI>
HWY_INLINE hn::Vec<DI> unsigned_small_float_code(DI di, hn::Vec<DI> f) {
  constexpr int kDropBits = 23 - kMantissaBits;
  constexpr int32_t kMantissaMask = (1 << kMantissaBits) - 1;
  constexpr int32_t kExponentAllOnes = 0x1F << kMantissaBits;
  constexpr int32_t kMaxFinite = (0x1E << kMantissaBits) | kMantissaMask;
  const hn::Rebind<float, DI> df;
  const auto magnitude = hn::And(f, hn::Set(di, 0x7FFFFFFF));
  auto payload = hn::And(hn::ShiftRight<kDropBits>(magnitude), hn::Set(di, kMantissaMask));
  payload = hn::IfThenElse(hn::Eq(payload, hn::Zero(di)), hn::Set(di, 1 << (kMantissaBits - 1)),
                           payload);
  const auto all_ones = hn::Set(di, kExponentAllOnes);
  // Only subnormal-range lanes go through the float rounding (the others as 0), so no lane
  // converts a NaN or an out-of-range value to int.
  const auto is_subnormal = hn::Lt(magnitude, hn::Set(di, 0x38800000));
  const auto scaled = hn::Mul(hn::BitCast(df, hn::IfThenElseZero(is_subnormal, magnitude)),
                              hn::Set(df, static_cast<float>(1u << (14 + kMantissaBits))));
  const auto rounded_float =
      hn::Sub(hn::Add(scaled, hn::Set(df, 8388608.0f)), hn::Set(df, 8388608.0f));
  const auto rebased = hn::Sub(magnitude, hn::Set(di, 112 << 23));
  const auto rounded =
      hn::Add(hn::Add(rebased, hn::Set(di, (1 << (kDropBits - 1)) - 1)),
              hn::And(hn::ShiftRight<kDropBits>(rebased), hn::Set(di, 1)));
  const auto code = hn::ShiftRight<kDropBits>(rounded);
  const auto normal_code = hn::Min(code, hn::Set(di, kMaxFinite));  // finite overflow: max
  auto result = hn::IfThenElse(is_subnormal, hn::ConvertTo(di, rounded_float), normal_code);
  result = hn::IfThenElse(hn::Eq(magnitude, hn::Set(di, 0x7F800000)), all_ones, result);
  result = hn::IfThenZeroElse(hn::Lt(f, hn::Zero(di)), result);  // negatives, -0, -Inf -> 0
  return hn::IfThenElse(hn::Gt(magnitude, hn::Set(di, 0x7F800000)), hn::Or(all_ones, payload),
                        result);  // NaN
}

// decode_small_float<kMantissaBits, false> of the code's low 5 + kMantissaBits bits.
template <int kMantissaBits, class DI>
HWY_INLINE hn::Vec<DI> unsigned_small_float_value_bits(DI di, hn::Vec<DI> code) {
  constexpr int kDropBits = 23 - kMantissaBits;
  const hn::Rebind<float, DI> df;
  const auto exponent = hn::And(hn::ShiftRight<kMantissaBits>(code), hn::Set(di, 0x1F));
  const auto mantissa = hn::And(code, hn::Set(di, (1 << kMantissaBits) - 1));
  const auto inf_nan = hn::Or(hn::Set(di, 0x7F800000), hn::ShiftLeft<kDropBits>(mantissa));
  const auto subnormal = hn::BitCast(
      di, hn::Mul(hn::ConvertTo(df, mantissa),
                  hn::Set(df, 1.0f / static_cast<float>(1u << (14 + kMantissaBits)))));
  const auto normal = hn::Or(hn::ShiftLeft<23>(hn::Add(exponent, hn::Set(di, 112))),
                             hn::ShiftLeft<kDropBits>(mantissa));
  const auto result = hn::IfThenElse(hn::Eq(exponent, hn::Zero(di)), subnormal, normal);
  return hn::IfThenElse(hn::Eq(exponent, hn::Set(di, 31)), inf_nan, result);
}

template <int kMantissaBits>
void EncodeSmallFloat(const float* values, int count, uint32_t* codes) {
  const hn::ScalableTag<int32_t> di;
  const hn::Rebind<float, decltype(di)> df;
  const size_t n = hn::Lanes(di);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto code = unsigned_small_float_code<kMantissaBits>(di, hn::BitCast(di, hn::LoadU(df, values + i)));
    hn::StoreU(code, di, reinterpret_cast<int32_t*>(codes) + i);
  }
  for (; i < static_cast<size_t>(count); ++i) {
    codes[i] = kMantissaBits == 6 ? float_to_uf11_bits(values[i]) : float_to_uf10_bits(values[i]);
  }
}

template <int kMantissaBits>
void DecodeSmallFloat(const uint32_t* codes, int count, float* values) {
  const hn::ScalableTag<int32_t> di;
  const hn::Rebind<float, decltype(di)> df;
  const size_t n = hn::Lanes(di);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto code = hn::LoadU(di, reinterpret_cast<const int32_t*>(codes) + i);
    hn::StoreU(hn::BitCast(df, unsigned_small_float_value_bits<kMantissaBits>(di, code)), df,
               values + i);
  }
  for (; i < static_cast<size_t>(count); ++i) {
    values[i] = kMantissaBits == 6 ? uf11_bits_to_float(codes[i]) : uf10_bits_to_float(codes[i]);
  }
}

template <int kMantissaBits>
void QuantizeSmallFloat(float* values, int count) {
  const hn::ScalableTag<int32_t> di;
  const hn::Rebind<float, decltype(di)> df;
  const size_t n = hn::Lanes(di);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto code = unsigned_small_float_code<kMantissaBits>(di, hn::BitCast(di, hn::LoadU(df, values + i)));
    hn::StoreU(hn::BitCast(df, unsigned_small_float_value_bits<kMantissaBits>(di, code)), df,
               values + i);
  }
  for (; i < static_cast<size_t>(count); ++i) {
    values[i] = kMantissaBits == 6 ? uf11_bits_to_float(float_to_uf11_bits(values[i]))
                                   : uf10_bits_to_float(float_to_uf10_bits(values[i]));
  }
}

void EncodeSmallFloatKernel(const float* values, int count, int mantissa_bits, uint32_t* codes) {
  if (mantissa_bits == 6) return EncodeSmallFloat<6>(values, count, codes);
  EncodeSmallFloat<5>(values, count, codes);
}
void DecodeSmallFloatKernel(const uint32_t* codes, int count, int mantissa_bits, float* values) {
  if (mantissa_bits == 6) return DecodeSmallFloat<6>(codes, count, values);
  DecodeSmallFloat<5>(codes, count, values);
}
void QuantizeSmallFloatKernel(float* values, int count, int mantissa_bits) {
  if (mantissa_bits == 6) return QuantizeSmallFloat<6>(values, count);
  QuantizeSmallFloat<5>(values, count);
}

// float_to_unorm on double lanes: 0 for NaN and v <= 0, max for v >= 1, else floor(v * max + 0.5).
void EncodeUnormCodesKernel(const float* values, int count, int bits, uint32_t* codes) {
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const hn::Rebind<int32_t, decltype(dd)> di;
  const size_t n = hn::Lanes(dd);
  const auto max_code = hn::Set(dd, static_cast<double>((1u << bits) - 1));
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto v = hn::PromoteTo(dd, hn::LoadU(df, values + i));
    const auto code = hn::Floor(hn::Add(hn::Mul(v, max_code), hn::Set(dd, 0.5)));
    const auto clamped = hn::IfThenElse(hn::Ge(v, hn::Set(dd, 1.0)), max_code, code);
    const auto result = hn::IfThenElseZero(hn::Gt(v, hn::Zero(dd)), clamped);
    hn::StoreU(hn::DemoteTo(di, result), di, reinterpret_cast<int32_t*>(codes) + i);
  }
  for (; i < static_cast<size_t>(count); ++i) codes[i] = float_to_unorm(values[i], bits);
}

// unorm_to_float: the code over the maximum in double (exact IEEE division), then float.
void DecodeUnormCodesKernel(const uint32_t* codes, int count, int bits, float* values) {
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const hn::Rebind<int32_t, decltype(dd)> di;
  const size_t n = hn::Lanes(dd);
  const auto max_code = hn::Set(dd, static_cast<double>((1u << bits) - 1));
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto code = hn::PromoteTo(dd, hn::LoadU(di, reinterpret_cast<const int32_t*>(codes) + i));
    hn::StoreU(hn::DemoteTo(df, hn::Div(code, max_code)), df, values + i);
  }
  for (; i < static_cast<size_t>(count); ++i) values[i] = unorm_to_float(codes[i], bits);
}

// pixel_format.cpp's encode_stencil: 0 for NaN and v <= 0, 255 for v >= 255, else
// floor(v + 0.5f) (in float). Lanes outside (0, 255) are zeroed before the conversion to int.
template <class DF>
HWY_INLINE hn::Vec<hn::RebindToSigned<DF>> stencil_code(DF df, hn::Vec<DF> v) {
  const hn::RebindToSigned<DF> di;
  const auto in_range = hn::And(hn::Gt(v, hn::Zero(df)), hn::Lt(v, hn::Set(df, 255.0f)));
  const auto rounded = hn::Floor(hn::Add(hn::IfThenElseZero(in_range, v), hn::Set(df, 0.5f)));
  const auto code = hn::IfThenElseZero(hn::RebindMask(di, in_range), hn::ConvertTo(di, rounded));
  return hn::IfThenElse(hn::RebindMask(di, hn::Ge(v, hn::Set(df, 255.0f))), hn::Set(di, 255), code);
}

uint32_t scalar_stencil(float value) {
  if (!(value > 0.0f)) return 0;
  if (value >= 255.0f) return 255;
  return static_cast<uint32_t>(std::floor(value + 0.5f));
}

void EncodeStencilKernel(const float* values, int count, uint32_t* codes) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const size_t n = hn::Lanes(df);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    hn::StoreU(stencil_code(df, hn::LoadU(df, values + i)), di,
               reinterpret_cast<int32_t*>(codes) + i);
  }
  for (; i < static_cast<size_t>(count); ++i) codes[i] = scalar_stencil(values[i]);
}

void QuantizeStencilKernel(float* values, int count) {
  const hn::ScalableTag<float> df;
  const size_t n = hn::Lanes(df);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    hn::StoreU(hn::ConvertTo(df, stencil_code(df, hn::LoadU(df, values + i))), df, values + i);
  }
  for (; i < static_cast<size_t>(count); ++i) {
    values[i] = static_cast<float>(scalar_stencil(values[i]));
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(EncodeSmallFloatKernel);
HWY_EXPORT(DecodeSmallFloatKernel);
HWY_EXPORT(QuantizeSmallFloatKernel);
HWY_EXPORT(EncodeUnormCodesKernel);
HWY_EXPORT(DecodeUnormCodesKernel);
HWY_EXPORT(EncodeStencilKernel);
HWY_EXPORT(QuantizeStencilKernel);

void encode_unsigned_small_float_simd(const float* values, int count, int mantissa_bits,
                                      uint32_t* codes) {
  HWY_DYNAMIC_DISPATCH(EncodeSmallFloatKernel)(values, count, mantissa_bits, codes);
}
void decode_unsigned_small_float_simd(const uint32_t* codes, int count, int mantissa_bits,
                                      float* values) {
  HWY_DYNAMIC_DISPATCH(DecodeSmallFloatKernel)(codes, count, mantissa_bits, values);
}
void quantize_unsigned_small_float_simd(float* values, int count, int mantissa_bits) {
  HWY_DYNAMIC_DISPATCH(QuantizeSmallFloatKernel)(values, count, mantissa_bits);
}
void encode_unorm_codes_simd(const float* values, int count, int bits, uint32_t* codes) {
  HWY_DYNAMIC_DISPATCH(EncodeUnormCodesKernel)(values, count, bits, codes);
}
void decode_unorm_codes_simd(const uint32_t* codes, int count, int bits, float* values) {
  HWY_DYNAMIC_DISPATCH(DecodeUnormCodesKernel)(codes, count, bits, values);
}
void encode_stencil_simd(const float* values, int count, uint32_t* codes) {
  HWY_DYNAMIC_DISPATCH(EncodeStencilKernel)(values, count, codes);
}
void quantize_stencil_simd(float* values, int count) {
  HWY_DYNAMIC_DISPATCH(QuantizeStencilKernel)(values, count);
}

}  // namespace ontile
#endif  // HWY_ONCE
