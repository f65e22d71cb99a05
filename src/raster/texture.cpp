// Texture2D and its sampler (OpenGL 4.6 sections 8.14-8.15, Vulkan "Texel Filtering" /
// "Wrapping Operation"); the mip chain is built in texture_mips.cpp. Sampling is on the
// per-fragment hot path: no allocation, encoding dispatched once per call, every texel read
// reported to the texel trace.
#include "raster/texture.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <cmath>
#include <cstddef>

#include "raster/pixel_format.h"
#include "raster/texel_trace.h"
#include "raster/texture_mips.h"
#include "raster/texture_quad_simd.h"
#include "raster/texel_wrap.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr int kChannels = 4;
// Beyond 2^24 every float is an integer, so reducing texel coordinates there (exact fmod, or a
// clamp for ClampToEdge) keeps the selected texel and keeps indices far from int overflow.
constexpr float kMaxExactTexelCoord = 16777216.0f;
// Textures start on 4 KiB boundaries of the simulated address space (a page, as allocators do).
constexpr uint64_t kTextureAlignmentBytes = 4096;
// Each texture is a region of its own, texture id << kTextureIdShift; the texture-cache model
// maps regions to frame-local addresses in first-use order (texture_cache.cpp), so counts do
// not depend on when or in which order textures were created.
std::atomic<uint64_t> next_texture_id{1};
std::mutex reserved_bytes_mutex;
std::vector<uint64_t> reserved_bytes_by_id{0};  // index = texture id
std::map<uint64_t, Texture2D::Identity> identities_by_id;  // living textures only

// Per-channel decode tables for 8-bit texels (unused for Float32), and whether a texel trace
// is active on this thread: looked up once per sampling call, since a thread_local read on
// every texel measurably slows sampling when nothing is traced.
struct TexelDecoder {
  const float* rgb = nullptr;
  const float* alpha = nullptr;
  bool trace = false;
};

TexelDecoder decoder_for(TexelEncoding encoding) {
  const float* unorm = unorm8_decode_table().data();
  const bool trace = texel_trace_detail::sink != nullptr;
  if (encoding == TexelEncoding::Srgb8) return {srgb8_decode_table().data(), unorm, trace};
  return {unorm, unorm, trace};
}

// Non-finite coordinates are treated as 0 so that NaN/Inf uv can never index out of bounds.
inline float finite_or_zero(float x) { return std::isfinite(x) ? x : 0.0f; }

// Where a level's texels live, a template parameter so each sampler loop loads one way.
enum class Storage { Bytes8, Float32, SurfaceFormat };

Storage storage_of(TexelEncoding encoding) {
  if (encoding == TexelEncoding::Float32) return Storage::Float32;
  if (encoding == TexelEncoding::SurfaceFormat) return Storage::SurfaceFormat;
  return Storage::Bytes8;
}

template <Storage kStorage>
inline glm::vec4 load_texel(const Texture2D::Level& level, const TexelDecoder& decoder, int x,
                            int y) {
  const size_t texel = static_cast<size_t>(y) * level.width + x;
  if (decoder.trace) record_texel_address(level.texel_byte_address(texel));
  if constexpr (kStorage == Storage::Float32) {
    const float* p = level.texels32f.data() + texel * kChannels;
    return {p[0], p[1], p[2], p[3]};
  } else if constexpr (kStorage == Storage::SurfaceFormat) {
    return Texture2D::load_surface_texel(level.surface_format, level.surface_bytes, texel);
  } else {
    const uint8_t* p = level.bytes8() + texel * kChannels;
    return {decoder.rgb[p[0]], decoder.rgb[p[1]], decoder.rgb[p[2]], decoder.alpha[p[3]]};
  }
}

// Texel-space coordinate u * size - offset, kept small enough for int conversion without
// changing the texel the wrap mode selects (see kMaxExactTexelCoord). A normalized |u| >= 2^24
// is an even integer, which Repeat and MirroredRepeat map like 0.
inline float texel_coord(float u, int size, WrapMode mode, float offset) {
  if (!(std::fabs(u) < kMaxExactTexelCoord)) {
    u = mode == WrapMode::ClampToEdge ? std::copysign(kMaxExactTexelCoord, u) : 0.0f;
  }
  const float x = u * static_cast<float>(size) - offset;
  if (std::fabs(x) < kMaxExactTexelCoord) return x;
  if (mode == WrapMode::ClampToEdge) return std::copysign(kMaxExactTexelCoord, x);
  return std::fmod(x, static_cast<float>(mode == WrapMode::Repeat ? size : 2 * size));
}

