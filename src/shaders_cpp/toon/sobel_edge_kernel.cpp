// The Sobel pass's SIMD stages (see sobel_edge_kernel.h), compiled once per SIMD target by
// Highway's foreach_target and chosen at run time. Each vector operation is the scalar code's
// operation in the same order (sobel_edge_shader.cpp: nearest_clamped_texel, linearize_depth,
// grazing_cosine, sobel_magnitude, sobel_vector_magnitude), so every target gives its bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/toon/sobel_edge_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/lane_bits-inl.h"
#include "shaders_cpp/toon/sobel_edge_math-inl.h"

#include <climits>
#include <cmath>
#include <cstring>

#include "raster/lane_bits.h"
#include "shaders_cpp/toon/sobel_edge_kernel.h"

HWY_BEFORE_NAMESPACE();
namespace ontile::sobel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using ontile::HWY_NAMESPACE::mask_bits;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using VF = hn::Vec<DF>;
using VI = hn::Vec<DI>;

// Beyond 2^24 every float is an integer: where texture.cpp's texel_coord clamps (ClampToEdge).
constexpr float kMaxExactTexelCoord = 16777216.0f;
constexpr float kMinOneMinusDepth = 5.9604645e-8f;  // 2^-24, as linearize_depth

// Mask of the lanes whose bit is set in bits (bit i = lane i).
HWY_INLINE hn::Mask<DI> lanes_of(DI di, uint64_t bits) {
  const VI word = hn::Set(di, static_cast<int32_t>(bits & 0xFFFFu));
  return hn::Ne(hn::And(word, hn::Load(di, kLaneBit)), hn::Zero(di));
}

// nearest_clamped_texel on lanes. When every lane's u * size is below 2^24 in magnitude (every
// uv of a full-screen pass), u is finite and below 2^24 too (size >= 1), so neither clamp
// changes a value: the floor of that product is taken directly, with the same bits.
HWY_INLINE VI nearest_clamped_texel(DF df, VF u, int size) {
  const DI di;
  const VF limit = hn::Set(df, kMaxExactTexelCoord);
  const VF direct = hn::Mul(u, hn::Set(df, static_cast<float>(size)));
  if (hn::AllTrue(df, hn::Lt(hn::Abs(direct), limit))) {
    const VI i = hn::ConvertTo(di, hn::Floor(direct));
    return hn::Min(hn::Max(i, hn::Zero(di)), hn::Set(di, size - 1));
  }
  u = hn::IfThenElseZero(hn::IsFinite(u), u);
  u = hn::IfThenElse(hn::Lt(hn::Abs(u), limit), u, hn::CopySign(limit, u));
  VF x = hn::Mul(u, hn::Set(df, static_cast<float>(size)));
  x = hn::IfThenElse(hn::Lt(hn::Abs(x), limit), x, hn::CopySign(limit, x));
  const VI i = hn::ConvertTo(di, hn::Floor(x));  // |x| <= 2^24: exact
  return hn::Min(hn::Max(i, hn::Zero(di)), hn::Set(di, size - 1));
}

