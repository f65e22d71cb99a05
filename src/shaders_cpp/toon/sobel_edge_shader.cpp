// Screen-space Sobel edges (see sobel_edge_shader.h).
#include "shaders_cpp/toon/sobel_edge_shader.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "raster/texture_batch_simd.h"
#include "shaders_cpp/full_screen.h"
#include "shaders_cpp/toon/sobel_tap_trace.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr float kMinOneMinusDepth = 5.9604645e-8f;  // 2^-24
// Beyond 2^24 every float is an integer: where texture.cpp's texel_coord clamps (ClampToEdge).
constexpr float kMaxExactTexelCoord = 16777216.0f;
using sobel::kCentreTap;
using sobel::kTaps;
using sobel::kTapsPerAxis;

// The texel index along one axis that Texture2D::sample_lod reads for a nearest, clamp-to-edge
// sample of level 0 at normalized coordinate u (texture.cpp: finite_or_zero, texel_coord,
// floor, wrap_texel_index; i = floor(u * size), OpenGL 4.6 eq. 8.9), operation for operation,
// so a direct fetch reads exactly the texel that sampling the tap would.
int nearest_clamped_texel(float u, int size) {
  if (!std::isfinite(u)) u = 0.0f;
  if (!(std::fabs(u) < kMaxExactTexelCoord)) u = std::copysign(kMaxExactTexelCoord, u);
  float x = u * static_cast<float>(size);
  if (!(std::fabs(x) < kMaxExactTexelCoord)) x = std::copysign(kMaxExactTexelCoord, x);
  const int i = static_cast<int>(std::floor(x));
  return i < 0 ? 0 : (i < size ? i : size - 1);
}

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
  color_ = p_.color->texel_view(0);
  depth_ = p_.depth->texel_view(0);
  if (p_.normal) normal_ = p_.normal->texel_view(0);
  if (p_.border) border_ = p_.border->texel_view(0);
  // Tap a of an axis is at uv + (a - 1) * step: the product rounded once, as the per-tap
  // sampling computes it.
  const glm::vec2 step(p_.thickness_px / static_cast<float>(depth_.width),
                       p_.thickness_px / static_cast<float>(depth_.height));
  for (int a = 0; a < kTapsPerAxis; ++a) {
    const float offset = static_cast<float>(a - 1);
    layout_.offset_u[a] = offset * step.x;
    layout_.offset_v[a] = offset * step.y;
  }
  layout_.grid_width = depth_.width;
  layout_.grid_height = depth_.height;
  layout_.color_width = color_.width;
  layout_.color_height = color_.height;
  // linearize_depth's constants: f * n and f - n are each one rounding, wherever computed.
  depth_decode_.mode = l.orthographic          ? sobel::DepthDecode::Orthographic
                       : l.far_plane == 0.0f ? sobel::DepthDecode::InfinitePerspective
                                             : sobel::DepthDecode::Perspective;
  depth_decode_.near_plane = l.near_plane;
  depth_decode_.far_times_near = l.far_plane * l.near_plane;
  depth_decode_.far_minus_near = l.far_plane - l.near_plane;
  edge_test_.depth_limit_scale = p_.depth_threshold * p_.depth_sensitivity;
  edge_test_.has_normal = p_.normal != nullptr;
  edge_test_.normal_threshold = p_.normal_threshold;
  edge_test_.view_ray_scale = p_.view_ray_scale;
  edge_test_.min_grazing_cosine = p_.min_grazing_cosine;
  trace_planes_.depth = sobel::TracePlane(depth_);
  trace_planes_.color = sobel::TracePlane(color_);
  trace_planes_.has_normal = p_.normal != nullptr;
  if (p_.normal) trace_planes_.normal = sobel::TracePlane(normal_);
  trace_planes_.has_border = p_.border != nullptr;
  if (p_.border) trace_planes_.border = sobel::TracePlane(border_);
  trace_planes_.prepare_tags();
  batch_lanes_ = sobel::BatchTracePlanes::fits_lanes(depth_, color_);
  color_codes_ = rgba8_codes_format(color_);
}