// One filtered sample of one level; uv must be finite.
template <Storage kStorage>
glm::vec4 sample_level(const Texture2D::Level& level, const TexelDecoder& decoder,
                       const SamplerDesc& sampler, FilterMode filter, glm::vec2 uv) {
  const int w = level.width, h = level.height;
  if (filter == FilterMode::Nearest) {
    // i = floor(u * size) (OpenGL 4.6 eq. 8.9, Vulkan "Unnormalized Texel Coordinate Operations")
    const float x = texel_coord(uv.x, w, sampler.wrap_u, 0.0f);
    const float y = texel_coord(uv.y, h, sampler.wrap_v, 0.0f);
    const int i = wrap_texel_index(static_cast<int>(std::floor(x)), w, sampler.wrap_u);
    const int j = wrap_texel_index(static_cast<int>(std::floor(y)), h, sampler.wrap_v);
    return load_texel<kStorage>(level, decoder, i, j);
  }
  // Bilinear: i0 = floor(u * size - 0.5), alpha = frac(u * size - 0.5) (OpenGL 4.6 eq. 8.10).
  const float x = texel_coord(uv.x, w, sampler.wrap_u, 0.5f);
  const float y = texel_coord(uv.y, h, sampler.wrap_v, 0.5f);
  const float x_floor = std::floor(x), y_floor = std::floor(y);
  const float a = x - x_floor, b = y - y_floor;
  const int i0 = static_cast<int>(x_floor), j0 = static_cast<int>(y_floor);
  const int xa = wrap_texel_index(i0, w, sampler.wrap_u);
  const int xb = wrap_texel_index(i0 + 1, w, sampler.wrap_u);
  const int ya = wrap_texel_index(j0, h, sampler.wrap_v);
  const int yb = wrap_texel_index(j0 + 1, h, sampler.wrap_v);
  // Loads in separate statements so the texel trace sees a fixed order (operand evaluation
  // order inside one expression is unspecified). p * (1 - t) + q * t (not p + (q - p) * t):
  // exact at t = 0 and a correctly rounded mean at t = 0.5.
  const glm::vec4 t00 = load_texel<kStorage>(level, decoder, xa, ya);
  const glm::vec4 t10 = load_texel<kStorage>(level, decoder, xb, ya);
  const glm::vec4 t01 = load_texel<kStorage>(level, decoder, xa, yb);
  const glm::vec4 t11 = load_texel<kStorage>(level, decoder, xb, yb);
  const glm::vec4 top = t00 * (1.0f - a) + t10 * a;
  const glm::vec4 bottom = t01 * (1.0f - a) + t11 * a;
  return top * (1.0f - b) + bottom * b;
}

// Filter and level selection for a level of detail lambda (bias already added), OpenGL 4.6
// section 8.14.2-8.14.3: lambda is clamped to [0, levels - 1]; lambda <= 0 magnifies.
template <Storage kStorage>
glm::vec4 sample_with_lambda(const std::vector<Texture2D::Level>& levels,
                             const TexelDecoder& decoder, const SamplerDesc& sampler, glm::vec2 uv,
                             float lambda) {
  const float max_level = static_cast<float>(levels.size() - 1);
  if (!(lambda > 0.0f)) {  // also NaN
    return sample_level<kStorage>(levels[0], decoder, sampler, sampler.mag_filter, uv);
  }
  lambda = std::min(lambda, max_level);
  const FilterMode filter = sampler.min_filter;
  switch (sampler.mipmap_mode) {
    case MipmapMode::None:
      return sample_level<kStorage>(levels[0], decoder, sampler, filter, uv);
    case MipmapMode::Nearest: {
      // d = ceil(lambda + 1/2) - 1 for lambda > 1/2, else the base level (eq. 8.19).
      const int d = lambda <= 0.5f ? 0 : static_cast<int>(std::ceil(lambda + 0.5f)) - 1;
      return sample_level<kStorage>(levels[d], decoder, sampler, filter, uv);
    }
    case MipmapMode::Linear: {
      // Trilinear: blend levels floor(lambda) and floor(lambda) + 1 by frac(lambda) (eq. 8.20).
      const float d1_float = std::floor(lambda);
      const int d1 = static_cast<int>(d1_float);
      const float blend = lambda - d1_float;
      const glm::vec4 s1 = sample_level<kStorage>(levels[d1], decoder, sampler, filter, uv);
      if (blend == 0.0f) return s1;
      const glm::vec4 s2 = sample_level<kStorage>(levels[d1 + 1], decoder, sampler, filter, uv);
      return s1 * (1.0f - blend) + s2 * blend;
    }
  }
  return sample_level<kStorage>(levels[0], decoder, sampler, filter, uv);
}

