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

}  // namespace ontile
