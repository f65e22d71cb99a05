// Screen-space Sobel edges (see sobel_edge_shader.h).
#include "shaders_cpp/toon/sobel_edge_shader.h"

#include <cmath>
#include <string>

#include "raster/texel_trace.h"
#include "shaders_cpp/batch_helpers.h"
#include "shaders_cpp/full_screen.h"
#include "util/error.h"

namespace ontile {
namespace {

constexpr float kMinOneMinusDepth = 5.9604645e-8f;  // 2^-24
// Beyond 2^24 every float is an integer: where texture.cpp's texel_coord clamps (ClampToEdge).
constexpr float kMaxExactTexelCoord = 16777216.0f;
constexpr int kTapsPerAxis = 3;
constexpr int kTaps = kTapsPerAxis * kTapsPerAxis;
constexpr int kCentreTap = 4;
// Distinct tap columns (or rows) of one quad: at most 3 per lane.
constexpr int kAxisSlots = kQuadLanes * kTapsPerAxis;

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

// The distinct texel indices along one axis that a quad's taps use, in order of first use:
// a tap's texel is the cell (row slot, column slot) of a small grid shared by the quad's lanes.
class AxisTexels {
 public:
  int slot_of(int index) {
    for (int s = 0; s < count_; ++s) {
      if (indices_[s] == index) return s;
    }
    indices_[count_] = index;
    return count_++;
  }

 private:
  int indices_[kAxisSlots];
  int count_ = 0;
};

// One bit per grid cell: which texels of the quad have been read and decoded.
class CellSet {
 public:
  bool contains(int cell) const { return (words_[cell >> 6] >> (cell & 63)) & 1u; }
  void insert(int cell) { words_[cell >> 6] |= uint64_t{1} << (cell & 63); }

