// The Sobel pass's batch trace (sobel_trace_kernel.h) on 32-bit lanes, for planes whose tags
// fit (BatchTracePlanes::prepare_tags): twice the lanes of the 64-bit kernel, each granule an
// add and a shift from per-row and per-column terms, and the common per-fragment read patterns
// written with gathers. Integer arithmetic only, so every SIMD target records the same granules.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/toon/sobel_trace32_kernel.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/lane_bits-inl.h"

#include <bit>
#include <cstring>

#include "shaders_cpp/toon/sobel_trace_kernel.h"

HWY_BEFORE_NAMESPACE();
namespace ontile::sobel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using ontile::HWY_NAMESPACE::kLaneBit32;
using ontile::HWY_NAMESPACE::mask_bits;

using DU = hn::ScalableTag<uint32_t>;
using VU = hn::Vec<DU>;

// Slots of a fragment's 20 reads, as in the 64-bit kernel: depth taps 0-8, the normal centre
// 9, the other normal taps 10-17 in row-major order, the colour 18, the border 19.
constexpr int kNormalCentreSlot = kTaps;
constexpr int kColorSlot = 2 * kTaps;
constexpr int kBorderSlot = 2 * kTaps + 1;

// Cells of each read pattern's reads (the first, then the kept slots in order) in the slot
// table (slot * kBatchFragments), and how many there are; unused cells read slot 0.
struct PatternCells {
  alignas(64) int32_t offset[kReadPatterns][kMaxPatternReads] = {};
  int reads[kReadPatterns] = {};
  constexpr PatternCells() {
    for (int p = 0; p < kReadPatterns; ++p) {
      int n = 1;
      for (int s = 1; s < kTraceSlots; ++s) {
        if ((kReadPatternSlots[p] >> s) & 1u) offset[p][n++] = s * kBatchFragments;
      }
      reads[p] = n;
    }
  }
};
constexpr PatternCells kPatternCells;
// The read patterns as the kernel's kept words (slot s at bit kBorderSlot - s).
constexpr uint32_t kept_word(uint32_t slot_bits) {
  uint32_t word = 0;
  for (int s = 0; s < kTraceSlots; ++s) {
    if ((slot_bits >> s) & 1u) word |= uint32_t{1} << (kBorderSlot - s);
  }
  return word;
}
constexpr uint32_t kPatternKept[kReadPatterns] = {
    kept_word(kReadPatternSlots[0]), kept_word(kReadPatternSlots[1]),
    kept_word(kReadPatternSlots[2]), kept_word(kReadPatternSlots[3]),
    kept_word(kReadPatternSlots[4])};
// The depth-edge pattern; the next is the same with the border read.
constexpr uint32_t kDepthEdgePattern = 3;
static_assert(kReadPatternSlots[kDepthEdgePattern + 1] ==
              (kReadPatternSlots[kDepthEdgePattern] | (uint32_t{1} << kBorderSlot)));

// Granules of a plane less its first (origin / 64) on 32-bit lanes: (origin % 64 + y *
// row_bytes + x * texel_bytes) >> 6, exact when the byte offsets fit 32 bits (prepare_tags).
struct PlaneLanes32 {
  VU origin_offset, row_bytes, texel_bytes;
  PlaneLanes32(DU du, const TracePlane& p)
      : origin_offset(hn::Set(du, static_cast<uint32_t>(p.origin & 63u))),
        row_bytes(hn::Set(du, static_cast<uint32_t>(p.texel_bytes * static_cast<uint64_t>(p.width)))),
        texel_bytes(hn::Set(du, static_cast<uint32_t>(p.texel_bytes))) {}
  HWY_INLINE VU row_term(VU y) const { return hn::Add(hn::Mul(y, row_bytes), origin_offset); }
  HWY_INLINE VU column_term(VU x) const { return hn::Mul(x, texel_bytes); }
  HWY_INLINE VU granule(VU row, VU column) const {
    return hn::ShiftRight<6>(hn::Add(row, column));
  }
};