// Scale factor rho of OpenGL 4.6 eq. 8.7 from the quad's finite-differenced uv, in texels of
// level 0: rho = max(|d(uv)/dx|, |d(uv)/dy|).
float quad_lambda(const glm::vec2 uv[4], int width, int height, float lod_bias) {
  const glm::vec2 size(static_cast<float>(width), static_cast<float>(height));
  const glm::vec2 d_dx = (uv[1] - uv[0]) * size;
  const glm::vec2 d_dy = (uv[2] - uv[0]) * size;
  const float rho = std::max(std::sqrt(d_dx.x * d_dx.x + d_dx.y * d_dx.y),
                             std::sqrt(d_dy.x * d_dy.x + d_dy.y * d_dy.y));
  return std::log2(rho) + lod_bias;  // rho = 0 -> -inf -> magnification
}

// The hot path of textured shading: bilinear (and trilinear) filtering of an 8-bit level for
// the 4 lanes of a quad. Same arithmetic, same texel order and same trace as sample_level
// (tested bit for bit), with the texel trace kept in locals and the in-range wrap case first.
class Linear8Sampler {
 public:
  Linear8Sampler(const TexelDecoder& decoder, const SamplerDesc& sampler)
      : rgb_(decoder.rgb), alpha_(decoder.alpha), sampler_(sampler),
        sink_(decoder.trace ? texel_trace_detail::sink : nullptr),
        last_(texel_trace_detail::last_granule) {}
  ~Linear8Sampler() { texel_trace_detail::last_granule = last_; }

  glm::vec4 sample(const Texture2D::Level& level, glm::vec2 uv) {
    const int w = level.width, h = level.height;
    const float x = texel_coord(uv.x, w, sampler_.wrap_u, 0.5f);
    const float y = texel_coord(uv.y, h, sampler_.wrap_v, 0.5f);
    const float x_floor = std::floor(x), y_floor = std::floor(y);
    const float a = x - x_floor, b = y - y_floor;
    const int i0 = static_cast<int>(x_floor), j0 = static_cast<int>(y_floor);
    size_t taps[4];
    bilinear_footprint(i0, j0, w, h, sampler_.wrap_u, sampler_.wrap_v, taps);
    const glm::vec4 t00 = load(level, taps[0]);
    const glm::vec4 t10 = load(level, taps[1]);
    const glm::vec4 t01 = load(level, taps[2]);
    const glm::vec4 t11 = load(level, taps[3]);
    const glm::vec4 top = t00 * (1.0f - a) + t10 * a;
    const glm::vec4 bottom = t01 * (1.0f - a) + t11 * a;
    return top * (1.0f - b) + bottom * b;
  }

 private:
  glm::vec4 load(const Texture2D::Level& level, size_t texel) {
    if (sink_) {
      const uint64_t granule = level.texel_byte_address(texel) >> 6;
      if (granule != last_) {
        sink_->push_back(granule);
        last_ = granule;
      }
    }
    const uint8_t* p = level.bytes8() + texel * kChannels;
    return {rgb_[p[0]], rgb_[p[1]], rgb_[p[2]], alpha_[p[3]]};
  }

  const float* rgb_;
  const float* alpha_;
  const SamplerDesc& sampler_;
  std::vector<uint64_t>* sink_;
  uint64_t last_;
};

