// Pixel format tables and the exact float <-> stored-bits conversions (see pixel_format.h).
// Every quantize path is the composition of the same scalar encode and decode functions that
// encode_pixel/decode_pixel use, minus the byte packing, so the two agree bit for bit.
#include "raster/pixel_format.h"

#include "raster/packed_bytes.h"
#include "raster/srgb8_tables.h"

#include <bit>
#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

namespace ontile {
namespace {

struct FormatInfo {
  PixelFormat format;
  const char* name;
  int bytes;
  int channels;
  bool depth;
};

constexpr FormatInfo kFormats[] = {
    {PixelFormat::RGBA8_UNORM, "rgba8", 4, 4, false},
    {PixelFormat::RGBA8_SRGB, "rgba8_srgb", 4, 4, false},
    {PixelFormat::RGB10A2_UNORM, "rgb10a2", 4, 4, false},
    {PixelFormat::RG11B10_FLOAT, "rg11b10f", 4, 3, false},
    {PixelFormat::RGBA16_FLOAT, "rgba16f", 8, 4, false},
    {PixelFormat::RG16_FLOAT, "rg16f", 4, 2, false},
    {PixelFormat::R32_FLOAT, "r32f", 4, 1, false},
    {PixelFormat::RGBA32_FLOAT, "rgba32f", 16, 4, false},
    {PixelFormat::D32_FLOAT, "d32f", 4, 1, true},
    {PixelFormat::D24S8, "d24s8", 4, 2, true},
    {PixelFormat::D16_UNORM, "d16", 2, 1, true},
    {PixelFormat::RG16_UNORM, "rg16", 4, 2, false},
};

constexpr bool formats_indexed_by_enum() {
  for (int i = 0; i < static_cast<int>(std::size(kFormats)); ++i) {
    if (static_cast<int>(kFormats[i].format) != i) return false;
  }
  return true;
}
static_assert(formats_indexed_by_enum(), "kFormats must list formats in enum order");

const FormatInfo& info(PixelFormat format) { return kFormats[static_cast<int>(format)]; }

// Exact sRGB EOTF of IEC 61966-2-1 (sRGB-encoded value in [0, 1] -> linear).
double srgb_eotf(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

}  // namespace

// See srgb8_tables.h: thresholds[c] is the smallest float whose OETF reaches (c + 0.5) / 255.
Srgb8Tables::Srgb8Tables() {
  for (int c = 0; c < 256; ++c) decode[c] = static_cast<float>(srgb_eotf(c / 255.0));
  for (int c = 0; c < 255; ++c) {
    const double boundary = srgb_eotf((c + 0.5) / 255.0);
    float t = static_cast<float>(boundary);
    if (static_cast<double>(t) < boundary) t = std::nextafter(t, 2.0f);
    thresholds[c] = t;
  }
  thresholds[255] = std::numeric_limits<float>::infinity();
  int code = 0;
  for (int bucket = 0; bucket < kSrgb8BucketCount; ++bucket) {
    const float start = std::bit_cast<float>(kSrgb8BucketLowestBits +
                                             (uint32_t(bucket) << (23 - kSrgb8BucketMantissaBits)));
    while (thresholds[code] <= start) ++code;
    bucket_start[bucket] = code;
  }
}

const Srgb8Tables& srgb8_tables() {
  static const Srgb8Tables tables;
  return tables;
}

namespace {

uint8_t srgb8_code(const Srgb8Tables& tables, float linear) {
  if (!(linear >= std::bit_cast<float>(kSrgb8BucketLowestBits))) return 0;  // also NaN, negatives
  if (linear >= 1.0f) return 255;
  const uint32_t bucket =
      (std::bit_cast<uint32_t>(linear) - kSrgb8BucketLowestBits) >> (23 - kSrgb8BucketMantissaBits);
  uint32_t code = tables.bucket_start[bucket];
  while (linear >= tables.thresholds[code]) ++code;
  return static_cast<uint8_t>(code);
}

// --- Small floats: 5-bit exponent (bias 15), kMantissaBits mantissa bits, optional sign bit
// above them (binary16), as in Vulkan "Floating Point Numbers" and "Unsigned 11-Bit ...". ---

template <int kMantissaBits, bool kSigned>
uint32_t encode_small_float(float value) {
  constexpr int kDropBits = 23 - kMantissaBits;
  constexpr uint32_t kMantissaMask = (1u << kMantissaBits) - 1;
  constexpr uint32_t kExponentAllOnes = 0x1Fu << kMantissaBits;
  constexpr uint32_t kMaxFinite = (0x1Eu << kMantissaBits) | kMantissaMask;
  const uint32_t f = std::bit_cast<uint32_t>(value);
  const uint32_t sign = kSigned ? (f >> 31) << (kMantissaBits + 5) : 0;
  const uint32_t magnitude = f & 0x7FFFFFFFu;
  if (magnitude > 0x7F800000u) {  // NaN: keep the top payload bits, never turn into Inf
    uint32_t payload = (magnitude >> kDropBits) & kMantissaMask;
    if (payload == 0) payload = 1u << (kMantissaBits - 1);
    return sign | kExponentAllOnes | payload;
  }
  if (!kSigned && (f >> 31)) return 0;  // unsigned formats: negatives (and -Inf, -0) -> 0
  if (magnitude == 0x7F800000u) return sign | kExponentAllOnes;
  if (magnitude < 0x38800000u) {
    // Below 2^-14 the target is subnormal: code = round_even(x * 2^(14 + M)). The scaling is
    // exact; adding and subtracting 2^23 rounds to an integer in the default (nearest-even)
    // mode. A result of 2^M is the smallest normal's code, so the carry needs no special case.
    constexpr float kScale = static_cast<float>(1u << (14 + kMantissaBits));
    const float scaled = std::bit_cast<float>(magnitude) * kScale;
    const float rounded = (scaled + 8388608.0f) - 8388608.0f;
    return sign | static_cast<uint32_t>(rounded);
  }
  // Normal: rebias the exponent (127 -> 15), then round the dropped bits to nearest even; a
  // mantissa carry correctly increments the exponent.
  const uint32_t rebased = magnitude - ((127u - 15u) << 23);
  const uint32_t rounded = rebased + ((1u << (kDropBits - 1)) - 1) + ((rebased >> kDropBits) & 1u);
  const uint32_t code = rounded >> kDropBits;
  if (code > kMaxFinite) return kSigned ? (sign | kExponentAllOnes) : kMaxFinite;
  return sign | code;
}

template <int kMantissaBits, bool kSigned>
float decode_small_float(uint32_t code) {
  constexpr int kDropBits = 23 - kMantissaBits;
  constexpr uint32_t kMantissaMask = (1u << kMantissaBits) - 1;
  const uint32_t sign = kSigned ? ((code >> (kMantissaBits + 5)) & 1u) << 31 : 0;
  const uint32_t exponent = (code >> kMantissaBits) & 0x1Fu;
  const uint32_t mantissa = code & kMantissaMask;
  if (exponent == 31) return std::bit_cast<float>(sign | 0x7F800000u | (mantissa << kDropBits));
  if (exponent == 0) {  // subnormal: mantissa * 2^-(14 + M), exact in float
    constexpr float kStep = 1.0f / static_cast<float>(1u << (14 + kMantissaBits));
    const float magnitude = static_cast<float>(mantissa) * kStep;
    return std::bit_cast<float>(sign | std::bit_cast<uint32_t>(magnitude));
  }
  return std::bit_cast<float>(sign | ((exponent + 112u) << 23) | (mantissa << kDropBits));
}

float quantize_half(float v) {
  return decode_small_float<10, true>(encode_small_float<10, true>(v));
}
float quantize_uf11(float v) {
  return decode_small_float<6, false>(encode_small_float<6, false>(v));
}
float quantize_uf10(float v) {
  return decode_small_float<5, false>(encode_small_float<5, false>(v));
}

float quantize_unorm(float v, int bits) { return unorm_to_float(float_to_unorm(v, bits), bits); }

uint32_t encode_stencil(float value) {
  if (!(value > 0.0f)) return 0;  // also NaN
  if (value >= 255.0f) return 255;
  return static_cast<uint32_t>(std::floor(value + 0.5f));
}

using namespace packed_bytes;

}  // namespace

int bytes_per_pixel(PixelFormat format) { return info(format).bytes; }
int bits_per_pixel(PixelFormat format) { return info(format).bytes * 8; }
const char* format_name(PixelFormat format) { return info(format).name; }
bool is_depth_format(PixelFormat format) { return info(format).depth; }
int channel_count(PixelFormat format) { return info(format).channels; }

std::optional<PixelFormat> parse_pixel_format(std::string_view name) {
  for (const FormatInfo& f : kFormats) {
    if (name == f.name) return f.format;
  }
  return std::nullopt;
}

uint32_t float_to_unorm(float value, int bits) {
  const uint32_t max_code = (1u << bits) - 1;
  if (!(value > 0.0f)) return 0;  // also NaN
  if (value >= 1.0f) return max_code;
  // value * max_code is exact in double (24 + 24 bits), so this is round-half-up of the exact
  // product, with no float rounding in between.
  return static_cast<uint32_t>(std::floor(static_cast<double>(value) * max_code + 0.5));
}

float unorm_to_float(uint32_t code, int bits) {
  const uint32_t max_code = (1u << bits) - 1;
  return static_cast<float>(static_cast<double>(code) / max_code);
}

const std::array<float, 256>& srgb8_decode_table() { return srgb8_tables().decode; }

bool unorm8_decodes_by_division() {
  static const bool exact = [] {
    const std::array<float, 256>& table = unorm8_decode_table();
    for (int c = 0; c < 256; ++c) {
      if (static_cast<float>(c) / 255.0f != table[c]) return false;
    }
    return true;
  }();
  return exact;
}

const std::array<float, 256>& unorm8_decode_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int c = 0; c < 256; ++c) t[c] = unorm_to_float(static_cast<uint32_t>(c), 8);
    return t;
  }();
  return table;
}