glm::vec4 SobelEdgeShader::edge_colour(glm::vec4 scene, int border_x, int border_y,
                                       sobel::TapTrace* trace) const {
  glm::vec4 border = p_.default_border_color;
  if (p_.border) {
    if (trace) trace->border(border_x, border_y);
    border = border_.load(border_x, border_y);
  }
  return glm::vec4(glm::mix(glm::vec3(scene), glm::vec3(border), border.w), scene.w);
}

glm::vec4 SobelEdgeShader::compose(const int tx[kTapsPerAxis], const int ty[kTapsPerAxis],
                                   int color_x, int color_y, bool edge, int nearest_tap,
                                   sobel::TapTrace& trace) const {
  const glm::vec4 scene = color_.load(color_x, color_y);
  if (!edge) return scene;
  return edge_colour(scene, tx[nearest_tap % kTapsPerAxis], ty[nearest_tap / kTapsPerAxis],
                     &trace);
}

glm::vec4 SobelEdgeShader::shade_one(glm::vec2 uv, sobel::TapTrace& trace) const {
  int tx[kTapsPerAxis], ty[kTapsPerAxis];
  for (int a = 0; a < kTapsPerAxis; ++a) {
    tx[a] = nearest_clamped_texel(uv.x + layout_.offset_u[a], depth_.width);
    ty[a] = nearest_clamped_texel(uv.y + layout_.offset_v[a], depth_.height);
  }
  float depth[kTaps], linear_z[kTaps];
  for (int k = 0; k < kTaps; ++k) {
    depth[k] = depth_.load(tx[k % 3], ty[k / 3]).x;
    linear_z[k] = linearize_depth(depth[k], p_.depth_linearization);
  }
  // The centre keeps ties, so neighbouring bordered materials at equal depth keep their own line.
  int nearest = kCentreTap;
  for (int k = 0; k < kTaps; ++k) {
    if (depth[k] < depth[nearest]) nearest = k;
  }
  float depth_limit = edge_test_.depth_limit_scale * linear_z[kCentreTap];
  glm::vec3 normals[kTaps];
  const auto normal_at = [&](int k) {
    return decode_view_normal(normal_.load(tx[k % 3], ty[k / 3]), p_.normal_encoding);
  };
  if (p_.normal) {
    normals[kCentreTap] = normal_at(kCentreTap);
    depth_limit /= grazing_cosine(normals[kCentreTap], uv);
  }
  const bool depth_edge = sobel_magnitude(linear_z) > depth_limit;
  bool edge = depth_edge;
  if (!edge && p_.normal) {
    for (int k = 0; k < kTaps; ++k) {
      if (k != kCentreTap) normals[k] = normal_at(k);
    }
    edge = sobel_vector_magnitude(normals) > p_.normal_threshold;
  }
  const int color_x = nearest_clamped_texel(uv.x, color_.width);
  const int color_y = nearest_clamped_texel(uv.y, color_.height);
  // The other normal taps only matter when depth found no edge.
  trace.fragment(tx, ty, color_x, color_y, p_.normal && !depth_edge);
  return compose(tx, ty, color_x, color_y, edge, nearest, trace);
}

