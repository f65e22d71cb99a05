// Built-in full-screen functors (see full_screen.h).
#include "shaders_cpp/full_screen.h"

#include "shaders_cpp/gradient_sky_lanes.h"

namespace ontile {
namespace {
// A triangle whose clip-space corners (-1,-1), (3,-1), (-1,3) cover the whole viewport.
constexpr float kCorners[3][2] = {{-1.0f, -1.0f}, {3.0f, -1.0f}, {-1.0f, 3.0f}};
constexpr uint32_t kIndices[3] = {0, 1, 2};
}  // namespace

const uint32_t* full_screen_indices() { return kIndices; }

FullScreenVertexShader::FullScreenVertexShader(float depth, const glm::dmat4* inverse_vp)
    : depth_(depth) {
  for (int i = 0; i < 3; ++i) {
    direction_[i] = glm::vec3(0.0f);
    if (!inverse_vp) continue;
    // The view ray through each corner: far point minus near point, unprojected.
    const glm::dvec4 near_p = *inverse_vp * glm::dvec4(kCorners[i][0], kCorners[i][1], 0.0, 1.0);
    const glm::dvec4 far_p = *inverse_vp * glm::dvec4(kCorners[i][0], kCorners[i][1], 0.5, 1.0);
    direction_[i] = glm::vec3(glm::dvec3(far_p) / far_p.w - glm::dvec3(near_p) / near_p.w);
  }
}

void FullScreenVertexShader::shade(uint32_t first, uint32_t count, glm::vec4* clip, float* var) const {
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t v = first + i;
    clip[i] = glm::vec4(kCorners[v][0], kCorners[v][1], depth_, 1.0f);
    float* out = var + i * 5;
    out[kUv] = kCorners[v][0] * 0.5f + 0.5f;
    out[kUv + 1] = 0.5f - kCorners[v][1] * 0.5f;
    out[kViewDirection] = direction_[v].x;
    out[kViewDirection + 1] = direction_[v].y;
    out[kViewDirection + 2] = direction_[v].z;
  }
}

void ClearColorShader::shade_batch(const FragmentBatch& batch, BatchOutput& out) const {
  const int n = batch.padded_fragment_count();
  for (int k = 0; k < outputs_; ++k) {
    for (int c = 0; c < 4; ++c) {
      const float value = color_[c];  // glm's operator[] is a switch: read it once
      for (int f = 0; f < n; ++f) out.color[k][c][f] = value;
    }
  }
}

// Per fragment as glm computes it: length = sqrt((x*x + y*y) + z*z), mix(a, b, t) =
// a * (1 - t) + b * t, min(1, x) = x < 1 ? x : 1; both sides are evaluated and one selected.
void GradientSkyShader::shade_batch(const FragmentBatch& batch, BatchOutput& out) const {
  gradient_sky_batch(batch.varyings[FullScreenVertexShader::kViewDirection],
                     batch.varyings[FullScreenVertexShader::kViewDirection + 1],
                     batch.varyings[FullScreenVertexShader::kViewDirection + 2], batch.padded_fragment_count(),
                     {zenith_, horizon_, ground_}, out.color[0]);
  // Other outputs (normals, borders of an MRT pass) are never written: the batcher's zeros.
  out.uniform_outputs |= ~uint32_t{1};
}

}  // namespace ontile