void TapTexelsKernel(const float* u, const float* v, int count, uint64_t active,
                     const TapLayout& layout, FragmentTaps& taps) {
  const DF df;
  const DI di;
  const size_t n = hn::Lanes(df);
  // The layout in locals: the stores to taps could alias it otherwise.
  const TapLayout l = layout;
  // With ordered offsets below 2^100 in magnitude, tap 0 <= tap 1 <= tap 2 on every lane:
  // u + offset is monotonic and cannot overflow to infinity for a finite u (that takes a sum
  // of 2^128 - 2^103), every step of nearest_clamped_texel is monotonic, and a non-finite u
  // gives texel 0 for all taps. So the box needs only the outer taps.
  const auto ordered = [](const float (&o)[kTapsPerAxis]) {
    constexpr float kSmall = 1.2676506e30f;  // 2^100
    return std::fabs(o[0]) < kSmall && std::fabs(o[2]) < kSmall && o[0] <= o[1] && o[1] <= o[2];
  };
  const bool outer_taps_bound = ordered(l.offset_u) && ordered(l.offset_v);
  // The centre taps sit at uv + (+-0): u + 0 is u (or +0 for u = -0, the same texel 0), so
  // where the colour texture has the grid's size its texel is the centre tap's.
  const bool color_is_centre = l.color_width == l.grid_width &&
                               l.color_height == l.grid_height && l.offset_u[1] == 0.0f &&
                               l.offset_v[1] == 0.0f;
  VI min_x = hn::Set(di, INT32_MAX), min_y = min_x;
  VI max_x = hn::Set(di, INT32_MIN), max_y = max_x;
  for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
    const VF uf = hn::LoadU(df, u + f), vf = hn::LoadU(df, v + f);
    // A vector of active lanes only (most of them) widens the box without masking.
    const uint64_t lane_bits = n >= 64 ? ~uint64_t{0} : (uint64_t{1} << n) - 1;
    const bool all_on = ((active >> f) & lane_bits) == lane_bits;
    const hn::Mask<DI> on = all_on ? hn::FirstN(di, n) : lanes_of(di, active >> f);
    VI x[kTapsPerAxis], y[kTapsPerAxis];
    for (int a = 0; a < kTapsPerAxis; ++a) {
      x[a] = nearest_clamped_texel(df, hn::Add(uf, hn::Set(df, l.offset_u[a])), l.grid_width);
      y[a] = nearest_clamped_texel(df, hn::Add(vf, hn::Set(df, l.offset_v[a])), l.grid_height);
      hn::Store(x[a], di, taps.x[a] + f);
      hn::Store(y[a], di, taps.y[a] + f);
    }
    const auto widen = [&](VI lo, VI hi, VI& box_min_x, VI& box_max_x) {
      if (all_on) {
        box_min_x = hn::Min(box_min_x, lo);
        box_max_x = hn::Max(box_max_x, hi);
        return;
      }
      box_min_x = hn::Min(box_min_x, hn::IfThenElse(on, lo, hn::Set(di, INT32_MAX)));
      box_max_x = hn::Max(box_max_x, hn::IfThenElse(on, hi, hn::Set(di, INT32_MIN)));
    };
    if (outer_taps_bound) {
      widen(x[0], x[2], min_x, max_x);
      widen(y[0], y[2], min_y, max_y);
    } else {
      for (int a = 0; a < kTapsPerAxis; ++a) {
        widen(x[a], x[a], min_x, max_x);
        widen(y[a], y[a], min_y, max_y);
      }
    }
    if (color_is_centre) {
      hn::Store(x[1], di, taps.color_x + f);
      hn::Store(y[1], di, taps.color_y + f);
      continue;
    }
    const VI color_x = nearest_clamped_texel(df, uf, l.color_width);
    const VI color_y = nearest_clamped_texel(df, vf, l.color_height);
    hn::Store(color_x, di, taps.color_x + f);
    hn::Store(color_y, di, taps.color_y + f);
  }
  taps.x0 = hn::GetLane(hn::MinOfLanes(di, min_x));
  taps.y0 = hn::GetLane(hn::MinOfLanes(di, min_y));
  taps.x1 = hn::GetLane(hn::MaxOfLanes(di, max_x));
  taps.y1 = hn::GetLane(hn::MaxOfLanes(di, max_y));
}

// linearize_depth on lanes, and the same for one value (row tails).
HWY_INLINE VF linearize(DF df, VF d, const DepthDecode& l) {
  const VF one = hn::Set(df, 1.0f);
  d = hn::IfThenElseZero(hn::Gt(d, hn::Zero(df)), hn::IfThenElse(hn::Lt(d, one), d, one));
  const VF n = hn::Set(df, l.near_plane);
  if (l.mode == DepthDecode::Orthographic) return hn::Add(n, hn::Mul(d, hn::Set(df, l.far_minus_near)));
  const VF one_minus_d = hn::Sub(one, d);
  if (l.mode == DepthDecode::InfinitePerspective) {
    const VF k = hn::Set(df, kMinOneMinusDepth);
    return hn::Div(n, hn::IfThenElse(hn::Gt(one_minus_d, k), one_minus_d, k));
  }
  return hn::Div(hn::Set(df, l.far_times_near),
                 hn::Add(n, hn::Mul(one_minus_d, hn::Set(df, l.far_minus_near))));
}

float linearize_one(float d, const DepthDecode& l) {
  d = d > 0.0f ? (d < 1.0f ? d : 1.0f) : 0.0f;
  const float n = l.near_plane;
  if (l.mode == DepthDecode::Orthographic) return n + d * l.far_minus_near;
  const float one_minus_d = 1.0f - d;
  if (l.mode == DepthDecode::InfinitePerspective) {
    return n / (one_minus_d > kMinOneMinusDepth ? one_minus_d : kMinOneMinusDepth);
  }
  return l.far_times_near / (n + one_minus_d * l.far_minus_near);
}

// decode_view_normal of one stored channel.
HWY_INLINE VF decode_normal(DF df, VF stored, NormalEncoding encoding) {
  if (encoding == NormalEncoding::Float) return stored;
  return hn::Sub(hn::Mul(stored, hn::Set(df, 2.0f)), hn::Set(df, 1.0f));
}