uint8_t linear_to_srgb8(float linear) { return srgb8_code(srgb8_tables(), linear); }

uint16_t float_to_half_bits(float value) {
  return static_cast<uint16_t>(encode_small_float<10, true>(value));
}
float half_bits_to_float(uint16_t bits) { return decode_small_float<10, true>(bits); }
const float* half_decode_table() {
  static const std::vector<float> table = [] {
    std::vector<float> t(65536);
    for (uint32_t code = 0; code < t.size(); ++code) t[code] = half_bits_to_float(static_cast<uint16_t>(code));
    return t;
  }();
  return table.data();
}
uint32_t float_to_uf11_bits(float value) { return encode_small_float<6, false>(value); }
uint32_t float_to_uf10_bits(float value) { return encode_small_float<5, false>(value); }
float uf11_bits_to_float(uint32_t bits) { return decode_small_float<6, false>(bits & 0x7FFu); }
float uf10_bits_to_float(uint32_t bits) { return decode_small_float<5, false>(bits & 0x3FFu); }

void encode_pixel(PixelFormat format, glm::vec4 v, uint8_t* dst) {
  switch (format) {
    case PixelFormat::RGBA8_UNORM:
      for (int i = 0; i < 4; ++i) dst[i] = static_cast<uint8_t>(float_to_unorm(v[i], 8));
      return;
    case PixelFormat::RGBA8_SRGB:
      for (int i = 0; i < 3; ++i) dst[i] = srgb8_code(srgb8_tables(), v[i]);
      dst[3] = static_cast<uint8_t>(float_to_unorm(v.w, 8));  // alpha is always linear
      return;
    case PixelFormat::RGB10A2_UNORM:
      store_u32(dst, float_to_unorm(v.x, 10) | (float_to_unorm(v.y, 10) << 10) |
                         (float_to_unorm(v.z, 10) << 20) | (float_to_unorm(v.w, 2) << 30));
      return;
    case PixelFormat::RG11B10_FLOAT:
      store_u32(dst, float_to_uf11_bits(v.x) | (float_to_uf11_bits(v.y) << 11) |
                         (float_to_uf10_bits(v.z) << 22));
      return;
    case PixelFormat::RGBA16_FLOAT:
      for (int i = 0; i < 4; ++i) store_u16(dst + 2 * i, float_to_half_bits(v[i]));
      return;
    case PixelFormat::RG16_FLOAT:
      for (int i = 0; i < 2; ++i) store_u16(dst + 2 * i, float_to_half_bits(v[i]));
      return;
    case PixelFormat::R32_FLOAT:
    case PixelFormat::D32_FLOAT:
      store_f32(dst, v.x);
      return;
    case PixelFormat::RGBA32_FLOAT:
      for (int i = 0; i < 4; ++i) store_f32(dst + 4 * i, v[i]);
      return;
    case PixelFormat::D24S8:
      store_u32(dst, float_to_unorm(v.x, 24) | (encode_stencil(v.y) << 24));
      return;
    case PixelFormat::D16_UNORM:
      store_u16(dst, float_to_unorm(v.x, 16));
      return;
    case PixelFormat::RG16_UNORM:
      store_u16(dst, float_to_unorm(v.x, 16));
      store_u16(dst + 2, float_to_unorm(v.y, 16));
      return;
  }
}

