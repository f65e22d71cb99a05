// Screen-space Sobel edges (see sobel_edge_shader.h).
#include "shaders_cpp/toon/sobel_edge_shader.h"

#include <cmath>
#include <string>

#include "shaders_cpp/full_screen.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr float kMinOneMinusDepth = 5.9604645e-8f;  // 2^-24

std::string size_text(const Texture2D& t) {
  return std::to_string(t.width()) + "x" + std::to_string(t.height());
}

void check_same_size(const char* what, const Texture2D* t, const Texture2D& depth) {
  if (t && (t->width() != depth.width() || t->height() != depth.height())) {
    throw Error("SobelEdgeShader: " + std::string(what) + " texture '" + t->name() + "' is " +
                size_text(*t) + " but depth texture '" + depth.name() + "' is " + size_text(depth));
  }
}

}  // namespace

DepthLinearization DepthLinearization::from_projection(const glm::dmat4& m) {
  DepthLinearization l;
  const double m22 = m[2][2], m32 = m[3][2];
  l.orthographic = m[2][3] == 0.0;
  l.near_plane = static_cast<float>(m32 / m22);
  if (l.orthographic) {
    l.far_plane = static_cast<float>(m32 / m22 - 1.0 / m22);
  } else {
    l.far_plane = m22 == -1.0 ? 0.0f : static_cast<float>(m32 / (m22 + 1.0));
  }
  return l;
}

float linearize_depth(float d, const DepthLinearization& l) {
  d = d > 0.0f ? (d < 1.0f ? d : 1.0f) : 0.0f;  // also NaN -> 0
  const float n = l.near_plane, f = l.far_plane;
  if (l.orthographic) return n + d * (f - n);
  if (f == 0.0f) {
    const float one_minus_d = 1.0f - d;
    return n / (one_minus_d > kMinOneMinusDepth ? one_minus_d : kMinOneMinusDepth);
  }
  // f - d (f - n) rewritten as n + (1 - d)(f - n): 1 - d is exact for d >= 0.5 (Sterbenz), so
  // distant depths, where D32F has the fewest steps, do not lose digits to cancellation.
  return f * n / (n + (1.0f - d) * (f - n));
}

float sobel_magnitude(const float v[9]) {
  const float gx = ((v[2] - v[0]) + (v[8] - v[6])) + 2.0f * (v[5] - v[3]);
  const float gy = ((v[6] - v[0]) + (v[8] - v[2])) + 2.0f * (v[7] - v[1]);
  return std::sqrt(gx * gx + gy * gy);
}

float sobel_vector_magnitude(const glm::vec3 v[9]) {
  const glm::vec3 gx = ((v[2] - v[0]) + (v[8] - v[6])) + 2.0f * (v[5] - v[3]);
  const glm::vec3 gy = ((v[6] - v[0]) + (v[8] - v[2])) + 2.0f * (v[7] - v[1]);
  return std::sqrt(glm::dot(gx, gx) + glm::dot(gy, gy));
}

float SobelEdgeShader::grazing_cosine(glm::vec3 view_normal, glm::vec2 uv) const {
  // The view ray through the pixel: (ndc.x / P00, ndc.y / P11, -1), ndc y up, uv v down.
  const glm::vec3 ray(p_.view_ray_scale.x * (2.0f * uv.x - 1.0f),
                      p_.view_ray_scale.y * (1.0f - 2.0f * uv.y), -1.0f);
  const float normal_len = glm::length(view_normal);
  if (!(normal_len > 0.0f)) return p_.min_grazing_cosine;  // background: nothing to compensate
  const float cosine = std::fabs(glm::dot(view_normal, ray)) / (normal_len * glm::length(ray));
  return cosine > p_.min_grazing_cosine ? cosine : p_.min_grazing_cosine;
}