 private:
  uint64_t words_[(kAxisSlots * kAxisSlots + 63) / 64] = {};
};

// One lane's taps: tap k is texel (x[k % 3], y[k / 3]), grid cell cell[k].
struct LaneTaps {
  int x[kTapsPerAxis], y[kTapsPerAxis];
  int cell[kTaps];
};

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

SobelEdgeShader::TexelAddressing SobelEdgeShader::addressing_of(const Texture2D* texture) {
  if (!texture) return {};
  return {texture->texel_address(0, 0, 0), static_cast<uint64_t>(texture->memory_bytes_per_texel()),
          texture->width(), texture->height()};
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
  tap_step_uv_ = glm::vec2(p_.thickness_px / static_cast<float>(p_.depth->width()),
                           p_.thickness_px / static_cast<float>(p_.depth->height()));
  color_addressing_ = addressing_of(p_.color);
  depth_addressing_ = addressing_of(p_.depth);
  normal_addressing_ = addressing_of(p_.normal);
  border_addressing_ = addressing_of(p_.border);
}

void SobelEdgeShader::shade_lanes(const glm::vec2 uv[kQuadLanes], uint8_t lane_mask,
                                  glm::vec4 out[kQuadLanes]) const {
  const auto active = [lane_mask](int lane) { return ((lane_mask >> lane) & 1u) != 0u; };
  // Tap k of a lane is column offset k % 3 - 1 and row offset k / 3 - 1, in steps of
  // tap_step_uv_; its uv is uv + offset * step per axis, as the per-tap sampling computed it.
  // Depth, normal and border have the same size (checked at construction): the same texels.
  const TexelAddressing& grid = depth_addressing_;
  AxisTexels columns, rows;
  LaneTaps taps[kQuadLanes];
  int color_x[kQuadLanes], color_y[kQuadLanes];
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    if (!active(lane)) continue;
    LaneTaps& t = taps[lane];
    int column_slot[kTapsPerAxis], row_slot[kTapsPerAxis];
    for (int a = 0; a < kTapsPerAxis; ++a) {
      const float offset = static_cast<float>(a - 1);
      t.x[a] = nearest_clamped_texel(uv[lane].x + offset * tap_step_uv_.x, grid.width_px);
      t.y[a] = nearest_clamped_texel(uv[lane].y + offset * tap_step_uv_.y, grid.height_px);
      column_slot[a] = columns.slot_of(t.x[a]);
      row_slot[a] = rows.slot_of(t.y[a]);
    }
    for (int k = 0; k < kTaps; ++k) {
      t.cell[k] = row_slot[k / kTapsPerAxis] * kAxisSlots + column_slot[k % kTapsPerAxis];
    }
    color_x[lane] = nearest_clamped_texel(uv[lane].x, color_addressing_.width_px);
    color_y[lane] = nearest_clamped_texel(uv[lane].y, color_addressing_.height_px);
  }
  // Decoded texels by grid cell, each read on first use.
  float cell_depth[kAxisSlots * kAxisSlots], cell_linear_z[kAxisSlots * kAxisSlots];
  glm::vec3 cell_normal[kAxisSlots * kAxisSlots];
  CellSet depth_read, normal_read;
  // What each lane read beyond its depth taps, for the trace.
  bool read_all_normals[kQuadLanes] = {};
  int border_tap[kQuadLanes] = {-1, -1, -1, -1};
  {
    // Reads here are not traced: the per-tap sequence is reported below.
    const TexelTraceScope untraced(nullptr);
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (!active(lane)) continue;
      const LaneTaps& t = taps[lane];
      float depth[kTaps], linear_z[kTaps];
      for (int k = 0; k < kTaps; ++k) {
        const int cell = t.cell[k];
        if (!depth_read.contains(cell)) {
          cell_depth[cell] = p_.depth->fetch(0, t.x[k % kTapsPerAxis], t.y[k / kTapsPerAxis]).x;
          cell_linear_z[cell] = linearize_depth(cell_depth[cell], p_.depth_linearization);
          depth_read.insert(cell);
        }
        depth[k] = cell_depth[cell];
        linear_z[k] = cell_linear_z[cell];
      }
      // The centre keeps ties, so neighbouring bordered materials at equal depth keep their
      // own line.
      int nearest = kCentreTap;
      for (int k = 0; k < kTaps; ++k) {
        if (depth[k] < depth[nearest]) nearest = k;
      }
      float depth_limit = p_.depth_threshold * p_.depth_sensitivity * linear_z[kCentreTap];
      const auto normal_at = [&](int k) {
        const int cell = t.cell[k];
        if (!normal_read.contains(cell)) {
          cell_normal[cell] = decode_view_normal(
              p_.normal->fetch(0, t.x[k % kTapsPerAxis], t.y[k / kTapsPerAxis]),
              p_.normal_encoding);
          normal_read.insert(cell);
        }
        return cell_normal[cell];
      };
      glm::vec3 normals[kTaps];
      if (p_.normal) {
        normals[kCentreTap] = normal_at(kCentreTap);
        depth_limit /= grazing_cosine(normals[kCentreTap], uv[lane]);
      }
      bool edge = sobel_magnitude(linear_z) > depth_limit;
      if (!edge && p_.normal) {  // the other normal taps only matter when depth found no edge
        for (int k = 0; k < kTaps; ++k) {
          if (k != kCentreTap) normals[k] = normal_at(k);
        }
        read_all_normals[lane] = true;
        edge = sobel_vector_magnitude(normals) > p_.normal_threshold;
      }
      const glm::vec4 scene = p_.color->fetch(0, color_x[lane], color_y[lane]);
      if (!edge) {
        out[lane] = scene;
        continue;
      }
      glm::vec4 border = p_.default_border_color;
      if (p_.border) {
        border = p_.border->fetch(0, t.x[nearest % kTapsPerAxis], t.y[nearest / kTapsPerAxis]);
        border_tap[lane] = nearest;
      }
      out[lane] = glm::vec4(glm::mix(glm::vec3(scene), glm::vec3(border), border.w), scene.w);
    }
  }
  // The texel trace of sampling every tap separately, lane by lane (see the class comment).
  for (int lane = 0; lane < kQuadLanes; ++lane) {
    if (!active(lane)) continue;
    const LaneTaps& t = taps[lane];
    const auto record_tap = [&t](const TexelAddressing& a, int k) {
      record_texel_address(a.address(t.x[k % kTapsPerAxis], t.y[k / kTapsPerAxis]));
    };
    for (int k = 0; k < kTaps; ++k) record_tap(depth_addressing_, k);
    if (p_.normal) {
      record_tap(normal_addressing_, kCentreTap);
      if (read_all_normals[lane]) {
        for (int k = 0; k < kTaps; ++k) {
          if (k != kCentreTap) record_tap(normal_addressing_, k);
        }
      }
    }
    record_texel_address(color_addressing_.address(color_x[lane], color_y[lane]));
    if (border_tap[lane] >= 0) record_tap(border_addressing_, border_tap[lane]);
  }
}

glm::vec4 SobelEdgeShader::shade_pixel(glm::vec2 uv) const {
  const glm::vec2 lane_uv[kQuadLanes] = {uv, uv, uv, uv};
  glm::vec4 out[kQuadLanes];
  shade_lanes(lane_uv, 0x1, out);
  return out[0];
}

void SobelEdgeShader::shade_batch(const FragmentBatch& batch, BatchOutput& out) const {
  // Quad by quad: shade_lanes shares texel reads within a quad and records the trace per quad,
  // so the reads and their order are those of shading the quads one at a time.
  for (int q = 0; q < batch.quad_count; ++q) {
    glm::vec2 uv[kQuadLanes];
    batch_quad_uv(batch, FullScreenVertexShader::kUv, q, uv);
    glm::vec4 colour[kQuadLanes];
    shade_lanes(uv, batch.lane_mask[q], colour);
    for (int lane = 0; lane < kQuadLanes; ++lane) {
      if (batch.active(q * kQuadLanes + lane)) out.set(0, q * kQuadLanes + lane, colour[lane]);
    }
  }
}

}  // namespace ontile
