// Bilinear / trilinear filtering of an 8-bit texture for the 4 lanes of a quad on SIMD lanes
// (Highway, runtime dispatch): the hot path of textured shading. Same arithmetic, same texel
// order and same texel trace as the scalar sampler in texture.cpp, so results are bit-identical.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "raster/texture.h"

namespace ontile {

struct QuadSample8 {
  const Texture2D::Level* levels[2] = {nullptr, nullptr};  // one level, or two to blend
  int level_count = 1;
  float blend = 0.0f;             // weight of levels[1] (trilinear)
  const glm::vec2* uv = nullptr;  // 4 finite coordinates
  WrapMode wrap_u = WrapMode::Repeat, wrap_v = WrapMode::Repeat;
  const float* rgb_decode = nullptr;    // 256-entry tables (sRGB or UNORM)
  const float* alpha_decode = nullptr;
  std::vector<uint64_t>* trace = nullptr;  // texel trace sink, or null
  uint64_t* last_granule = nullptr;        // the trace's last granule (updated)
  int trace_repeats = 1;                   // identical fetches the trace records (>= 1)
};

// Returns false, touching nothing, when a lane needs the general path (coordinates beyond 2^24
// texels, or a level of 2^31 texels or more); the caller then samples the quad with the scalar
// code.
bool sample_quad8_simd(const QuadSample8& in, glm::vec4 out[4]);

// One 8-bit texture read with Linear filters of a QuadBatch8: its levels, sampler and decode
// tables, and where fragment f's channel c goes (out[c][f]).
struct BatchRead8 {
  const Texture2D::Level* levels = nullptr;
  float max_level = 0.0f;  // level count - 1
  MipmapMode mipmap_mode = MipmapMode::Linear;
  float lod_bias = 0.0f;
  WrapMode wrap_u = WrapMode::Repeat, wrap_v = WrapMode::Repeat;
  const float* rgb_decode = nullptr;
  const float* alpha_decode = nullptr;
  float* out[4] = {nullptr, nullptr, nullptr, nullptr};
  int trace_repeats = 1;  // identical fetches the trace records (>= 1), as QuadSample8's
};

// Texture2D::sample_quads for reads that are all BatchRead8: quad q's lane i is fragment
// f = 4 q + i at (u[f], v[f]), not yet made finite.
struct QuadBatch8 {
  static constexpr int kMaxReads = 4;
  const BatchRead8* reads = nullptr;
  int read_count = 0;
  const float* u = nullptr;
  const float* v = nullptr;
  int quad_count = 0;
  std::vector<uint64_t>* trace = nullptr;  // texel trace sink, or null
  uint64_t* last_granule = nullptr;
  const Texture2D::QuadTraceHook* after_quad = nullptr;  // traced after each quad's reads, or null
};

// Samples the batch's jobs (quad q, read r), position q * read_count + r, from `first` on in
// that order, with one dispatch: the level of detail and level selection of sample_quad, then
// sample_quad8_simd's filter and trace (and after_quad's, once a quad's last read ran). Returns the position of the first job that needs the
// general path (nothing of it read or traced), or quad_count * read_count when all ran.
int sample_quad_batch8_simd(const QuadBatch8& batch, int first);

}  // namespace ontile
