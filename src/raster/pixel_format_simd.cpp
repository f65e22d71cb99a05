// SIMD channel conversions (see pixel_format_simd.h), compiled per target by Highway's
// foreach_target. UNORM conversion runs in double exactly as the scalar float_to_unorm does
// (the product value * (2^bits - 1) is exact in double); sRGB uses the scalar path's tables
// through gathers. Only IEEE operations and table reads: every target gives the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/pixel_format_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

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

void QuantizeUnormKernel(float* values, int count, int bits) {
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
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const hn::Rebind<int32_t, decltype(dd)> di;
  const hn::Rebind<uint8_t, decltype(dd)> d8;
  const size_t n = hn::Lanes(dd);
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto code = unorm_code(dd, hn::PromoteTo(dd, hn::LoadU(df, values + i)), 255.0);
    hn::StoreU(hn::DemoteTo(d8, hn::DemoteTo(di, code)), d8, dst + i);
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

void QuantizeSrgb8Kernel(float* values, int count) {
  const hn::ScalableTag<float> df;
  const size_t n = hn::Lanes(df);
  const Srgb8Tables& t = srgb8_tables();
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    const auto code = srgb8_code(df, hn::LoadU(df, values + i), t);
    hn::StoreU(hn::GatherIndex(df, t.decode.data(), code), df, values + i);
  }
  for (; i < static_cast<size_t>(count); ++i) values[i] = t.decode[linear_to_srgb8(values[i])];
}

void EncodeSrgb8Kernel(const float* values, int count, uint8_t* dst) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::Rebind<uint8_t, decltype(di)> d8;
  const size_t n = hn::Lanes(df);
  const Srgb8Tables& t = srgb8_tables();
  size_t i = 0;
  for (; i + n <= static_cast<size_t>(count); i += n) {
    hn::StoreU(hn::DemoteTo(d8, srgb8_code(df, hn::LoadU(df, values + i), t)), d8, dst + i);
  }
  for (; i < static_cast<size_t>(count); ++i) dst[i] = linear_to_srgb8(values[i]);
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
HWY_EXPORT(QuantizeSrgb8Kernel);
HWY_EXPORT(EncodeSrgb8Kernel);
HWY_EXPORT(DecodeTable8Kernel);

void quantize_unorm_simd(float* values, int count, int bits) {
  HWY_DYNAMIC_DISPATCH(QuantizeUnormKernel)(values, count, bits);
}
void quantize_srgb8_simd(float* values, int count) {
  HWY_DYNAMIC_DISPATCH(QuantizeSrgb8Kernel)(values, count);
}
void encode_unorm8_simd(const float* values, int count, uint8_t* dst) {
  HWY_DYNAMIC_DISPATCH(EncodeUnorm8Kernel)(values, count, dst);
}
void encode_srgb8_simd(const float* values, int count, uint8_t* dst) {
  HWY_DYNAMIC_DISPATCH(EncodeSrgb8Kernel)(values, count, dst);
}
void decode_table8_simd(const uint8_t* src, int count, const float* table, float* dst) {
  HWY_DYNAMIC_DISPATCH(DecodeTable8Kernel)(src, count, table, dst);
}

}  // namespace ontile
#endif  // HWY_ONCE