// The RGBA floats of texels [x0, x0 + count) of row y, or null for 8-bit texels (decoded one
// at a time): Float32 texels in place; a surface view's pixels decoded into `row` with
// decode_pixels, the values the view's load() gives, on SIMD lanes.
const float* float_row(const Texture2D::TexelView& view, int x0, int y, int count,
                       glm::vec4* row) {
  const size_t first = static_cast<size_t>(y) * view.width + x0;
  if (view.texels32f) return view.texels32f + first * 4;
  if (!view.surface_bytes) return nullptr;
  decode_pixels(view.surface_format, view.surface_bytes + first * view.memory_bytes_per_texel,
                count, row);
  return &row[0].x;
}

void DecodeGridKernel(const Texture2D::TexelView& depth, const Texture2D::TexelView* normal,
                      NormalEncoding encoding, const DepthDecode& decode, NeighbourhoodGrid& grid) {
  const DF df;
  const size_t n = hn::Lanes(df);
  const size_t width = static_cast<size_t>(grid.width);
  static_assert(sizeof(glm::vec4) == 4 * sizeof(float), "a row of vec4 is a row of floats");
  glm::vec4 row_texels[kMaxGridTexels];
  for (int row = 0; row < grid.height; ++row) {
    const int y = grid.y0 + row;
    const size_t cell0 = static_cast<size_t>(row) * width;
    size_t i = 0;
    // Float texels on lanes (RGBA interleaved: the x channel is every fourth float); 8-bit
    // texels, and the tail of a row, decode one at a time with the same operations.
    if (depth.surface_bytes && (depth.surface_format == PixelFormat::D32_FLOAT ||
                                depth.surface_format == PixelFormat::R32_FLOAT)) {
      // One float per texel, stored as is: decode_pixel gives (d, 0, 0, 1) with d these bits.
      const uint8_t* src = depth.surface_bytes + (static_cast<size_t>(y) * depth.width + grid.x0) * 4;
      const auto cells = [&](size_t at) {
        const VF d = hn::LoadU(df, reinterpret_cast<const float*>(src + 4 * at));
        hn::StoreU(d, df, grid.depth + cell0 + at);
        hn::StoreU(linearize(df, d, decode), df, grid.linear_z + cell0 + at);
      };
      for (; i + n <= width; i += n) cells(i);
      // The tail as the last full vector of the row: cells decoded twice get the same bits.
      if (i < width && width >= n) {
        cells(width - n);
        i = width;
      }
      for (; i < width; ++i) {
        float d;
        std::memcpy(&d, src + 4 * i, sizeof d);
        grid.depth[cell0 + i] = d;
        grid.linear_z[cell0 + i] = linearize_one(d, decode);
      }
    } else if (const float* src = float_row(depth, grid.x0, y, grid.width, row_texels)) {
      const auto cells = [&](size_t at) {
        VF d, g, b, a;
        hn::LoadInterleaved4(df, src + at * 4, d, g, b, a);
        hn::StoreU(d, df, grid.depth + cell0 + at);
        hn::StoreU(linearize(df, d, decode), df, grid.linear_z + cell0 + at);
      };
      for (; i + n <= width; i += n) cells(i);
      if (i < width && width >= n) {
        cells(width - n);
        i = width;
      }
      for (; i < width; ++i) {
        grid.depth[cell0 + i] = src[i * 4];
        grid.linear_z[cell0 + i] = linearize_one(src[i * 4], decode);
      }
    }
    for (; i < width; ++i) {
      const float d = depth.load(grid.x0 + static_cast<int>(i), y).x;
      grid.depth[cell0 + i] = d;
      grid.linear_z[cell0 + i] = linearize_one(d, decode);
    }
    if (!normal) continue;
    i = 0;
    if (normal->surface_bytes && normal->surface_format == PixelFormat::RGB10A2_UNORM) {
      // A view of 10-bit normals decoded on lanes straight from the words, with
      // DecodeRgb10a2Kernel's operations (code / 1023, exact codes), then decode_normal.
      const uint8_t* src =
          normal->surface_bytes + (static_cast<size_t>(y) * normal->width + grid.x0) * 4;
      const hn::RebindToUnsigned<DF> du;
      const auto ten_bits = hn::Set(du, 0x3FFu);
      const VF max10 = hn::Set(df, 1023.0f);
      const auto channel = [&](hn::Vec<decltype(du)> code) {
        return decode_normal(df, hn::Div(hn::ConvertTo(df, hn::BitCast(DI(), code)), max10),
                             encoding);
      };
      const auto cells = [&](size_t at) {
        const auto word = hn::LoadU(du, reinterpret_cast<const uint32_t*>(src + 4 * at));
        hn::StoreU(channel(hn::And(word, ten_bits)), df, grid.normal[0] + cell0 + at);
        hn::StoreU(channel(hn::And(hn::ShiftRight<10>(word), ten_bits)), df,
                   grid.normal[1] + cell0 + at);
        hn::StoreU(channel(hn::And(hn::ShiftRight<20>(word), ten_bits)), df,
                   grid.normal[2] + cell0 + at);
      };
      for (; i + n <= width; i += n) cells(i);
      if (i < width && width >= n) {
        cells(width - n);
        i = width;
      }
    } else if (const float* src = float_row(*normal, grid.x0, y, grid.width, row_texels)) {
      const auto cells = [&](size_t at) {
        VF nx, ny, nz, nw;
        hn::LoadInterleaved4(df, src + at * 4, nx, ny, nz, nw);
        hn::StoreU(decode_normal(df, nx, encoding), df, grid.normal[0] + cell0 + at);
        hn::StoreU(decode_normal(df, ny, encoding), df, grid.normal[1] + cell0 + at);
        hn::StoreU(decode_normal(df, nz, encoding), df, grid.normal[2] + cell0 + at);
      };
      for (; i + n <= width; i += n) cells(i);
      if (i < width && width >= n) {
        cells(width - n);
        i = width;
      }
      for (; i < width; ++i) {
        const glm::vec4 texel(src[i * 4], src[i * 4 + 1], src[i * 4 + 2], src[i * 4 + 3]);
        const glm::vec3 nv = decode_view_normal(texel, encoding);
        for (int c = 0; c < 3; ++c) grid.normal[c][cell0 + i] = nv[c];
      }
    }
    for (; i < width; ++i) {
      const glm::vec3 nv = decode_view_normal(normal->load(grid.x0 + static_cast<int>(i), y), encoding);
      for (int c = 0; c < 3; ++c) grid.normal[c][cell0 + i] = nv[c];
    }
  }
}