// The SIMD job of sample_with_lambda for an 8-bit texture whose filters are all Linear (the
// common sampler) at level of detail lambda: the level (or the two levels and their blend).
inline void linear8_job(const std::vector<Texture2D::Level>& levels, const TexelDecoder& decoder,
                        const SamplerDesc& sampler, const glm::vec2 uv[4], float lambda, int fetches,
                        QuadSample8& simd) {
  simd.uv = uv;
  simd.wrap_u = sampler.wrap_u;
  simd.wrap_v = sampler.wrap_v;
  simd.rgb_decode = decoder.rgb;
  simd.alpha_decode = decoder.alpha;
  simd.trace = decoder.trace ? texel_trace_detail::sink : nullptr;
  simd.last_granule = &texel_trace_detail::last_granule;
  simd.trace_repeats = fetches;
  const float max_level = static_cast<float>(levels.size() - 1);
  const bool base_only = !(lambda > 0.0f) || sampler.mipmap_mode == MipmapMode::None;
  if (!base_only) lambda = std::min(lambda, max_level);
  if (base_only) {
    simd.levels[0] = &levels[0];
  } else if (sampler.mipmap_mode == MipmapMode::Nearest) {
    const int single_level = lambda <= 0.5f ? 0 : static_cast<int>(std::ceil(lambda + 0.5f)) - 1;
    simd.levels[0] = &levels[single_level];
  } else {
    const float d1_float = std::floor(lambda);
    const float blend = lambda - d1_float;
    simd.levels[0] = &levels[static_cast<int>(d1_float)];
    if (blend != 0.0f) {
      simd.levels[1] = &levels[static_cast<int>(d1_float) + 1];
      simd.level_count = 2;
      simd.blend = blend;
    }
  }
}

// The general path of a job (rare: huge coordinates), sample_with_lambda's filters lane by lane;
// it samples once per fetch, so each is traced.
void sample_linear8_scalar(const QuadSample8& job, const TexelDecoder& decoder,
                           const SamplerDesc& sampler, glm::vec4 out[4]) {
  Linear8Sampler s(decoder, sampler);
  for (int fetch = 0; fetch < job.trace_repeats; ++fetch) {
    for (int lane = 0; lane < 4; ++lane) {
      const glm::vec4 s1 = s.sample(*job.levels[0], job.uv[lane]);
      if (job.level_count == 1) {
        out[lane] = s1;
        continue;
      }
      const glm::vec4 s2 = s.sample(*job.levels[1], job.uv[lane]);
      out[lane] = s1 * (1.0f - job.blend) + s2 * job.blend;
    }
  }
}

// sample_with_lambda for 8-bit textures whose filters are all Linear. Quads run on SIMD lanes
// (texture_quad_simd.h, the same bits); coordinates beyond 2^24 texels take the scalar path.
void sample_quad_linear8(const std::vector<Texture2D::Level>& levels, const TexelDecoder& decoder,
                         const SamplerDesc& sampler, const glm::vec2 uv[4], float lambda,
                         int fetches, glm::vec4 out[4]) {
  QuadSample8 job;
  linear8_job(levels, decoder, sampler, uv, lambda, fetches, job);
  if (sample_quad8_simd(job, out)) return;
  sample_linear8_scalar(job, decoder, sampler, out);
}

