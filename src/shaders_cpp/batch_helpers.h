// Helpers shared by the batched fragment functors: the uv of one quad for its texture reads, and
// interpolated normals made unit length over a whole batch as structure-of-arrays lanes.
#pragma once
#include <glm/glm.hpp>

#include "raster/shader_interface.h"
#include "raster/texture.h"

namespace ontile {

// Structure-of-arrays vectors over a batch's fragments: v[component][fragment].
using BatchVec3 = float[3][kBatchFragments];
using BatchVec4 = float[4][kBatchFragments];

// A Texture2D::sample_quads read whose texels land in `texel` (texel[c][fragment]).
inline Texture2D::QuadRead batch_texture_read(const Texture2D* texture, const SamplerDesc& sampler,
                                              BatchVec4& texel, int fetches = 1) {
  return {texture, &sampler, {texel[0], texel[1], texel[2], texel[3]}, fetches};
}

// colour[c][f] *= texel[c][f] for channels [0, channels) of the fragments of quads < quad_count
// (the padding lanes after them keep their value).
template <int kChannels>
inline void batch_multiply_quads(float (&colour)[kChannels][kBatchFragments], int channels, int quad_count,
                                 const BatchVec4& texel) {
  const int fragments = quad_count * kQuadLanes;
  for (int c = 0; c < channels; ++c) {
    for (int f = 0; f < fragments; ++f) colour[c][f] *= texel[c][f];
  }
}

// The four lanes of quad q of varyings [first, first + 1], for Texture2D::sample_quad.
inline void batch_quad_uv(const FragmentBatch& batch, int first, int q, glm::vec2 uv[kQuadLanes]) {
  const int f0 = q * kQuadLanes;
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    uv[lane] = {batch.varyings[first][f0 + lane], batch.varyings[first + 1][f0 + lane]};
  }
}

// colour[c][fragment] *= texel[lane][c] for channels [0, channels) of quad q's lanes.
template <int kChannels>
inline void batch_multiply_quad(float (&colour)[kChannels][kBatchFragments], int channels, int q,
                                const glm::vec4 texel[kQuadLanes]) {
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    for (int c = 0; c < channels; ++c) colour[c][q * kQuadLanes + lane] *= texel[lane][c];
  }
}

inline glm::vec3 batch_var3(const FragmentBatch& batch, int first, int f) {
  return {batch.varyings[first][f], batch.varyings[first + 1][f], batch.varyings[first + 2][f]};
}

inline glm::vec3 batch_get3(const BatchVec3& v, int f) { return {v[0][f], v[1][f], v[2][f]}; }
inline void batch_set3(BatchVec3& v, int f, glm::vec3 value) {
  v[0][f] = value.x;
  v[1][f] = value.y;
  v[2][f] = value.z;
}

// Varyings [first, first + 3) made unit length (a zero vector gives +Z) and negated on back
// faces, for fragments [0, n) rounded up to whole vectors (n <= kBatchFragments; every array is
// kBatchFragments long): toon_unit_normal's operations per fragment on SIMD lanes
// (unit_normal_lanes.cpp), so the bits match it on every target and with every compiler.
void batch_unit_normals(const FragmentBatch& batch, int first, int n, BatchVec3& out);

}  // namespace ontile