// Writes `reads` granules of fragment f: table[offsets[i] + f] (its r) plus untag[i], with
// gathers of up to 8 lanes (offsets and untag hold a multiple of 8 entries; the vectors may
// write up to 7 entries past `reads`).
HWY_INLINE void gather_reads(const uint32_t* table, int f, const int32_t* offsets,
                             const uint64_t* untag, int reads, uint64_t* out) {
#if HWY_TARGET == HWY_SCALAR
  for (int i = 0; i < reads; ++i) out[i] = untag[i] + table[offsets[i] + f];
#else
  const hn::CappedTag<uint32_t, 8> dg;
  const hn::RebindToSigned<decltype(dg)> dgi;
  const hn::Half<decltype(dg)> dh;
  const hn::Rebind<uint64_t, decltype(dh)> dw;
  const size_t half = hn::Lanes(dh);
  const auto fragment = hn::Set(dgi, f);
  for (int i = 0; i < reads; i += static_cast<int>(hn::Lanes(dg))) {
    const auto r = hn::GatherIndex(dg, table, hn::Add(hn::Load(dgi, offsets + i), fragment));
    hn::StoreU(hn::Add(hn::PromoteTo(dw, hn::LowerHalf(dh, r)), hn::Load(dw, untag + i)), dw,
               out + i);
    hn::StoreU(hn::Add(hn::PromoteTo(dw, hn::UpperHalf(dh, r)),
                       hn::Load(dw, untag + i + half)),
               dw, out + i + half);
  }
#endif
}