template <Storage kStorage>
void sample_quad_lanes(const std::vector<Texture2D::Level>& levels, const TexelDecoder& decoder,
                       const SamplerDesc& sampler, const glm::vec2 uv[4], int fetches,
                       glm::vec4 out[4]) {
  glm::vec2 finite_uv[4];
  for (int lane = 0; lane < 4; ++lane) {
    finite_uv[lane] = {finite_or_zero(uv[lane].x), finite_or_zero(uv[lane].y)};
  }
  if ((kStorage != Storage::Bytes8 || sampler.mag_filter == FilterMode::Nearest) &&
      sampler.mag_filter == sampler.min_filter &&
      (sampler.mipmap_mode == MipmapMode::None || levels.size() == 1)) {
    // One filter and one level (render targets, nearest copies): sample_with_lambda reads level
    // 0 with that filter whatever lambda is (a positive lambda clamps to the last level, 0, and
    // selects it with blend 0), so the derivatives and log2 are skipped.
    for (int fetch = 0; fetch < fetches; ++fetch) {
      for (int lane = 0; lane < 4; ++lane) {
        out[lane] = sample_level<kStorage>(levels[0], decoder, sampler, sampler.mag_filter,
                                           finite_uv[lane]);
      }
    }
    return;
  }
  const float lambda = quad_lambda(finite_uv, levels[0].width, levels[0].height, sampler.lod_bias);
  if constexpr (kStorage == Storage::Bytes8) {
    if (sampler.mag_filter == FilterMode::Linear && sampler.min_filter == FilterMode::Linear) {
      sample_quad_linear8(levels, decoder, sampler, finite_uv, lambda, fetches, out);
      return;
    }
  }
  for (int fetch = 0; fetch < fetches; ++fetch) {
    for (int lane = 0; lane < 4; ++lane) {
      out[lane] = sample_with_lambda<kStorage>(levels, decoder, sampler, finite_uv[lane], lambda);
    }
  }
}

void check_size(int width, int height, size_t values, const std::string& name) {
  const std::string label = "texture '" + name + "'";
  if (width <= 0 || height <= 0) {
    throw Error(label + ": invalid size " + std::to_string(width) + "x" + std::to_string(height));
  }
  const size_t expected = static_cast<size_t>(width) * height * kChannels;
  if (values != expected) {
    throw Error(label + ": " + std::to_string(values) + " texel values for " +
                std::to_string(width) + "x" + std::to_string(height) + " RGBA (expected " +
                std::to_string(expected) + ")");
  }
}

}  // namespace

std::shared_ptr<const Texture2D> Texture2D::from_rgba8(int width, int height,
                                                       std::vector<uint8_t> rgba, bool srgb,
                                                       std::string name,
                                                       TextureCompression compression) {
  check_size(width, height, rgba.size(), name);
  std::shared_ptr<Texture2D> texture(new Texture2D());
  texture->encoding_ = srgb ? TexelEncoding::Srgb8 : TexelEncoding::Unorm8;
  texture->compression_ = compression;
  texture->name_ = std::move(name);
  texture->etc2_alpha_ = compression == TextureCompression::Etc2 && has_translucent_texel(rgba);
  Level base;
  base.width = width;
  base.height = height;
  base.texels8 = std::move(rgba);
  texture->levels_ = build_mip_chain(std::move(base), texture->encoding_);
  texture->assign_addresses(texture->bytes_per_texel());
  return texture;
}

std::shared_ptr<const Texture2D> Texture2D::from_rgba32f(int width, int height,
                                                         std::vector<float> rgba,
                                                         std::string name) {
  check_size(width, height, rgba.size(), name);
  std::shared_ptr<Texture2D> texture(new Texture2D());
  texture->encoding_ = TexelEncoding::Float32;
  texture->name_ = std::move(name);
  Level base;
  base.width = width;
  base.height = height;
  base.texels32f = std::move(rgba);
  texture->levels_ = build_mip_chain(std::move(base), texture->encoding_);
  texture->assign_addresses(texture->bytes_per_texel());
  return texture;
}

std::shared_ptr<const Texture2D> Texture2D::from_surface_texels(int width, int height,
                                                                std::vector<float> rgba,
                                                                int memory_bytes_per_texel,
                                                                std::string name) {
  check_size(width, height, rgba.size(), name);
  if (memory_bytes_per_texel <= 0) {
    throw Error("texture '" + name + "': invalid memory_bytes_per_texel " +
                std::to_string(memory_bytes_per_texel));
  }
  std::shared_ptr<Texture2D> texture(new Texture2D());
  texture->encoding_ = TexelEncoding::Float32;
  texture->name_ = std::move(name);
  texture->levels_.push_back(Level{width, height, {}, std::move(rgba)});
  texture->render_target_ = true;
  texture->assign_addresses(memory_bytes_per_texel);
  return texture;
}

