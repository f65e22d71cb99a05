// 2D textures with full mip chains and the sampler a fragment shader uses: nearest, bilinear
// and trilinear filtering, repeat/clamp/mirror wrapping, LOD from 2x2-quad derivatives, and
// each texture's place in the simulated address space the texture-cache model sees.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "raster/pixel_format.h"
#include "raster/texture_compression.h"

namespace ontile {

enum class WrapMode { Repeat, ClampToEdge, MirroredRepeat };
enum class FilterMode { Nearest, Linear };
enum class MipmapMode { None, Nearest, Linear };  // None: base level only

struct SamplerDesc {
  FilterMode mag_filter = FilterMode::Linear;
  FilterMode min_filter = FilterMode::Linear;
  MipmapMode mipmap_mode = MipmapMode::Linear;
  WrapMode wrap_u = WrapMode::Repeat;
  WrapMode wrap_v = WrapMode::Repeat;
  float lod_bias = 0.0f;
  friend bool operator==(const SamplerDesc&, const SamplerDesc&) = default;
};

// How texels are stored; sampling always returns linear float RGBA. SurfaceFormat: a render
// target's own bytes in its PixelFormat, decoded as Surface::read decodes them (view_of_surface).
enum class TexelEncoding { Unorm8, Srgb8, Float32, SurfaceFormat };

class Texture2D {
 public:
  ~Texture2D();
  Texture2D(const Texture2D&) = delete;
  Texture2D& operator=(const Texture2D&) = delete;
  // Builds the mip chain down to 1x1 (2x2 box filter in linear space; odd sizes floor, the
  // last row/column folded in: the last texel along an odd axis averages 3 texels, 1/3 each)
  // from base-level RGBA8 texels, row-major, top row first. Levels are re-encoded to 8 bits
  // with round to nearest (sRGB encode for srgb). Throws Error (naming `name`) on a bad size.
  // `compression` lays the levels out in that block format (see TextureCompression).
  static std::shared_ptr<const Texture2D> from_rgba8(int width, int height,
                                                     std::vector<uint8_t> rgba, bool srgb,
                                                     std::string name = {},
                                                     TextureCompression compression = TextureCompression::None);
  static std::shared_ptr<const Texture2D> from_rgba32f(int width, int height,
                                                       std::vector<float> rgba,
                                                       std::string name = {});
  // A render-target snapshot used as a texture: Float32 storage but `memory_bytes_per_texel`
  // bytes per texel in simulated memory (the target's real format, e.g. 4 for RGBA8), and a
  // single level (render targets have no mip chain, so every mip mode samples level 0).
  // Throws Error (naming `name`) on a bad size or memory_bytes_per_texel <= 0.
  static std::shared_ptr<const Texture2D> from_surface_texels(int width, int height,
                                                              std::vector<float> rgba,
                                                              int memory_bytes_per_texel,
                                                              std::string name);

  // A render target sampled in place, without a copy: `bytes` are the surface's pixels, row
  // after row, in `format` (single-sample). RGBA8 and sRGB8 surfaces become Unorm8 and Srgb8
  // textures over those bytes (their decode tables are the format's), every other format is
  // decoded per texel read with decode_pixel; a single level, addresses as from_surface_texels
  // gives them for bytes_per_pixel(format). The bytes must stay alive and unchanged while the
  // texture is sampled. Throws Error (naming `name`) on a bad size or a null `bytes`.
  static std::shared_ptr<const Texture2D> view_of_surface(int width, int height,
                                                          PixelFormat format,
                                                          const uint8_t* bytes, std::string name);

  // Whether a render target of `format` can be sampled in place at about the cost of a texture
  // (its stored texel is the value: RGBA8, sRGB8 and 32-bit float depth or red; RGBA16F, whose
  // channels decode by table lookup). Other packed formats (RGB10A2, ...) decode per texel
  // read, which bilinear footprints and PCF repeat up to 16 times per pixel, so the context
  // samples a decoded copy of those instead.
  static bool samples_in_place(PixelFormat format);
  // Texel `texel` (row-major index) of surface pixels in `format`: decode_pixel, with 32-bit
  // float depth and red read inline and RGBA16F through half_decode_table.
  static glm::vec4 load_surface_texel(PixelFormat format, const uint8_t* pixels, size_t texel) {
    if (format == PixelFormat::D32_FLOAT || format == PixelFormat::R32_FLOAT) {
      float value;
      std::memcpy(&value, pixels + texel * 4, sizeof value);
      return {value, 0.0f, 0.0f, 1.0f};
    }
    if (format == PixelFormat::RGBA16_FLOAT) {
      uint16_t code[4];  // host order, as the format's rows store them (pixel_format.cpp)
      std::memcpy(code, pixels + texel * 8, sizeof code);
      const float* table = half_decode_table();
      return {table[code[0]], table[code[1]], table[code[2]], table[code[3]]};
    }
    return decode_pixel(format, pixels + texel * bytes_per_pixel(format));
  }