void FindEdgesKernel(const float* u, const float* v, int count, const FragmentTaps& taps,
                     const NeighbourhoodGrid& grid, const EdgeTest& test, FragmentEdges& edges) {
  const DF df;
  const DI di;
  const size_t n = hn::Lanes(df);
  const VI x0 = hn::Set(di, grid.x0), y0 = hn::Set(di, grid.y0);
  const VI x1 = hn::Set(di, grid.x0 + grid.width - 1), y1 = hn::Set(di, grid.y0 + grid.height - 1);
  const VI width = hn::Set(di, grid.width);
  edges.depth_edge = edges.edge = 0;
  for (size_t f = 0; f < static_cast<size_t>(count); f += n) {
    // Grid cells of the taps; fragments outside the grid (inactive ones) read clamped cells.
    VI column[kTapsPerAxis], row_start[kTapsPerAxis];
    for (int a = 0; a < kTapsPerAxis; ++a) {
      column[a] = hn::Sub(hn::Min(hn::Max(hn::Load(di, taps.x[a] + f), x0), x1), x0);
      row_start[a] =
          hn::Mul(hn::Sub(hn::Min(hn::Max(hn::Load(di, taps.y[a] + f), y0), y1), y0), width);
    }
    VI cell[kTaps];
    for (int k = 0; k < kTaps; ++k) {
      cell[k] = hn::Add(row_start[k / kTapsPerAxis], column[k % kTapsPerAxis]);
    }
    hn::Mask<DF> depth_edge, edge;
    VI nearest;
    edge_lanes(
        df, hn::LoadU(df, u + f), hn::LoadU(df, v + f), test,
        [&](int k) { return hn::GatherIndex(df, grid.linear_z, cell[k]); },
        [&](int k) { return hn::GatherIndex(df, grid.depth, cell[k]); },
        [&](int c, int k) { return hn::GatherIndex(df, grid.normal[c], cell[k]); }, depth_edge,
        edge, nearest);
    hn::Store(nearest, di, edges.nearest_tap + f);
    edges.depth_edge |= mask_bits(df, depth_edge) << f;
    edges.edge |= mask_bits(df, edge) << f;
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile::sobel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile::sobel {

HWY_EXPORT(TapTexelsKernel);
HWY_EXPORT(DecodeGridKernel);
HWY_EXPORT(FindEdgesKernel);

void tap_texels(const float* u, const float* v, int count, uint64_t active,
                const TapLayout& layout, FragmentTaps& taps) {
  HWY_DYNAMIC_DISPATCH(TapTexelsKernel)(u, v, count, active, layout, taps);
}

void decode_grid(const Texture2D::TexelView& depth, const Texture2D::TexelView* normal,
                 NormalEncoding encoding, const DepthDecode& decode, NeighbourhoodGrid& grid) {
  HWY_DYNAMIC_DISPATCH(DecodeGridKernel)(depth, normal, encoding, decode, grid);
}

void find_edges(const float* u, const float* v, int count, const FragmentTaps& taps,
                const NeighbourhoodGrid& grid, const EdgeTest& test, FragmentEdges& edges) {
  HWY_DYNAMIC_DISPATCH(FindEdgesKernel)(u, v, count, taps, grid, test, edges);
}

}  // namespace ontile::sobel
#endif  // HWY_ONCE