std::shared_ptr<const Texture2D> Texture2D::view_of_surface(int width, int height,
                                                            PixelFormat format,
                                                            const uint8_t* bytes,
                                                            std::string name) {
  if (width <= 0 || height <= 0 || bytes == nullptr) {
    throw Error("texture '" + name + "': invalid surface view " + std::to_string(width) + "x" +
                std::to_string(height) + (bytes ? "" : " without pixels"));
  }
  std::shared_ptr<Texture2D> texture(new Texture2D());
  // RGBA8 pixels are the 8-bit encodings' texels, decoded with the same tables
  // (pixel_format.cpp), so those views take the 8-bit sampling paths.
  texture->encoding_ = format == PixelFormat::RGBA8_SRGB    ? TexelEncoding::Srgb8
                       : format == PixelFormat::RGBA8_UNORM ? TexelEncoding::Unorm8
                                                            : TexelEncoding::SurfaceFormat;
  texture->name_ = std::move(name);
  Level level;
  level.width = width;
  level.height = height;
  level.surface_bytes = bytes;
  level.surface_format = format;
  texture->levels_.push_back(std::move(level));
  texture->render_target_ = true;
  texture->assign_addresses(bytes_per_pixel(format));
  return texture;
}

void Texture2D::assign_addresses(int memory_bytes_per_texel) {
  const BlockFormat block = block_format(compression_, etc2_alpha_);
  uint64_t size_bytes = 0;
  for (Level& level : levels_) {
    level.address = size_bytes;  // offset for now; the base is added once reserved
    level.memory_bytes_per_texel = static_cast<uint32_t>(memory_bytes_per_texel);
    if (block.bytes == 0) {
      size_bytes += static_cast<uint64_t>(level.width) * level.height * memory_bytes_per_texel;
      continue;
    }
    // Partial blocks at the right and bottom edges (and levels smaller than a block) take a
    // whole block, as in every block format.
    const int side_x = 1 << block.width_shift, side_y = 1 << block.height_shift;
    level.block_bytes = block.bytes;
    level.block_width_shift = block.width_shift;
    level.block_height_shift = block.height_shift;
    level.blocks_per_row = static_cast<uint32_t>((level.width + side_x - 1) / side_x);
    const uint64_t block_rows = static_cast<uint64_t>((level.height + side_y - 1) / side_y);
    size_bytes += uint64_t{level.blocks_per_row} * block_rows * block.bytes;
  }
  const uint64_t reserved_bytes =
      (size_bytes + kTextureAlignmentBytes - 1) / kTextureAlignmentBytes * kTextureAlignmentBytes;
  const uint64_t id = next_texture_id.fetch_add(1);
  {
    const std::lock_guard<std::mutex> lock(reserved_bytes_mutex);
    if (reserved_bytes_by_id.size() <= id) reserved_bytes_by_id.resize(id + 1, 0);
    reserved_bytes_by_id[id] = reserved_bytes;
    identities_by_id[id] = Identity{name_, render_target_};
  }
  base_address_ = id << kTextureIdShift;
  for (Level& level : levels_) level.address += base_address_;
}

Texture2D::~Texture2D() {
  if (base_address_ == 0) return;  // construction failed before an id was reserved
  const std::lock_guard<std::mutex> lock(reserved_bytes_mutex);
  identities_by_id.erase(base_address_ >> kTextureIdShift);
}

Texture2D::Identity Texture2D::identity_of(uint64_t texture_id) {
  const std::lock_guard<std::mutex> lock(reserved_bytes_mutex);
  const auto found = identities_by_id.find(texture_id);
  return found == identities_by_id.end() ? Identity{} : found->second;
}

uint64_t Texture2D::reserved_bytes_of(uint64_t texture_id) {
  const std::lock_guard<std::mutex> lock(reserved_bytes_mutex);
  return texture_id < reserved_bytes_by_id.size() ? reserved_bytes_by_id[texture_id] : 0;
}

int Texture2D::width(int level) const { return levels_[level].width; }
int Texture2D::height(int level) const { return levels_[level].height; }
int Texture2D::level_count() const { return static_cast<int>(levels_.size()); }
TexelEncoding Texture2D::encoding() const { return encoding_; }
const std::string& Texture2D::name() const { return name_; }
int Texture2D::bytes_per_texel() const {
  if (encoding_ == TexelEncoding::SurfaceFormat) return bytes_per_pixel(levels_[0].surface_format);
  return encoding_ == TexelEncoding::Float32 ? 4 * static_cast<int>(sizeof(float)) : 4;
}