  int width(int level = 0) const;
  int height(int level = 0) const;
  int level_count() const;
  TexelEncoding encoding() const;
  const std::string& name() const;
  // Bytes one texel occupies in memory (4 for 8-bit encodings, 16 for Float32, the format's
  // size for SurfaceFormat).
  int bytes_per_texel() const;

  // Simulated memory layout (for the texture-cache model): each texture owns the region
  // id << kTextureIdShift (ids in creation order), levels one after another inside it, and
  // reserves its size rounded up to 4 KiB. Sampling reports the byte address of every texel it
  // reads to the thread's texel trace (raster/texel_trace.h); the cache model places regions
  // at frame-local addresses in first-use order.
  static constexpr int kTextureIdShift = 40;
  static uint64_t reserved_bytes_of(uint64_t texture_id);
  // What a texture id names while the texture lives, so reports can attribute texture traffic
  // to its source: the texture's name, and whether it is a render target (a surface view or a
  // decoded render target) rather than a scene texture. Unknown ids give {"", false}.
  struct Identity {
    std::string name;
    bool render_target = false;
  };
  static Identity identity_of(uint64_t texture_id);
  uint64_t base_address() const;
  uint64_t level_offset_bytes(int level) const;  // prefix sum of the sizes of levels < level
  int memory_bytes_per_texel() const;            // the stored size: a surface's for snapshots
  TextureCompression compression() const;
  // Level::texel_byte_address of texel (x, y).
  uint64_t texel_address(int level, int x, int y) const;

  // One texel, decoded to linear float. x, y must be inside the level.
  glm::vec4 fetch(int level, int x, int y) const;

  // One level's texels for kernels that compute their own texel indices and report their own
  // texel trace (uncompressed textures only: `address` and `memory_bytes_per_texel` describe a
  // texel-per-texel layout, which render targets, the only textures those kernels read, have): load() decodes exactly as fetch() does, without its per-call format dispatch
  // and without tracing. Valid while the texture lives.
  struct TexelView {
    const float* texels32f = nullptr;     // Float32: RGBA floats, row-major; null otherwise
    const uint8_t* texels8 = nullptr;     // Unorm8/Srgb8: RGBA bytes, row-major
    const uint8_t* surface_bytes = nullptr;  // SurfaceFormat: pixels in surface_format
    PixelFormat surface_format = PixelFormat::RGBA8_UNORM;
    const float* rgb_decode = nullptr;    // 8-bit: byte -> linear float for R, G, B
    const float* alpha_decode = nullptr;  // 8-bit: byte -> float for A
    int width = 0, height = 0;
    uint64_t address = 0;                 // simulated byte address of texel (0, 0)
    uint64_t memory_bytes_per_texel = 0;

    glm::vec4 load(int x, int y) const {
      const size_t texel = static_cast<size_t>(y) * static_cast<size_t>(width) + x;
      if (texels32f) {
        const float* t = texels32f + texel * 4;
        return {t[0], t[1], t[2], t[3]};
      }
      if (surface_bytes) return load_surface_texel(surface_format, surface_bytes, texel);
      const uint8_t* t = texels8 + texel * 4;
      return {rgb_decode[t[0]], rgb_decode[t[1]], rgb_decode[t[2]], alpha_decode[t[3]]};
    }
  };
  TexelView texel_view(int level) const;  // defined in texel_view.cpp

