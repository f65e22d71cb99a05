// Batch texel reads on SIMD lanes (see texture_batch_simd.h), compiled once per SIMD target by
// Highway's foreach_target and chosen at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/texture_batch_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/lane_bits-inl.h"

#include <bit>
#include <cstring>

#include "raster/lane_bits.h"
#include "raster/texel_trace.h"
#include "raster/texture_batch_simd.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using VI = hn::Vec<DI>;

// Beyond 2^24 every float is an integer: where texture.cpp's texel_coord clamps (ClampToEdge).
constexpr float kMaxExactTexelCoord = 16777216.0f;
// Mask of the float lanes of fragments f.. whose bit is set in `bits`.
HWY_INLINE hn::Mask<DF> float_lanes_of(DF df, uint64_t bits, size_t f) {
  const DI di;
  const VI word = hn::Set(di, static_cast<int32_t>((bits >> f) & 0xFFFFu));
  return hn::RebindMask(df, hn::Ne(hn::And(word, hn::LoadU(di, kLaneBit)), hn::Zero(di)));
}

void NearestClampedTexelsKernel(const float* coord, int count, int size, int32_t* out) {
  const DF df;
  const DI di;
  const auto limit = hn::Set(df, kMaxExactTexelCoord);
  const auto scale = hn::Set(df, static_cast<float>(size));
  const VI last = hn::Set(di, size - 1);
  const auto zero = hn::Zero(df);
  // A lane with 0 <= u * size < size <= 2^24 (finite, |u| < 2^24) passes every clamp below
  // unchanged: its texel is floor(u * size) (render-target copies, full-screen passes).
  const bool exact_range = size <= (1 << 24);
  for (size_t f = 0; f < static_cast<size_t>(count); f += hn::Lanes(df)) {
    if (exact_range) {
      const auto x = hn::Mul(hn::LoadU(df, coord + f), scale);
      if (hn::AllTrue(df, hn::And(hn::Ge(x, zero), hn::Lt(x, scale)))) {
        hn::StoreU(hn::ConvertTo(di, hn::Floor(x)), di, out + f);
        continue;
      }
    }
    auto u = hn::LoadU(df, coord + f);
    u = hn::IfThenElseZero(hn::IsFinite(u), u);
    u = hn::IfThenElse(hn::Lt(hn::Abs(u), limit), u, hn::CopySign(limit, u));
    auto x = hn::Mul(u, scale);
    x = hn::IfThenElse(hn::Lt(hn::Abs(x), limit), x, hn::CopySign(limit, x));
    const VI i = hn::ConvertTo(di, hn::Floor(x));  // |x| <= 2^24: exact
    hn::StoreU(hn::Min(hn::Max(i, hn::Zero(di)), last), di, out + f);
  }
}

