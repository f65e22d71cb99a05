// Inverted-hull outline vertex functor (see outline_shader.h).
#include "shaders_cpp/toon/outline_shader.h"

#include <cmath>
#include <string>

#include "util/error.h"

namespace ontile {

OutlineVertexShader::OutlineVertexShader(const MeshPrimitive& primitive, const glm::dmat4& world,
                                         const glm::dmat4& view_projection,
                                         const OutlineParams& params)
    : primitive_(primitive), params_(params), world_(world), view_projection_(view_projection),
      model_view_projection_(view_projection * world),
      normal_matrix_(glm::transpose(glm::inverse(glm::dmat3(world)))),
      half_viewport_px_(0.5f * static_cast<float>(params.viewport_width_px),
                        0.5f * static_cast<float>(params.viewport_height_px)) {
  if (params_.mode == OutlineMode::ScreenSpace &&
      (params_.viewport_width_px <= 0 || params_.viewport_height_px <= 0)) {
    throw Error("OutlineVertexShader: screen-space outlines need the viewport size (got " +
                std::to_string(params_.viewport_width_px) + "x" +
                std::to_string(params_.viewport_height_px) + ")");
  }
}

void OutlineVertexShader::shade(uint32_t first, uint32_t count, glm::vec4* clip, float*) const {
  const bool has_normals = !primitive_.normals.empty();
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t v = first + i;
    const glm::vec3 p = primitive_.positions[v];
    if (!has_normals) {
      clip[i] = model_view_projection_ * glm::vec4(p, 1.0f);
      continue;
    }
    const glm::vec3 n = primitive_.normals[v];
    const float n_len = glm::length(n);
    if (params_.mode == OutlineMode::ObjectSpace) {
      const glm::vec3 pushed = n_len > 0.0f ? p + n * (params_.thickness_object_units / n_len) : p;
      clip[i] = model_view_projection_ * glm::vec4(pushed, 1.0f);
      continue;
    }
    glm::vec4 c = view_projection_ * (world_ * glm::vec4(p, 1.0f));
    const glm::vec4 n_clip = view_projection_ * glm::vec4(normal_matrix_ * n, 0.0f);
    // d/de of (c.xy + e n_clip.xy) / (c.w + e n_clip.w) at e = 0, up to the positive factor
    // 1 / w^2, in pixels.
    const glm::vec2 dir_px =
        (glm::vec2(n_clip) * c.w - glm::vec2(c) * n_clip.w) * half_viewport_px_;
    const float dir_len = glm::length(dir_px);
    if (dir_len > 0.0f && std::isfinite(dir_len)) {
      const glm::vec2 offset_ndc = (dir_px / dir_len) * params_.thickness_px / half_viewport_px_;
      c.x += offset_ndc.x * c.w;
      c.y += offset_ndc.y * c.w;
    }
    clip[i] = c;
  }
}

uint32_t OutlineVertexShader::input_vertex_bytes() const {
  return primitive_.normals.empty() ? 12u : 24u;
}

}  // namespace ontile
