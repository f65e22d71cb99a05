// Attachment pixel formats of the simulated GPU: sizes, names, and exact encode/decode/quantize
// following the Vulkan data-format conversion rules, so tile memory keeps real-hardware precision.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string_view>

namespace ontile {

enum class PixelFormat {
  RGBA8_UNORM,
  RGBA8_SRGB,
  RGB10A2_UNORM,  // Vulkan A2B10G10R10_UNORM_PACK32
  RG11B10_FLOAT,  // Vulkan B10G11R11_UFLOAT_PACK32
  RGBA16_FLOAT,
  RG16_FLOAT,
  R32_FLOAT,
  RGBA32_FLOAT,
  D32_FLOAT,
  D24S8,  // Vulkan D24_UNORM_S8_UINT: depth in bits 0-23, stencil in bits 24-31
  D16_UNORM,
  RG16_UNORM,  // Vulkan R16G16_UNORM (e.g. octahedral-encoded normals)
};

int bytes_per_pixel(PixelFormat format);
int bits_per_pixel(PixelFormat format);
// Short lowercase name used in CLI options and reports, e.g. "rgba8_srgb", "rg11b10f", "d24s8".
const char* format_name(PixelFormat format);
// Inverse of format_name (exact, lowercase); nullopt for anything else.
std::optional<PixelFormat> parse_pixel_format(std::string_view name);
bool is_depth_format(PixelFormat format);
// Channels the format stores (D24S8 counts depth and stencil: 2).
int channel_count(PixelFormat format);

// Writes bytes_per_pixel(format) bytes, little-endian packed as in Vulkan. Colour formats take
// value.rgba; depth formats take value.x as depth, and D24S8 also takes value.y as the stencil
// value (rounded to nearest, clamped to 0..255; NaN -> 0).
void encode_pixel(PixelFormat format, glm::vec4 value, uint8_t* dst);
// Missing channels decode as G = B = 0, A = 1 (Vulkan "Format Conversion"); depth formats give
// (depth, 0, 0, 1), except D24S8 which gives (depth, stencil, 0, 1).
glm::vec4 decode_pixel(PixelFormat format, const uint8_t* src);
// decode_pixel(encode_pixel(value)) bit for bit, without the byte round trip.
glm::vec4 quantize_pixel(PixelFormat format, glm::vec4 value);
// quantize_pixel on `count` values held as structure-of-arrays channels, in place: one format
// dispatch for a whole batch of shaded fragments.
void quantize_pixels(PixelFormat format, float* r, float* g, float* b, float* a, int count);
// encode_pixel / decode_pixel on `count` consecutive pixels (a row of tile memory and of a
// surface): the same bytes and values, one format dispatch per row and SIMD lanes for the 8-bit
// and 32-bit float formats.
void encode_pixels(PixelFormat format, const glm::vec4* src, int count, uint8_t* dst);
void decode_pixels(PixelFormat format, const uint8_t* src, int count, glm::vec4* dst);
// encode_pixels on `rows` rows of `count` pixels, src rows src_row_pixels apart and dst rows
// dst_row_bytes apart (a tile of tile memory into a surface): one dispatch for the whole block
// where the values are already quantised to the format (tile memory holds no other values).
void encode_pixel_rows(PixelFormat format, const glm::vec4* src, size_t src_row_pixels, int count,
                       int rows, uint8_t* dst, size_t dst_row_bytes);

// --- Scalar conversions shared with textures and image IO -------------------------------------

// UNORM (Vulkan "Conversion from Floating-Point to Normalized Fixed-Point"): clamp to [0, 1],
// NaN -> 0, then floor(x * (2^bits - 1) + 0.5), i.e. round to nearest with ties away from zero.
uint32_t float_to_unorm(float value, int bits);
// Vulkan "Conversion from Normalized Fixed-Point to Floating-Point": code / (2^bits - 1).
float unorm_to_float(uint32_t code, int bits);

// 8-bit sRGB (IEC 61966-2-1). Decoding uses the exact EOTF evaluated in double precision and
// rounded to float. Encoding returns the code whose sRGB value is nearest to the exact OETF of
// the input (NaN and values <= 0 -> 0, >= 1 -> 255).
const std::array<float, 256>& srgb8_decode_table();
const std::array<float, 256>& unorm8_decode_table();
// True when float(c) / 255.0f (one IEEE float division) equals unorm8_decode_table()[c] (the
// double quotient rounded to float) for every code: SIMD kernels then decode and check 8-bit
// UNORM codes by a division instead of table gathers.
bool unorm8_decodes_by_division();
uint8_t linear_to_srgb8(float linear);

// IEEE 754 binary16: round to nearest even, subnormals kept, overflow -> signed Inf (IEEE
// rounding; Vulkan allows either Inf or the largest finite value), NaN stays NaN with the top
// payload bits kept (a payload that would vanish becomes the quiet bit).
uint16_t float_to_half_bits(float value);
float half_bits_to_float(uint16_t bits);
// half_bits_to_float of every code (65536 floats), for samplers that decode by table lookup.
const float* half_decode_table();
// Vulkan "Unsigned 11-Bit / 10-Bit Floating-Point Numbers": 5-bit exponent (bias 15), 6 or 5
// mantissa bits, no sign. Finite values round to the nearest representable finite value (ties
// to even), so finite overflow gives the largest finite value (65024 / 64512); negative values
// and -Inf give 0, +Inf gives Inf, NaN gives NaN (payload kept as for half).
uint32_t float_to_uf11_bits(float value);
uint32_t float_to_uf10_bits(float value);
float uf11_bits_to_float(uint32_t bits);
float uf10_bits_to_float(uint32_t bits);

}  // namespace ontile