void LoadTexelsKernel(const Texture2D::TexelView& view, const int32_t* x, const int32_t* y,
                      int count, uint64_t active, float (&colour)[4][kBatchFragments]) {
  const DF df;
  const DI di;
  const size_t n = hn::Lanes(df);
  const VI width = hn::Set(di, view.width);
  if (view.texels8) {
    // 8-bit RGBA: the texel's bytes through the decode tables, as TexelView::load.
    alignas(64) int32_t packed[kBatchFragments];
    if (reinterpret_cast<uintptr_t>(view.texels8) % 4 == 0 &&
        int64_t{view.width} * view.height < (int64_t{1} << 31)) {
      // A texel's 4 bytes are one 32-bit word: one gather per vector (texel indices fit 31 bits).
      const int32_t* words = reinterpret_cast<const int32_t*>(view.texels8);
      for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
        const VI texel = hn::Add(hn::Mul(hn::LoadU(di, y + f), width), hn::LoadU(di, x + f));
        hn::Store(hn::GatherIndex(di, words, texel), di, packed + f);
      }
    } else {
      for (int f = 0; f < count; ++f) {
        const size_t texel = static_cast<size_t>(y[f]) * static_cast<size_t>(view.width) + x[f];
        std::memcpy(&packed[f], view.texels8 + texel * 4, 4);
      }
    }
    const VI byte = hn::Set(di, 0xFF);
    // UNORM channels by one division (the table's values, unorm8_decodes_by_division) rather
    // than a gather per channel.
    const float* unorm = unorm8_decodes_by_division() ? unorm8_decode_table().data() : nullptr;
    const bool rgb_unorm = view.rgb_decode == unorm, alpha_unorm = view.alpha_decode == unorm;
    const auto max_code = hn::Set(df, 255.0f);
    const auto decode = [&](int c, VI code) {
      if (c < 3 ? rgb_unorm : alpha_unorm) return hn::Div(hn::ConvertTo(df, code), max_code);
      return hn::GatherIndex(df, c < 3 ? view.rgb_decode : view.alpha_decode, code);
    };
    const bool all_active = count >= 64 ? active == ~uint64_t{0} : active == (uint64_t{1} << count) - 1;
    for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
      const VI p = hn::Load(di, packed + f);
      const VI bytes[4] = {hn::And(p, byte), hn::And(hn::ShiftRight<8>(p), byte),
                           hn::And(hn::ShiftRight<16>(p), byte), hn::And(hn::ShiftRight<24>(p), byte)};
      if (all_active) {  // whole batches (copies): no lanes to keep
        for (int c = 0; c < 4; ++c) hn::StoreU(decode(c, bytes[c]), df, colour[c] + f);
        continue;
      }
      const auto on = float_lanes_of(df, active, f);
      for (int c = 0; c < 4; ++c) {
        const auto value = decode(c, bytes[c]);
        hn::StoreU(hn::IfThenElse(on, value, hn::LoadU(df, colour[c] + f)), df, colour[c] + f);
      }
    }
    return;
  }
  if (view.texels32f) {
    for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
      const auto on = float_lanes_of(df, active, f);
      const VI texel = hn::Add(hn::Mul(hn::LoadU(di, y + f), width), hn::LoadU(di, x + f));
      const VI first = hn::ShiftLeft<2>(texel);
      for (int c = 0; c < 4; ++c) {
        const auto value = hn::GatherIndex(df, view.texels32f, hn::Add(first, hn::Set(di, c)));
        hn::StoreU(hn::IfThenElse(on, value, hn::LoadU(df, colour[c] + f)), df, colour[c] + f);
      }
    }
    return;
  }
  if (view.surface_bytes && view.surface_format == PixelFormat::RGBA16_FLOAT) {
    // binary16 RGBA: two 32-bit words per texel (host order, R and B in the low halves), each
    // code through half_decode_table, as load_surface_texel.
    const float* table = half_decode_table();
    const int32_t* words = reinterpret_cast<const int32_t*>(view.surface_bytes);
    const VI low_half = hn::Set(di, 0xFFFF);
    for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
      const auto on = float_lanes_of(df, active, f);
      const VI texel = hn::Add(hn::Mul(hn::LoadU(di, y + f), width), hn::LoadU(di, x + f));
      const VI first = hn::ShiftLeft<1>(texel);
      const VI rg = hn::GatherIndex(di, words, first);
      const VI ba = hn::GatherIndex(di, words, hn::Add(first, hn::Set(di, 1)));
      const VI codes[4] = {hn::And(rg, low_half), hn::And(hn::ShiftRight<16>(rg), low_half),
                           hn::And(ba, low_half), hn::And(hn::ShiftRight<16>(ba), low_half)};
      for (int c = 0; c < 4; ++c) {
        const auto value = hn::GatherIndex(df, table, codes[c]);
        hn::StoreU(hn::IfThenElse(on, value, hn::LoadU(df, colour[c] + f)), df, colour[c] + f);
      }
    }
    return;
  }
  if (view.surface_bytes && (view.surface_format == PixelFormat::D32_FLOAT ||
                             view.surface_format == PixelFormat::R32_FLOAT)) {
    // One float per texel, its bits as stored, then (d, 0, 0, 1) as load_surface_texel.
    const float* texels = reinterpret_cast<const float*>(view.surface_bytes);
    const hn::Vec<DF> constant[4] = {hn::Zero(df), hn::Zero(df), hn::Zero(df), hn::Set(df, 1.0f)};
    for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
      const auto on = float_lanes_of(df, active, f);
      const VI texel = hn::Add(hn::Mul(hn::LoadU(di, y + f), width), hn::LoadU(di, x + f));
      const auto depth = hn::GatherIndex(df, texels, texel);
      for (int c = 0; c < 4; ++c) {
        const auto value = c == 0 ? depth : constant[c];
        hn::StoreU(hn::IfThenElse(on, value, hn::LoadU(df, colour[c] + f)), df, colour[c] + f);
      }
    }
    return;
  }
  if (view.surface_bytes && view.surface_format == PixelFormat::RGB10A2_UNORM) {
    // One 32-bit word per texel, each code by one float division as DecodeRgb10a2Kernel
    // (unorm_to_float's bits for every code, checked by PixelRows), as load_surface_texel.
    const int32_t* words = reinterpret_cast<const int32_t*>(view.surface_bytes);
    const VI ten_bits = hn::Set(di, 0x3FF);
    const auto max10 = hn::Set(df, 1023.0f), max2 = hn::Set(df, 3.0f);
    for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
      const auto on = float_lanes_of(df, active, f);
      const VI texel = hn::Add(hn::Mul(hn::LoadU(di, y + f), width), hn::LoadU(di, x + f));
      const VI word = hn::GatherIndex(di, words, texel);
      const hn::Vec<DF> value[4] = {
          hn::Div(hn::ConvertTo(df, hn::And(word, ten_bits)), max10),
          hn::Div(hn::ConvertTo(df, hn::And(hn::ShiftRight<10>(word), ten_bits)), max10),
          hn::Div(hn::ConvertTo(df, hn::And(hn::ShiftRight<20>(word), ten_bits)), max10),
          hn::Div(hn::ConvertTo(df, hn::And(hn::ShiftRight<30>(word), hn::Set(di, 3))), max2)};
      for (int c = 0; c < 4; ++c) {
        hn::StoreU(hn::IfThenElse(on, value[c], hn::LoadU(df, colour[c] + f)), df, colour[c] + f);
      }
    }
    return;
  }
  for (uint64_t rest = active; rest != 0; rest &= rest - 1) {
    const int f = std::countr_zero(rest);
    const glm::vec4 texel = view.load(x[f], y[f]);
    for (int c = 0; c < 4; ++c) colour[c][f] = texel[c];
  }
}