glm::vec4 decode_pixel(PixelFormat format, const uint8_t* src) {
  switch (format) {
    case PixelFormat::RGBA8_UNORM: {
      const std::array<float, 256>& unorm = unorm8_decode_table();
      return {unorm[src[0]], unorm[src[1]], unorm[src[2]], unorm[src[3]]};
    }
    case PixelFormat::RGBA8_SRGB: {
      const std::array<float, 256>& srgb = srgb8_decode_table();
      return {srgb[src[0]], srgb[src[1]], srgb[src[2]], unorm8_decode_table()[src[3]]};
    }
    case PixelFormat::RGB10A2_UNORM: {
      const uint32_t p = load_u32(src);
      return {unorm_to_float(p & 0x3FFu, 10), unorm_to_float((p >> 10) & 0x3FFu, 10),
              unorm_to_float((p >> 20) & 0x3FFu, 10), unorm_to_float(p >> 30, 2)};
    }
    case PixelFormat::RG11B10_FLOAT: {
      const uint32_t p = load_u32(src);
      return {uf11_bits_to_float(p), uf11_bits_to_float(p >> 11), uf10_bits_to_float(p >> 22),
              1.0f};
    }
    case PixelFormat::RGBA16_FLOAT:
      return {half_bits_to_float(static_cast<uint16_t>(load_u16(src))),
              half_bits_to_float(static_cast<uint16_t>(load_u16(src + 2))),
              half_bits_to_float(static_cast<uint16_t>(load_u16(src + 4))),
              half_bits_to_float(static_cast<uint16_t>(load_u16(src + 6)))};
    case PixelFormat::RG16_FLOAT:
      return {half_bits_to_float(static_cast<uint16_t>(load_u16(src))),
              half_bits_to_float(static_cast<uint16_t>(load_u16(src + 2))), 0.0f, 1.0f};
    case PixelFormat::R32_FLOAT:
    case PixelFormat::D32_FLOAT:
      return {load_f32(src), 0.0f, 0.0f, 1.0f};
    case PixelFormat::RGBA32_FLOAT:
      return {load_f32(src), load_f32(src + 4), load_f32(src + 8), load_f32(src + 12)};
    case PixelFormat::D24S8: {
      const uint32_t p = load_u32(src);
      return {unorm_to_float(p & 0xFFFFFFu, 24), static_cast<float>(p >> 24), 0.0f, 1.0f};
    }
    case PixelFormat::D16_UNORM:
      return {unorm_to_float(load_u16(src), 16), 0.0f, 0.0f, 1.0f};
    case PixelFormat::RG16_UNORM:
      return {unorm_to_float(load_u16(src), 16), unorm_to_float(load_u16(src + 2), 16), 0.0f, 1.0f};
  }
  return {0.0f, 0.0f, 0.0f, 1.0f};
}