  // Filtered sample at uv (0..1 spans the texture; v = 0 is the top row, as in glTF) and an
  // explicit level of detail (0 = base level; the sampler's lod_bias is added, as in GL/Vulkan).
  // Non-finite uv components are treated as 0 and a NaN lod as 0, so sampling never reads out
  // of bounds.
  glm::vec4 sample_lod(const SamplerDesc& sampler, glm::vec2 uv, float lod) const;
  // Samples the 4 lanes of a 2x2 quad (lane order: (0,0), (1,0), (0,1), (1,1)). The LOD comes
  // from the quad's uv derivatives as in the OpenGL 4.6 spec, section 8.14.1.
  // `fetches` > 1 stands for a shader that issues that many identical sample instructions (same
  // texture, sampler and uv, e.g. two material slots bound to one image): a GPU's texture unit
  // still reads the texels once per instruction, so the texel trace records every fetch, but the
  // filtered value, the same bits each time, is computed once.
  void sample_quad(const SamplerDesc& sampler, const glm::vec2 uv[4], glm::vec4 out[4],
                   int fetches = 1) const;
  // One texture read of sample_quads: the texture, its sampler, where fragment f's channel c
  // goes (out[c][f]), and sample_quad's `fetches` (identical sample instructions it stands for).
  struct QuadRead {
    const Texture2D* texture = nullptr;
    const SamplerDesc* sampler = nullptr;
    float* out[4] = {nullptr, nullptr, nullptr, nullptr};
    int fetches = 1;
  };
  // A shader's own texel trace of a quad, between the quads' texture reads: while sample_quads
  // traces, it calls append(context, q, out, last) after quad q's reads and before quad q + 1's;
  // append writes at most max_granules (<= kMaxGranules) granules to out in trace order, repeats
  // of `last` (the trace's last granule) removed, updates last and returns how many it wrote.
  // So a functor that reads other memory per quad (shadow-map taps) keeps the per-quad order.
  struct QuadTraceHook {
    static constexpr int kMaxGranules = 64;
    int (*append)(const void* context, int quad, uint64_t* out, uint64_t& last) = nullptr;
    const void* context = nullptr;
    int max_granules = 0;
  };
  // sample_quad for quads q < quad_count, whose lane i is fragment f = 4 q + i at (u[f], v[f]),
  // and per quad for each of `reads` in order: the values and the texel trace of calling
  // sample_quad(*read.sampler, uv, read.fetches) quad by quad and read by read, with the per-call dispatch
  // done once per batch (8-bit linear samplers run on SIMD lanes a batch per call); after_quad
  // (optional) traces after each quad's reads.
  static void sample_quads(const QuadRead* reads, int read_count, const float* u, const float* v,
                           int quad_count, const QuadTraceHook* after_quad = nullptr);

  struct Level {
    int width = 0, height = 0;
    std::vector<uint8_t> texels8;  // Unorm8/Srgb8 texels the texture owns
    std::vector<float> texels32f;  // Float32
    uint64_t address = 0;          // simulated byte address of texel (0, 0)
    uint32_t memory_bytes_per_texel = 4;
    // A surface view's pixels (view_of_surface): RGBA8 bytes for Unorm8/Srgb8 views, else
    // surface_format pixels; null when the level owns its texels.
    const uint8_t* surface_bytes = nullptr;
    PixelFormat surface_format = PixelFormat::RGBA8_UNORM;
    // The RGBA8 texels of an Unorm8/Srgb8 level, owned or viewed.
    const uint8_t* bytes8() const { return surface_bytes ? surface_bytes : texels8.data(); }
    // Block-compressed storage (TextureCompression): bytes per block (0: uncompressed), block
    // size as shifts (4x4: 2, 8x8: 3) and blocks per row, blocks stored row-major.
    uint32_t block_bytes = 0;
    uint32_t blocks_per_row = 0;
    int block_width_shift = 0, block_height_shift = 0;
    // The simulated byte address the texture cache sees for texel `texel` (row-major index):
    // the texel's own bytes, or the start of the block holding it.
    uint64_t texel_byte_address(size_t texel) const {
      if (block_bytes == 0) return address + texel * memory_bytes_per_texel;
      const size_t y = texel / static_cast<size_t>(width);
      const size_t x = texel - y * static_cast<size_t>(width);
      return address + ((y >> block_height_shift) * blocks_per_row + (x >> block_width_shift)) * block_bytes;
    }
  };

 private:
  Texture2D() = default;
  std::vector<Level> levels_;
  bool render_target_ = false;
  TexelEncoding encoding_ = TexelEncoding::Unorm8;
  TextureCompression compression_ = TextureCompression::None;
  bool etc2_alpha_ = false;  // Etc2 with a texel whose alpha is below 255: 16-byte blocks
  std::string name_;
  uint64_t base_address_ = 0;

  // Gives the levels their addresses (laid out in compression_'s blocks): reserves this
  // texture's range of the address space.
  void assign_addresses(int memory_bytes_per_texel);
};

}  // namespace ontile
