// The Sobel pass's batch trace (see sobel_trace_kernel.h), compiled once per SIMD target by
// Highway's foreach_target: integer address arithmetic only, so every target records the same
// granules.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/toon/sobel_trace_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <bit>

#include "shaders_cpp/toon/sobel_trace_kernel.h"

HWY_BEFORE_NAMESPACE();
namespace ontile::sobel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DU = hn::ScalableTag<uint64_t>;
using VU = hn::Vec<DU>;
using DI = hn::ScalableTag<int32_t>;
using VI = hn::Vec<DI>;

// Bit i for lane i: lane masks from fragment bit words (x86 vectors hold at most 16 lanes).
alignas(64) constexpr uint64_t kLaneBit64[8] = {1, 2, 4, 8, 16, 32, 64, 128};

// Slot of each tap in the 20 reads of a fragment: depth taps 0-8, the normal centre 9, the
// other normal taps 10-17 in row-major order, the colour 18, the border 19.
constexpr int kNormalCentreSlot = kTaps;
constexpr int kColorSlot = 2 * kTaps;
constexpr int kBorderSlot = 2 * kTaps + 1;

// Granules of texel indices idx (zero-extended 32-bit lanes) of a plane: (origin + idx *
// texel_bytes) >> 6, the product exact in 64 bits (idx < 2^31).
struct PlaneLanes {
  VU origin, texel_bytes;
  int shift;  // log2(texel_bytes) when a power of two, else -1
  PlaneLanes(DU du, const TracePlane& p)
      : origin(hn::Set(du, p.origin)), texel_bytes(hn::Set(du, p.texel_bytes)),
        shift(std::has_single_bit(p.texel_bytes) ? std::countr_zero(p.texel_bytes) : -1) {}
  HWY_INLINE VU granule(VU idx) const {
    const VU offset = shift >= 0 ? hn::ShiftLeftSame(idx, shift) : hn::Mul(idx, texel_bytes);
    return hn::ShiftRight<6>(hn::Add(origin, offset));
  }
};