// The granule offsets (texel byte offset / 64) that record_texel_address would append for
// fragments [0, count) reading texels (x[f], y[f]), a granule equal to the one before dropped
// (`previous`: the one before fragment 0, or -1): written to out (room for kBatchFragments),
// returns how many. Byte offsets fit 31 bits (sample_batch_nearest checks).
int NearestGranulesKernel(const int32_t* x, const int32_t* y, int count, int width,
                          int bytes_per_texel, int32_t previous, int32_t* out) {
  const DI di;
  const size_t n = hn::Lanes(di);
  const VI width_v = hn::Set(di, width), bytes_v = hn::Set(di, bytes_per_texel);
  // granule[0] is the previous one, granule[1 + f] fragment f's.
  alignas(64) int32_t granule[kBatchFragments + 1 + HWY_MAX_BYTES / sizeof(int32_t)];
  granule[0] = previous;
  for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
    const VI texel = hn::Add(hn::Mul(hn::LoadU(di, y + f), width_v), hn::LoadU(di, x + f));
    hn::StoreU(hn::ShiftRight<6>(hn::Mul(texel, bytes_v)), di, granule + 1 + f);
  }
  // Bit f: fragment f's granule differs from the one before. Kept granules are copied one by one
  // (about 2 per quad in a copy): Highway's CompressStore copies a 1 KiB table per call on AVX2.
  uint64_t changed = 0;
  for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
    const auto differs = hn::Ne(hn::LoadU(di, granule + 1 + f), hn::LoadU(di, granule + f));
    changed |= mask_bits(di, differs) << f;
  }
  if (count < 64) changed &= (uint64_t{1} << count) - 1;
  int kept = 0;
  for (; changed != 0; changed &= changed - 1) out[kept++] = granule[1 + std::countr_zero(changed)];
  return kept;
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(NearestClampedTexelsKernel);
HWY_EXPORT(LoadTexelsKernel);
HWY_EXPORT(NearestGranulesKernel);

void nearest_clamped_texels(const float* coord, int count, int size, int32_t* out) {
  HWY_DYNAMIC_DISPATCH(NearestClampedTexelsKernel)(coord, count, size, out);
}

void load_texels(const Texture2D::TexelView& view, const int32_t* x, const int32_t* y, int count,
                 uint64_t active, float (&colour)[4][kBatchFragments]) {
  HWY_DYNAMIC_DISPATCH(LoadTexelsKernel)(view, x, y, count, active, colour);
}

