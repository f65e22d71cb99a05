// Batched main-light shadow lookups (see main_light_shadows_batch.h), compiled per SIMD target by
// Highway's foreach_target: IEEE multiply, add, compare, truncating conversion and gathers only,
// so every target gives the bits of the scalar main_light_visibility.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipelines/universal/main_light_shadows_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/lane_bits-inl.h"

#include <bit>
#include <cstring>
#include <vector>

#include "pipelines/universal/main_light_shadows_batch.h"
#include "raster/texel_trace.h"

HWY_BEFORE_NAMESPACE();
namespace ontile {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;

void ShadowBatchKernel(const ShadowLookup& s, const float* x, const float* y, const float* z,
                       const float (&normal)[3][kBatchFragments], glm::vec3 to_light, int count,
                       ShadowBatch& out) {
  const DF df;
  const DI di;
  const Texture2D::TexelView& map = s.texels;
  const int w = map.width, h = map.height;
  // Float texels: a 32-bit surface's bytes, or RGBA float texels (depth in .x).
  const float* texels = map.texels32f ? map.texels32f : reinterpret_cast<const float*>(map.surface_bytes);
  const int float_stride = map.texels32f ? 4 : 1;
  const glm::mat4& m = s.world_to_shadow;
  // The scalar path's to_light * depth_bias_world, per component.
  const auto lift_x = hn::Set(df, to_light.x * s.depth_bias_world);
  const auto lift_y = hn::Set(df, to_light.y * s.depth_bias_world);
  const auto lift_z = hn::Set(df, to_light.z * s.depth_bias_world);
  const auto lx = hn::Set(df, to_light.x), ly = hn::Set(df, to_light.y), lz = hn::Set(df, to_light.z);
  const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f);
  const auto normal_bias = hn::Set(df, s.normal_bias_world);
  const auto strength = hn::Set(df, s.strength);
  const auto nine = hn::Set(df, 9.0f);
  const auto w_f = hn::Set(df, static_cast<float>(w)), h_f = hn::Set(df, static_cast<float>(h));
  const auto last_x = hn::Set(di, w - 1), last_y = hn::Set(di, h - 1), zero_i = hn::Zero(di);
  const auto width_i = hn::Set(di, w);
  const auto bytes_per_texel = hn::Set(di, static_cast<int32_t>(map.memory_bytes_per_texel));
  const auto stride = hn::Set(di, float_stride);
  out.inside = 0;
  for (size_t f = 0; f < static_cast<size_t>(count); f += hn::Lanes(df)) {
    const auto nx = hn::LoadU(df, normal[0] + f), ny = hn::LoadU(df, normal[1] + f),
               nz = hn::LoadU(df, normal[2] + f);
    // glm::dot: (x + y) + z of the products; std::clamp(v, 0, 1) keeps NaN.
    const auto dot = hn::Add(hn::Add(hn::Mul(nx, lx), hn::Mul(ny, ly)), hn::Mul(nz, lz));
    const auto n_dot_l = hn::IfThenElse(hn::Lt(dot, zero), zero, hn::IfThenElse(hn::Lt(one, dot), one, dot));
    const auto k = hn::Mul(normal_bias, hn::Sub(one, n_dot_l));
    const auto bx = hn::Add(hn::Add(hn::LoadU(df, x + f), lift_x), hn::Mul(nx, k));
    const auto by = hn::Add(hn::Add(hn::LoadU(df, y + f), lift_y), hn::Mul(ny, k));
    const auto bz = hn::Add(hn::Add(hn::LoadU(df, z + f), lift_z), hn::Mul(nz, k));
    // glm's mat4 * vec4: (m0 * x + m1 * y) + (m2 * z + m3 * 1).
    const auto row = [&](int r) {
      return hn::Add(hn::Add(hn::Mul(hn::Set(df, m[0][r]), bx), hn::Mul(hn::Set(df, m[1][r]), by)),
                     hn::Add(hn::Mul(hn::Set(df, m[2][r]), bz), hn::Mul(hn::Set(df, m[3][r]), one)));
    };
    const auto px = row(0), py = row(1), pz = row(2);
    const auto inside = hn::And(
        hn::And(hn::And(hn::Ge(px, zero), hn::Le(px, one)), hn::And(hn::Ge(py, zero), hn::Le(py, one))),
        hn::And(hn::Ge(pz, zero), hn::Le(pz, one)));
    // Lanes outside read texel (0, 0) and are overridden below (the scalar path reads nothing).
    const auto cx = hn::Min(hn::ConvertTo(di, hn::Mul(hn::IfThenElseZero(inside, px), w_f)), last_x);
    const auto cy = hn::Min(hn::ConvertTo(di, hn::Mul(hn::IfThenElseZero(inside, py), h_f)), last_y);
    hn::Vec<DI> xs[3], rows[3];
    for (int d = 0; d < 3; ++d) {
      xs[d] = hn::Min(hn::Max(hn::Add(cx, hn::Set(di, d - 1)), zero_i), last_x);
      rows[d] = hn::Mul(hn::Min(hn::Max(hn::Add(cy, hn::Set(di, d - 1)), zero_i), last_y), width_i);
    }
    auto lit = hn::Zero(df);
    auto changes = zero_i, previous = zero_i;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        const int tap = r * 3 + c;
        const auto texel = hn::Add(rows[r], xs[c]);
        const auto depth = hn::GatherIndex(df, texels, hn::Mul(texel, stride));
        lit = hn::Add(lit, hn::IfThenElseZero(hn::Le(pz, depth), one));
        const auto granule =
            hn::BitCast(di, hn::ShiftRight<6>(hn::BitCast(hn::RebindToUnsigned<DF>(), hn::Mul(texel, bytes_per_texel))));
        hn::StoreU(granule, di, reinterpret_cast<int32_t*>(out.granule_offset[tap]) + f);
        if (tap > 0) changes = hn::Or(changes, hn::IfThenElseZero(hn::Ne(granule, previous), hn::Set(di, 1 << (tap - 1))));
        previous = granule;
      }
    }
    hn::StoreU(changes, di, out.tap_changes + f);
    const auto visibility = hn::Sub(one, hn::Mul(strength, hn::Sub(one, hn::Div(lit, nine))));
    hn::StoreU(hn::IfThenElse(inside, visibility, one), df, out.visibility + f);
    out.inside |= mask_bits(df, inside) << f;
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile {

HWY_EXPORT(ShadowBatchKernel);

bool shadow_batch_supported(const ShadowLookup& s) {
  const Texture2D::TexelView& map = s.texels;
  if (!s.map || map.width <= 0 || map.height <= 0 || map.address % 64 != 0) return false;
  const bool float_surface = map.surface_bytes && (map.surface_format == PixelFormat::D32_FLOAT ||
                                                   map.surface_format == PixelFormat::R32_FLOAT);
  if (!map.texels32f && !float_surface) return false;
  // Texel byte offsets and float indices stay below 2^31.
  const int64_t texels = int64_t{map.width} * map.height;
  return texels * static_cast<int64_t>(std::max<uint64_t>(map.memory_bytes_per_texel, 4)) < (int64_t{1} << 31);
}

void main_light_visibility_batch(const ShadowLookup& lookup, const float* x, const float* y,
                                 const float* z, const float (&normal)[3][kBatchFragments],
                                 glm::vec3 to_light, int count, ShadowBatch& out) {
  HWY_DYNAMIC_DISPATCH(ShadowBatchKernel)(lookup, x, y, z, normal, to_light, count, out);
}

// tap_changes of a footprint whose rows each lie in one granule, the rows in different ones
// (taps 3 and 6 start new granules): most lookups away from granule edges.
constexpr int32_t kRowChanges = (1 << 2) | (1 << 5);

int shadow_quad_granules(const ShadowLookup& lookup, const ShadowBatch& batch, int q, unsigned lanes,
                         uint64_t* granules, uint64_t& last) {
  const uint64_t base = lookup.texels.address >> 6;
  int kept = 0;
  const unsigned read = lanes & static_cast<unsigned>(batch.inside >> (q * kQuadLanes)) & 0xFu;
  // Tap 0 is kept unless it repeats the trace's last granule; taps 1..8 where tap_changes says
  // they differ from the tap before (the compaction of record_texel_address, precomputed).
  for (unsigned rest = read; rest != 0; rest &= rest - 1) {
    const int f = q * kQuadLanes + std::countr_zero(rest);
    const uint64_t first = base + batch.granule_offset[0][f];
    granules[kept] = first;
    kept += first != last;
    if (batch.tap_changes[f] == kRowChanges) {  // the common footprint, without the bit loop
      granules[kept] = base + batch.granule_offset[3][f];
      granules[kept + 1] = base + batch.granule_offset[6][f];
      kept += 2;
      last = base + batch.granule_offset[kShadowTaps - 1][f];
      continue;
    }
    for (uint32_t changes = static_cast<uint32_t>(batch.tap_changes[f]); changes != 0; changes &= changes - 1) {
      granules[kept++] = base + batch.granule_offset[std::countr_zero(changes) + 1][f];
    }
    last = base + batch.granule_offset[kShadowTaps - 1][f];
  }
  return kept;
}

void trace_shadow_quad(const ShadowLookup& lookup, const ShadowBatch& batch, int q, unsigned lanes) {
  std::vector<uint64_t>* const sink = texel_trace_detail::sink;
  if (!sink) return;
  uint64_t granules[kMaxShadowQuadGranules];
  const int kept = shadow_quad_granules(lookup, batch, q, lanes, granules, texel_trace_detail::last_granule);
  sink->insert(sink->end(), granules, granules + kept);
}

}  // namespace ontile
#endif  // HWY_ONCE