bool SobelEdgeShader::shade_fragments(const float* u, const float* v, int count, uint64_t active,
                                      float (&colour)[4][kBatchFragments]) const {
  const auto store = [&colour](int f, glm::vec4 c) {
    for (int ch = 0; ch < 4; ++ch) colour[ch][f] = c[ch];
  };
  sobel::TapTrace trace(color_, depth_, p_.normal ? &normal_ : nullptr,
                        p_.border ? &border_ : nullptr);
  sobel::FragmentTaps taps;
  sobel::tap_texels(u, v, count, active, layout_, taps);
  const int64_t box_width = int64_t{taps.x1} - taps.x0 + 1;
  const int64_t box_height = int64_t{taps.y1} - taps.y0 + 1;
  if (active == 0) return false;
  if (box_width * box_height > sobel::kMaxGridTexels) {
    for (uint64_t rest = active; rest != 0; rest &= rest - 1) {
      const int f = std::countr_zero(rest);
      store(f, shade_one({u[f], v[f]}, trace));
    }
    return false;
  }
  sobel::NeighbourhoodGrid grid;
  grid.x0 = taps.x0;
  grid.y0 = taps.y0;
  grid.width = static_cast<int>(box_width);
  grid.height = static_cast<int>(box_height);
  sobel::decode_grid(depth_, p_.normal ? &normal_ : nullptr, p_.normal_encoding, depth_decode_,
                     grid);
  sobel::FragmentEdges edges;
  const bool regular = sobel::find_edges_rows(u, v, count, active, taps, grid, edge_test_, edges);
  if (!regular) {
    sobel::find_edges(u, v, count, taps, grid, edge_test_, edges);
  }
  if (batch_lanes_) {
    trace.batch(trace_planes_, taps, edges, count, active, regular);
    load_texels(color_, taps.color_x, taps.color_y, count, active, colour);
    for (uint64_t rest = active & edges.edge; rest != 0; rest &= rest - 1) {
      const int f = std::countr_zero(rest);
      const int tap = edges.nearest_tap[f];
      const glm::vec4 scene(colour[0][f], colour[1][f], colour[2][f], colour[3][f]);
      store(f, edge_colour(scene, taps.x[tap % kTapsPerAxis][f], taps.y[tap / kTapsPerAxis][f],
                           nullptr));
    }
    return (active & edges.edge) == 0;
  }
  for (uint64_t rest = active; rest != 0; rest &= rest - 1) {
    const int f = std::countr_zero(rest);
    const int tx[kTapsPerAxis] = {taps.x[0][f], taps.x[1][f], taps.x[2][f]};
    const int ty[kTapsPerAxis] = {taps.y[0][f], taps.y[1][f], taps.y[2][f]};
    const bool all_normals = p_.normal && ((edges.depth_edge >> f) & 1u) == 0u;
    trace.fragment(tx, ty, taps.color_x[f], taps.color_y[f], all_normals);
    store(f, compose(tx, ty, taps.color_x[f], taps.color_y[f], (edges.edge >> f) & 1u,
                     edges.nearest_tap[f], trace));
  }
  return (active & edges.edge) == 0;
}

glm::vec4 SobelEdgeShader::shade_pixel(glm::vec2 uv) const {
  // One active fragment in a padded vector of 16 (the kernels' granularity).
  constexpr int kPadded = 16;
  float u[kPadded], v[kPadded];
  for (int f = 0; f < kPadded; ++f) {
    u[f] = uv.x;
    v[f] = uv.y;
  }
  float colour[4][kBatchFragments];
  shade_fragments(u, v, kPadded, 1u, colour);
  return {colour[0][0], colour[1][0], colour[2][0], colour[3][0]};
}

void SobelEdgeShader::shade_batch(const FragmentBatch& batch, BatchOutput& out) const {
  // Fragments in batch order are quads in order, lanes in order: the trace order of shading
  // the quads one at a time.
  const bool edge_free = shade_fragments(
      batch.varyings[FullScreenVertexShader::kUv], batch.varyings[FullScreenVertexShader::kUv + 1],
      batch.padded_fragment_count(), batch.active_mask(), out.color[0]);
  // Without an edge every written lane is a scene texel and every other lane the batcher's
  // zero (code 0): all decoded codes (BatchOutput::output0_codes_of).
  if (edge_free) out.output0_codes_of = color_codes_;
}

}  // namespace ontile