glm::vec4 quantize_pixel(PixelFormat format, glm::vec4 v) {
  switch (format) {
    case PixelFormat::RGBA8_UNORM: {
      const std::array<float, 256>& unorm = unorm8_decode_table();
      return {unorm[float_to_unorm(v.x, 8)], unorm[float_to_unorm(v.y, 8)],
              unorm[float_to_unorm(v.z, 8)], unorm[float_to_unorm(v.w, 8)]};
    }
    case PixelFormat::RGBA8_SRGB: {
      const Srgb8Tables& srgb = srgb8_tables();
      return {srgb.decode[srgb8_code(srgb, v.x)], srgb.decode[srgb8_code(srgb, v.y)],
              srgb.decode[srgb8_code(srgb, v.z)], unorm8_decode_table()[float_to_unorm(v.w, 8)]};
    }
    case PixelFormat::RGB10A2_UNORM:
      return {quantize_unorm(v.x, 10), quantize_unorm(v.y, 10), quantize_unorm(v.z, 10),
              quantize_unorm(v.w, 2)};
    case PixelFormat::RG11B10_FLOAT:
      return {quantize_uf11(v.x), quantize_uf11(v.y), quantize_uf10(v.z), 1.0f};
    case PixelFormat::RGBA16_FLOAT:
      return {quantize_half(v.x), quantize_half(v.y), quantize_half(v.z), quantize_half(v.w)};
    case PixelFormat::RG16_FLOAT:
      return {quantize_half(v.x), quantize_half(v.y), 0.0f, 1.0f};
    case PixelFormat::R32_FLOAT:
    case PixelFormat::D32_FLOAT:
      return {v.x, 0.0f, 0.0f, 1.0f};
    case PixelFormat::RGBA32_FLOAT:
      return v;
    case PixelFormat::D24S8:
      return {quantize_unorm(v.x, 24), static_cast<float>(encode_stencil(v.y)), 0.0f, 1.0f};
    case PixelFormat::D16_UNORM:
      return {quantize_unorm(v.x, 16), 0.0f, 0.0f, 1.0f};
    case PixelFormat::RG16_UNORM:
      return {quantize_unorm(v.x, 16), quantize_unorm(v.y, 16), 0.0f, 1.0f};
  }
  return {0.0f, 0.0f, 0.0f, 1.0f};
}

}  // namespace ontile