uint64_t Texture2D::base_address() const { return base_address_; }
uint64_t Texture2D::level_offset_bytes(int level) const {
  return levels_[level].address - base_address_;
}
int Texture2D::memory_bytes_per_texel() const {
  return static_cast<int>(levels_[0].memory_bytes_per_texel);
}
TextureCompression Texture2D::compression() const { return compression_; }
uint64_t Texture2D::texel_address(int level, int x, int y) const {
  const Level& l = levels_[level];
  return l.texel_byte_address(static_cast<size_t>(y) * static_cast<size_t>(l.width) + static_cast<size_t>(x));
}

glm::vec4 Texture2D::fetch(int level, int x, int y) const {
  // Shaders fetch texel by texel (shadow-map PCF, G-buffer reads): only 8-bit texels need the
  // decode tables, so the others skip looking them up.
  const Level& l = levels_[level];
  const TexelDecoder untabled{nullptr, nullptr, texel_trace_detail::sink != nullptr};
  switch (storage_of(encoding_)) {
    case Storage::Float32: return load_texel<Storage::Float32>(l, untabled, x, y);
    case Storage::SurfaceFormat: return load_texel<Storage::SurfaceFormat>(l, untabled, x, y);
    case Storage::Bytes8: break;
  }
  return load_texel<Storage::Bytes8>(l, decoder_for(encoding_), x, y);
}

bool Texture2D::samples_in_place(PixelFormat format) {
  return format == PixelFormat::RGBA8_UNORM || format == PixelFormat::RGBA8_SRGB ||
         format == PixelFormat::D32_FLOAT || format == PixelFormat::R32_FLOAT ||
         format == PixelFormat::RGBA16_FLOAT;
}

glm::vec4 Texture2D::sample_lod(const SamplerDesc& sampler, glm::vec2 uv, float lod) const {
  const glm::vec2 finite_uv(finite_or_zero(uv.x), finite_or_zero(uv.y));
  // The sampler's bias applies to explicit LODs too (OpenGL 4.6 eq. 8.6, Vulkan "LOD
  // Operation"); a NaN LOD selects the base level.
  const float lambda = lod + sampler.lod_bias;
  const TexelDecoder decoder = decoder_for(encoding_);
  switch (storage_of(encoding_)) {
    case Storage::Float32:
      return sample_with_lambda<Storage::Float32>(levels_, decoder, sampler, finite_uv, lambda);
    case Storage::SurfaceFormat:
      return sample_with_lambda<Storage::SurfaceFormat>(levels_, decoder, sampler, finite_uv,
                                                        lambda);
    case Storage::Bytes8: break;
  }
  return sample_with_lambda<Storage::Bytes8>(levels_, decoder, sampler, finite_uv, lambda);
}

void Texture2D::sample_quad(const SamplerDesc& sampler, const glm::vec2 uv[4],
                            glm::vec4 out[4], int fetches) const {
  const TexelDecoder decoder = decoder_for(encoding_);
  fetches = std::max(fetches, 1);
  switch (storage_of(encoding_)) {
    case Storage::Float32:
      sample_quad_lanes<Storage::Float32>(levels_, decoder, sampler, uv, fetches, out);
      return;
    case Storage::SurfaceFormat:
      sample_quad_lanes<Storage::SurfaceFormat>(levels_, decoder, sampler, uv, fetches, out);
      return;
    case Storage::Bytes8: break;
  }
  sample_quad_lanes<Storage::Bytes8>(levels_, decoder, sampler, uv, fetches, out);
}

namespace {
// A QuadTraceHook's granules of quad q appended to the thread's trace (the paths of sample_quads
// that trace quad by quad).
void trace_after_quad(const Texture2D::QuadTraceHook* hook, int q) {
  std::vector<uint64_t>* const sink = texel_trace_detail::sink;
  if (!hook || !sink) return;
  uint64_t granules[Texture2D::QuadTraceHook::kMaxGranules];
  const int count = hook->append(hook->context, q, granules, texel_trace_detail::last_granule);
  sink->insert(sink->end(), granules, granules + count);
}
}  // namespace