std::optional<PixelFormat> rgba8_codes_format(const Texture2D::TexelView& view) {
  if (view.surface_bytes) {
    if (view.surface_format == PixelFormat::RGBA8_UNORM || view.surface_format == PixelFormat::RGBA8_SRGB) {
      return view.surface_format;
    }
    return std::nullopt;
  }
  if (!view.texels8 || view.alpha_decode != unorm8_decode_table().data()) return std::nullopt;
  if (view.rgb_decode == unorm8_decode_table().data()) return PixelFormat::RGBA8_UNORM;
  if (view.rgb_decode == srgb8_decode_table().data()) return PixelFormat::RGBA8_SRGB;
  return std::nullopt;
}

bool sample_batch_nearest(const Texture2D& texture, const SamplerDesc& sampler, const float* u,
                          const float* v, int fragment_count, float (&out)[4][kBatchFragments],
                          std::optional<PixelFormat>* codes_of) {
  // sample_quad_lanes' one-filter, one-level case (texture.cpp), with the clamp-to-edge wrap.
  if (sampler.mag_filter != FilterMode::Nearest || sampler.min_filter != FilterMode::Nearest ||
      (sampler.mipmap_mode != MipmapMode::None && texture.level_count() != 1) ||
      sampler.wrap_u != WrapMode::ClampToEdge || sampler.wrap_v != WrapMode::ClampToEdge) {
    return false;
  }
  // Block-compressed storage maps texels to blocks; the generic path traces that.
  if (texture.compression() != TextureCompression::None) return false;
  const Texture2D::TexelView view = texture.texel_view(0);
  // Lanes index float channels as 32-bit integers (4 * texel).
  if (int64_t{view.width} * view.height >= (int64_t{1} << 29)) return false;
  const int padded = (fragment_count + 15) & ~15;
  alignas(64) int32_t x[kBatchFragments], y[kBatchFragments];
  nearest_clamped_texels(u, padded, view.width, x);
  nearest_clamped_texels(v, padded, view.height, y);
  std::vector<uint64_t>* const sink = texel_trace_detail::sink;
  if (sink && fragment_count > 0 && view.address % 64 == 0 && view.memory_bytes_per_texel < 65536 &&
      int64_t{view.width} * view.height * static_cast<int64_t>(view.memory_bytes_per_texel) <
          (int64_t{1} << 31)) {
    // A granule-aligned level: granule = address / 64 + byte offset / 64, the offsets compared
    // and compacted on 32-bit lanes (the same granules and drops as the per-fragment loop below).
    const uint64_t base = view.address >> 6;
    const uint64_t last = texel_trace_detail::last_granule;
    const int32_t previous = last >= base && last - base < (uint64_t{1} << 31)
                                 ? static_cast<int32_t>(last - base) : -1;
    alignas(64) int32_t kept[kBatchFragments];
    const int count = HWY_DYNAMIC_DISPATCH(NearestGranulesKernel)(
        x, y, fragment_count, view.width, static_cast<int>(view.memory_bytes_per_texel), previous, kept);
    if (count > 0) {
      const size_t at = sink->size();
      sink->resize(at + static_cast<size_t>(count));
      uint64_t* granules = sink->data() + at;
      for (int i = 0; i < count; ++i) granules[i] = base + static_cast<uint64_t>(kept[i]);
      texel_trace_detail::last_granule = granules[count - 1];
    }
  } else if (sink) {
    // record_texel_address per fragment: a granule that repeats the one before is dropped.
    uint64_t granules[kBatchFragments];
    uint64_t last = texel_trace_detail::last_granule;
    int count = 0;
    for (int f = 0; f < fragment_count; ++f) {
      const uint64_t texel = static_cast<uint64_t>(y[f]) * static_cast<uint64_t>(view.width) +
                             static_cast<uint64_t>(x[f]);
      const uint64_t granule = (view.address + texel * view.memory_bytes_per_texel) >> 6;
      granules[count] = granule;
      count += granule != last;
      last = granule;
    }
    sink->insert(sink->end(), granules, granules + count);
    texel_trace_detail::last_granule = last;
  }
  const uint64_t all = padded >= 64 ? ~uint64_t{0} : (uint64_t{1} << padded) - 1;
  load_texels(view, x, y, padded, all, out);
  if (codes_of) *codes_of = rgba8_codes_format(view);
  return true;
}

}  // namespace ontile
#endif  // HWY_ONCE