int TraceBatchKernel(const BatchTracePlanes& planes, const FragmentTaps& taps,
                     const FragmentEdges& edges, int count, uint64_t active, uint64_t* out,
                     uint64_t& last_granule) {
  const DI di;
  const DU du;
  const hn::Rebind<uint32_t, DU> du32;
  // Texel indices per tap (depth grid; the normal and border planes share its size) and of
  // the colour, on 32-bit lanes: y * width + x, exact below 2^31.
  alignas(64) int32_t index[kTaps + 1][kBatchFragments];
  const VI depth_width = hn::Set(di, planes.depth.width);
  const VI color_width = hn::Set(di, planes.color.width);
  for (int f = 0; f < count; f += static_cast<int>(hn::Lanes(di))) {
    VI row[kTapsPerAxis], column[kTapsPerAxis];
    for (int a = 0; a < kTapsPerAxis; ++a) {
      row[a] = hn::Mul(hn::Load(di, taps.y[a] + f), depth_width);
      column[a] = hn::Load(di, taps.x[a] + f);
    }
    for (int k = 0; k < kTaps; ++k) {
      hn::Store(hn::Add(row[k / kTapsPerAxis], column[k % kTapsPerAxis]), di, index[k] + f);
    }
    const VI color = hn::Add(hn::Mul(hn::Load(di, taps.color_y + f), color_width),
                             hn::Load(di, taps.color_x + f));
    hn::Store(color, di, index[kTaps] + f);
  }
  // Granules per slot and, per fragment, bit s set where slot s differs from the read before it
  // in the fragment. A read the fragment does not make repeats the granule before it, so it is
  // never kept and the next read compares with the last read that was made.
  alignas(64) uint64_t granule[kTraceSlots][kBatchFragments];
  alignas(64) uint64_t kept[kBatchFragments];
  const PlaneLanes depth(du, planes.depth), normal(du, planes.normal), color(du, planes.color);
  const auto load_index = [&](int k, int f) {
    return hn::PromoteTo(du, hn::LoadU(du32, reinterpret_cast<const uint32_t*>(index[k] + f)));
  };
  for (int f = 0; f < count; f += static_cast<int>(hn::Lanes(du))) {
    VU keep = hn::Zero(du);
    VU previous = depth.granule(load_index(0, f));
    hn::Store(previous, du, granule[0] + f);
    const auto next = [&](VU current, int slot) {
      hn::Store(current, du, granule[slot] + f);
      keep = hn::Or(keep, hn::IfThenElseZero(hn::Ne(current, previous),
                                             hn::Set(du, uint64_t{1} << slot)));
      previous = current;
    };
    for (int k = 1; k < kTaps; ++k) next(depth.granule(load_index(k, f)), k);
    if (planes.has_normal) {
      next(normal.granule(load_index(kCentreTap, f)), kNormalCentreSlot);
      const auto depth_edge = hn::Ne(
          hn::And(hn::Set(du, edges.depth_edge >> f), hn::LoadU(du, kLaneBit64)), hn::Zero(du));
      int slot = kNormalCentreSlot + 1;
      for (int k = 0; k < kTaps; ++k) {
        if (k == kCentreTap) continue;
        next(hn::IfThenElse(depth_edge, previous, normal.granule(load_index(k, f))), slot++);
      }
    }
    next(color.granule(load_index(kTaps, f)), kColorSlot);
    hn::Store(previous, du, granule[kBorderSlot] + f);
    hn::Store(keep, du, kept + f);
  }
  // The border read of fragments on an edge, at the nearest tap's texel.
  if (planes.has_border) {
    const TracePlane& b = planes.border;
    for (uint64_t rest = active & edges.edge; rest != 0; rest &= rest - 1) {
      const int f = std::countr_zero(rest);
      const int tap = edges.nearest_tap[f];
      const uint64_t texel = static_cast<uint64_t>(taps.y[tap / kTapsPerAxis][f]) * b.width +
                             static_cast<uint64_t>(taps.x[tap % kTapsPerAxis][f]);
      const uint64_t g = (b.origin + texel * b.texel_bytes) >> 6;
      granule[kBorderSlot][f] = g;
      if (g != granule[kColorSlot][f]) kept[f] |= uint64_t{1} << kBorderSlot;
    }
  }
  // Fragments in order: the first read compares with the last read of the fragment before.
  int written = 0;
  uint64_t last = last_granule;
  for (uint64_t rest = active; rest != 0; rest &= rest - 1) {
    const int f = std::countr_zero(rest);
    out[written] = granule[0][f];
    written += granule[0][f] != last;
    for (uint64_t slots = kept[f]; slots != 0; slots &= slots - 1) {
      out[written++] = granule[std::countr_zero(slots)][f];
    }
    last = granule[kBorderSlot][f];
  }
  last_granule = last;
  return written;
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile::sobel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile::sobel {

HWY_EXPORT(TraceBatchKernel);

bool BatchTracePlanes::fits_lanes(const Texture2D::TexelView& depth,
                                  const Texture2D::TexelView& color) {
  // Float texels are indexed per channel (4 * texel), so 2^29 texels at most.
  constexpr int64_t kLaneLimit = int64_t{1} << 29;
  return int64_t{depth.width} * depth.height < kLaneLimit &&
         int64_t{color.width} * color.height < kLaneLimit;
}

int trace_batch(const BatchTracePlanes& planes, const FragmentTaps& taps,
                const FragmentEdges& edges, int count, uint64_t active, uint64_t* granules,
                uint64_t& last_granule) {
  if (planes.templates.usable) {
    const int written =
        trace_batch_template(planes, taps, edges, count, active, granules, last_granule);
    if (written >= 0) return written;
  }
  if (planes.tags_fit) {
    return trace_batch_32(planes, taps, edges, count, active, granules, last_granule);
  }
  return trace_batch_64(planes, taps, edges, count, active, granules, last_granule);
}

int trace_batch_64(const BatchTracePlanes& planes, const FragmentTaps& taps,
                   const FragmentEdges& edges, int count, uint64_t active, uint64_t* granules,
                   uint64_t& last_granule) {
  return HWY_DYNAMIC_DISPATCH(TraceBatchKernel)(planes, taps, edges, count, active, granules,
                                                last_granule);
}

}  // namespace ontile::sobel
#endif  // HWY_ONCE