void Texture2D::sample_quads(const QuadRead* reads, int read_count, const float* u,
                             const float* v, int quad_count, const QuadTraceHook* after_quad) {
  // 8-bit reads with Linear filters (the common sampler) run in one dispatch per batch; a batch
  // with any other read samples quad by quad and read by read through sample_quad.
  if (read_count <= 0 || quad_count <= 0) return;
  BatchRead8 batch_reads[QuadBatch8::kMaxReads];
  TexelDecoder decoders[QuadBatch8::kMaxReads];
  bool all_linear8 = read_count <= QuadBatch8::kMaxReads;
  for (int r = 0; r < read_count && all_linear8; ++r) {
    const Texture2D& t = *reads[r].texture;
    const SamplerDesc& sampler = *reads[r].sampler;
    all_linear8 = storage_of(t.encoding_) == Storage::Bytes8 &&
                  sampler.mag_filter == FilterMode::Linear && sampler.min_filter == FilterMode::Linear;
    decoders[r] = decoder_for(t.encoding_);
    BatchRead8& read = batch_reads[r];
    read.levels = t.levels_.data();
    read.max_level = static_cast<float>(t.levels_.size() - 1);
    read.mipmap_mode = sampler.mipmap_mode;
    read.lod_bias = sampler.lod_bias;
    read.wrap_u = sampler.wrap_u;
    read.wrap_v = sampler.wrap_v;
    read.rgb_decode = decoders[r].rgb;
    read.alpha_decode = decoders[r].alpha;
    read.trace_repeats = std::max(reads[r].fetches, 1);
    for (int c = 0; c < 4; ++c) read.out[c] = reads[r].out[c];
  }
  if (!all_linear8) {
    for (int q = 0; q < quad_count; ++q) {
      const int f0 = q * 4;
      const glm::vec2 uv[4] = {{u[f0], v[f0]}, {u[f0 + 1], v[f0 + 1]}, {u[f0 + 2], v[f0 + 2]},
                               {u[f0 + 3], v[f0 + 3]}};
      for (int r = 0; r < read_count; ++r) {
        glm::vec4 texel[4];
        reads[r].texture->sample_quad(*reads[r].sampler, uv, texel, reads[r].fetches);
        for (int lane = 0; lane < 4; ++lane) {
          for (int c = 0; c < 4; ++c) reads[r].out[c][f0 + lane] = texel[lane][c];
        }
      }
      trace_after_quad(after_quad, q);
    }
    return;
  }
  QuadBatch8 batch;
  batch.reads = batch_reads;
  batch.read_count = read_count;
  batch.u = u;
  batch.v = v;
  batch.quad_count = quad_count;
  batch.trace = texel_trace_detail::sink;
  batch.last_granule = &texel_trace_detail::last_granule;
  batch.after_quad = after_quad;
  const int end = quad_count * read_count;
  for (int position = sample_quad_batch8_simd(batch, 0); position < end;
       position = sample_quad_batch8_simd(batch, position + 1)) {
    // The general path (rare: huge coordinates) for job (quad q, read r), as sample_quad runs it.
    const int q = position / read_count, r = position % read_count, f0 = q * 4;
    glm::vec2 finite_uv[4];
    for (int lane = 0; lane < 4; ++lane) {
      finite_uv[lane] = {finite_or_zero(u[f0 + lane]), finite_or_zero(v[f0 + lane])};
    }
    const SamplerDesc& sampler = *reads[r].sampler;
    const std::vector<Level>& levels = reads[r].texture->levels_;
    const float lambda = quad_lambda(finite_uv, levels[0].width, levels[0].height, sampler.lod_bias);
    QuadSample8 job;
    linear8_job(levels, decoders[r], sampler, finite_uv, lambda, batch_reads[r].trace_repeats, job);
    glm::vec4 texel[4];
    sample_linear8_scalar(job, decoders[r], sampler, texel);
    for (int lane = 0; lane < 4; ++lane) {
      for (int c = 0; c < 4; ++c) reads[r].out[c][f0 + lane] = texel[lane][c];
    }
    // The kernel goes on at the next job: after a quad's last read, its hook runs here.
    if (r == read_count - 1) trace_after_quad(after_quad, q);
  }
}

}  // namespace ontile
