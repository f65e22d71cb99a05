// Built-in full-screen functors (see full_screen.h).
#include "shaders_cpp/full_screen.h"

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

void ClearColorShader::shade(const QuadFragment&, QuadOutput& out) const {
  for (int k = 0; k < outputs_; ++k)
    for (int lane = 0; lane < kQuadLanes; ++lane) out.color[k][lane] = color_;
}

void GradientSkyShader::shade(const QuadFragment& quad, QuadOutput& out) const {
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    const glm::vec3 d = quad.var3(FullScreenVertexShader::kViewDirection, lane);
    const float len = glm::length(d);
    const float up = len > 0.0f ? d.y / len : 0.0f;
    const glm::vec3 c = up >= 0.0f ? glm::mix(horizon_, zenith_, glm::sqrt(up))
                                   : glm::mix(horizon_, ground_, glm::min(1.0f, -up * 4.0f));
    out.color[0][lane] = glm::vec4(c, 1.0f);
  }
}

}  // namespace ontile