glm::vec2 view_ray_scale(const glm::dmat4& projection) {
  if (projection[2][3] == 0.0) return glm::vec2(0.0f);  // orthographic: every ray is -Z
  return {static_cast<float>(1.0 / projection[0][0]), static_cast<float>(1.0 / projection[1][1])};
}

SobelEdgeShader::SobelEdgeShader(const SobelEdgeParams& params) : p_(params) {
  if (!p_.color) throw Error("SobelEdgeShader: no scene colour texture");
  if (!p_.depth) throw Error("SobelEdgeShader: no depth texture");
  check_same_size("normal", p_.normal, *p_.depth);
  check_same_size("border", p_.border, *p_.depth);
  const DepthLinearization& l = p_.depth_linearization;
  const bool valid = l.orthographic ? l.far_plane > l.near_plane
                                    : l.near_plane > 0.0f &&
                                          (l.far_plane == 0.0f || l.far_plane > l.near_plane);
  if (!valid) {
    throw Error("SobelEdgeShader: invalid depth range near " + std::to_string(l.near_plane) +
                " far " + std::to_string(l.far_plane) +
                (l.orthographic ? " (orthographic)" : " (perspective)"));
  }
  sampler_.mag_filter = FilterMode::Nearest;
  sampler_.min_filter = FilterMode::Nearest;
  sampler_.mipmap_mode = MipmapMode::None;
  sampler_.wrap_u = WrapMode::ClampToEdge;
  sampler_.wrap_v = WrapMode::ClampToEdge;
  tap_step_uv_ = glm::vec2(p_.thickness_px / static_cast<float>(p_.depth->width()),
                           p_.thickness_px / static_cast<float>(p_.depth->height()));
}

glm::vec4 SobelEdgeShader::shade_pixel(glm::vec2 uv) const {
  glm::vec2 tap_uv[9];
  float linear_z[9];
  float depth[9];
  for (int k = 0; k < 9; ++k) {
    tap_uv[k] = uv + glm::vec2(static_cast<float>(k % 3 - 1), static_cast<float>(k / 3 - 1)) *
                         tap_step_uv_;
    depth[k] = p_.depth->sample_lod(sampler_, tap_uv[k], 0.0f).x;
    linear_z[k] = linearize_depth(depth[k], p_.depth_linearization);
  }
  // The centre keeps ties, so neighbouring bordered materials at equal depth keep their own line.
  int nearest = 4;
  for (int k = 0; k < 9; ++k) {
    if (depth[k] < depth[nearest]) nearest = k;
  }
  float depth_limit = p_.depth_threshold * p_.depth_sensitivity * linear_z[4];
  const auto normal_at = [&](int k) {
    return decode_view_normal(p_.normal->sample_lod(sampler_, tap_uv[k], 0.0f), p_.normal_encoding);
  };
  glm::vec3 normals[9];
  if (p_.normal) {
    normals[4] = normal_at(4);
    depth_limit /= grazing_cosine(normals[4], uv);
  }
  bool edge = sobel_magnitude(linear_z) > depth_limit;
  if (!edge && p_.normal) {  // the other normal taps only matter when depth found no edge
    for (int k = 0; k < 9; ++k) {
      if (k != 4) normals[k] = normal_at(k);
    }
    edge = sobel_vector_magnitude(normals) > p_.normal_threshold;
  }
  const glm::vec4 scene = p_.color->sample_lod(sampler_, uv, 0.0f);
  if (!edge) return scene;
  const glm::vec4 border =
      p_.border ? p_.border->sample_lod(sampler_, tap_uv[nearest], 0.0f) : p_.default_border_color;
  return glm::vec4(glm::mix(glm::vec3(scene), glm::vec3(border), border.w), scene.w);
}

void SobelEdgeShader::shade(const QuadFragment& quad, QuadOutput& out) const {
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    if (!quad.lane_active(lane)) continue;
    out.color[0][lane] = shade_pixel(quad.var2(FullScreenVertexShader::kUv, lane));
  }
}

}  // namespace ontile