int TraceBatch32Kernel(const BatchTracePlanes& planes, const FragmentTaps& taps,
                       const FragmentEdges& edges, int count, uint64_t active, uint64_t* out,
                       uint64_t& last_granule) {
  const DU du;
  const size_t lanes = hn::Lanes(du);
  // Per slot, the granule less the first granule of its plane (origin / 64) and, per
  // fragment, the slots that differ from the read before them in the fragment, slot s at bit
  // kBorderSlot - s. A read the fragment does not make repeats the granule before it, so it
  // is never kept and the next read compares with the last read that was made. Reads of two
  // planes compare only where the planes share a tag (one texture); otherwise their granules
  // never meet (prepare_tags).
  alignas(64) uint32_t granule[kTraceSlots][kBatchFragments];
  alignas(64) uint32_t kept[kBatchFragments];
  alignas(64) uint32_t pattern[kBatchFragments];  // read pattern index, kReadPatterns for none
  uint64_t pattern0 = 0;  // bit f: fragment f has read pattern 0
  using P = BatchTracePlanes;
  const PlaneLanes32 depth(du, planes.depth), normal(du, planes.normal), color(du, planes.color);
  const bool normal_meets_depth = planes.tag[P::kNormal] == planes.tag[P::kDepth];
  const int color_follows = planes.has_normal ? P::kNormal : P::kDepth;
  const bool color_meets_before = planes.tag[P::kColor] == planes.tag[color_follows];
  const auto load = [du](const int32_t* p) {
    return hn::BitCast(du, hn::Load(hn::RebindToSigned<DU>(), p));
  };
  for (int f = 0; f < count; f += static_cast<int>(lanes)) {
    VU y[kTapsPerAxis], x[kTapsPerAxis], row[kTapsPerAxis], column[kTapsPerAxis];
    for (int a = 0; a < kTapsPerAxis; ++a) {
      y[a] = load(taps.y[a] + f);
      x[a] = load(taps.x[a] + f);
      row[a] = depth.row_term(y[a]);
      column[a] = depth.column_term(x[a]);
    }
    // repeats = 2 repeats + (1 where the read equals the one before): the earliest slot ends
    // in the highest bit, with an add, a compare and a subtract per slot.
    VU repeats = hn::Zero(du);
    VU previous = depth.granule(row[0], column[0]);
    hn::Store(previous, du, granule[0] + f);
    const auto next = [&](VU current, int slot, bool comparable) {
      hn::Store(current, du, granule[slot] + f);
      repeats = hn::Add(repeats, repeats);
      if (comparable) repeats = hn::Sub(repeats, hn::VecFromMask(du, hn::Eq(current, previous)));
      previous = current;
    };
    for (int k = 1; k < kTaps; ++k) {
      next(depth.granule(row[k / kTapsPerAxis], column[k % kTapsPerAxis]), k, true);
    }
    if (planes.has_normal) {
      for (int a = 0; a < kTapsPerAxis; ++a) {
        row[a] = normal.row_term(y[a]);
        column[a] = normal.column_term(x[a]);
      }
      next(normal.granule(row[1], column[1]), kNormalCentreSlot, normal_meets_depth);
      const VU edge_bits = hn::Set(du, static_cast<uint32_t>((edges.depth_edge >> f) & 0xFFFFu));
      const auto depth_edge = hn::Ne(hn::And(edge_bits, hn::Load(du, kLaneBit32)), hn::Zero(du));
      int slot = kNormalCentreSlot + 1;
      for (int k = 0; k < kTaps; ++k) {
        if (k == kCentreTap) continue;
        const VU g = normal.granule(row[k / kTapsPerAxis], column[k % kTapsPerAxis]);
        next(hn::IfThenElse(depth_edge, previous, g), slot++, true);
      }
    } else {
      // No normal reads: slots 9-17 repeat the read before.
      constexpr int kSkipped = kColorSlot - kNormalCentreSlot;
      repeats = hn::Or(hn::ShiftLeft<kSkipped>(repeats), hn::Set(du, (1u << kSkipped) - 1));
    }
    const VU color_row = color.row_term(load(taps.color_y + f));
    next(color.granule(color_row, color.column_term(load(taps.color_x + f))), kColorSlot,
         color_meets_before);
    // Kept: the slots 1-18 that are no repeat, slot s at bit kBorderSlot - s.
    constexpr uint32_t kSlotsBits = (1u << (kColorSlot)) - 1;  // slots 1-18 in repeats
    const VU kept_slots = hn::ShiftLeft<1>(hn::AndNot(repeats, hn::Set(du, kSlotsBits)));
    hn::Store(kept_slots, du, kept + f);
    VU pattern_of = hn::Set(du, uint32_t{kReadPatterns});
    for (int p = 0; p < kReadPatterns; ++p) {
      pattern_of = hn::IfThenElse(hn::Eq(kept_slots, hn::Set(du, kPatternKept[p])),
                                  hn::Set(du, static_cast<uint32_t>(p)), pattern_of);
    }
    hn::Store(pattern_of, du, pattern + f);
    pattern0 |= mask_bits(du, hn::Eq(pattern_of, hn::Zero(du))) << f;
  }
  // The border read of fragments on an edge, at the nearest tap's texel.
  const uint64_t* const untag = planes.slot_untag;
  if (planes.has_border) {
    const TracePlane& b = planes.border;
    for (uint64_t rest = active & edges.edge; rest != 0; rest &= rest - 1) {
      const int f = std::countr_zero(rest);
      const int tap = edges.nearest_tap[f];
      const uint64_t texel = static_cast<uint64_t>(taps.y[tap / kTapsPerAxis][f]) * b.width +
                             static_cast<uint64_t>(taps.x[tap % kTapsPerAxis][f]);
      const uint64_t g = (b.origin + texel * b.texel_bytes) >> 6;
      granule[kBorderSlot][f] = static_cast<uint32_t>(g - untag[kBorderSlot]);
      if (g != untag[kColorSlot] + granule[kColorSlot][f]) {
        kept[f] |= 1u;  // slot kBorderSlot
        // Only the depth-edge pattern has a bordered twin; the others have no border read.
        pattern[f] = pattern[f] == kDepthEdgePattern ? kDepthEdgePattern + 1 : kReadPatterns;
        pattern0 &= ~(uint64_t{1} << f);
      }
    }
  }
  // Fragments in order: the first read compares with the last read of the fragment before.
  // A fragment of a read pattern whose first read is new writes its granules with gathers
  // from the slot table (vectors of up to 8; the last may write past its reads, into room
  // the next fragments overwrite).
  const uint64_t untag_depth = untag[0], untag_color = untag[kColorSlot];
  const uint32_t* const table = &granule[0][0];
  // Fragments of read pattern 0 (bit f). Its last read is the colour texel: where the colour
  // and depth planes have different tags their granules never meet, so the first read of the
  // pattern-0 fragments after one (in a run) is always new: the run is written with no
  // compares, the first of the run compared with the read before it.
  if (planes.tag[P::kDepth] == planes.tag[P::kColor]) pattern0 = 0;
  int written = 0;
  uint64_t last = last_granule;
  for (uint64_t rest = active; rest != 0; rest &= rest - 1) {
    const int f = std::countr_zero(rest);
    const uint64_t first = untag_depth + granule[0][f];
    const uint32_t p = pattern[f];
    if (p == 0 && first != last) {
      // This fragment and the pattern-0 fragments after it up to the next other one.
      const uint64_t others = rest & ~pattern0;
      const uint64_t run = others == 0 ? rest : rest & ((others & (0 - others)) - 1);
      if (pattern0 >> f & 1u) {
        int f_last = f;
        for (uint64_t in_run = run; in_run != 0; in_run &= in_run - 1) {
          f_last = std::countr_zero(in_run);
          gather_reads(table, f_last, kPatternCells.offset[0], planes.pattern_untag[0],
                       kPatternCells.reads[0], out + written);
          written += kPatternCells.reads[0];
        }
        last = untag_color + granule[kColorSlot][f_last];
        rest &= ~run | (uint64_t{1} << f_last);  // the loop's step drops f_last
        continue;
      }
      gather_reads(table, f, kPatternCells.offset[0], planes.pattern_untag[0],
                   kPatternCells.reads[0], out + written);
      written += kPatternCells.reads[0];
      last = untag_color + granule[kColorSlot][f];
      continue;
    }
    if (p < kReadPatterns && first != last) {
      gather_reads(table, f, kPatternCells.offset[p], planes.pattern_untag[p],
                   kPatternCells.reads[p], out + written);
      written += kPatternCells.reads[p];
      last = out[written - 1];
      continue;
    }
    out[written] = first;
    written += first != last;
    last = first;
    for (uint32_t slots = kept[f]; slots != 0;) {
      const int bit = 31 - std::countl_zero(slots);  // the earliest slot left
      slots ^= uint32_t{1} << bit;
      const int slot = kBorderSlot - bit;
      last = untag[slot] + granule[slot][f];
      out[written++] = last;
    }
  }
  last_granule = last;
  return written;
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile::sobel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile::sobel {

HWY_EXPORT(TraceBatch32Kernel);

uint64_t TracePlane::last_granule() const {
  return (origin + texel_bytes * static_cast<uint64_t>(width) * static_cast<uint64_t>(height) - 1) >> 6;
}

void BatchTracePlanes::prepare_tags() {
  // r stays below 2^26 (byte offsets below 2^32); tags only tell planes apart.
  constexpr uint64_t kByteLimit = uint64_t{1} << 32;
  const TracePlane* const plane[kPlanes] = {&depth, has_normal ? &normal : nullptr, &color,
                                            has_border ? &border : nullptr};
  tags_fit = false;
  templates.usable = false;
  uint32_t next_tag = 0;
  for (int p = 0; p < kPlanes; ++p) {
    if (!plane[p]) continue;
    const TracePlane& a = *plane[p];
    const uint64_t bytes = a.texel_bytes * static_cast<uint64_t>(a.width) * a.height;
    if (a.texel_bytes == 0 || (a.origin & 63u) + bytes >= kByteLimit) return;
    int shared = -1;
    for (int q = 0; q < p; ++q) {
      if (!plane[q]) continue;
      const TracePlane& b = *plane[q];
      if (a.origin == b.origin) {
        // One texture twice: one tag when its texels map to the same bytes.
        if (a.texel_bytes != b.texel_bytes || a.width != b.width) return;
        shared = q;
      } else if (a.first_granule() <= b.last_granule() && b.first_granule() <= a.last_granule()) {
        return;  // overlapping planes at different origins: granules could meet untagged
      }
    }
    if (shared >= 0) {
      tag[p] = tag[shared];
    } else {
      tag[p] = next_tag;
      ++next_tag;
    }
  }
  const TracePlane* const by_index[kPlanes] = {&depth, &normal, &color, &border};
  for (int s = 0; s < kTraceSlots; ++s) {
    const int index = s < kTaps ? kDepth : s < 2 * kTaps ? kNormal : s == 2 * kTaps ? kColor : kBorder;
    slot_untag[s] = by_index[index]->first_granule();
  }
  for (int p = 0; p < kReadPatterns; ++p) {
    int n = 0;
    for (int s = 0; s < kTraceSlots; ++s) {
      if (s == 0 || ((kReadPatternSlots[p] >> s) & 1u)) pattern_untag[p][n++] = slot_untag[s];
    }
  }
  tags_fit = true;
  prepare_templates();
}

int trace_batch_32(const BatchTracePlanes& planes, const FragmentTaps& taps,
                   const FragmentEdges& edges, int count, uint64_t active, uint64_t* granules,
                   uint64_t& last_granule) {
  return HWY_DYNAMIC_DISPATCH(TraceBatch32Kernel)(planes, taps, edges, count, active, granules,
                                                  last_granule);
}

}  // namespace ontile::sobel
#endif  // HWY_ONCE
