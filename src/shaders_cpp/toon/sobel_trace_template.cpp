// The Sobel pass's batch trace from per-class templates (TraceTemplates, sobel_trace_kernel.h):
// on aligned depth and normal planes a full-screen fragment's reads up to its colour sample are
// its class's template plus one offset, written with vector adds and stores instead of a
// granule, compare and pattern test per tap. Integer arithmetic only: every SIMD target records
// the granules of the other kernels.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shaders_cpp/toon/sobel_trace_template.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/lane_bits-inl.h"

#include <bit>

#include "shaders_cpp/toon/sobel_trace_kernel.h"

HWY_BEFORE_NAMESPACE();
namespace ontile::sobel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using ontile::HWY_NAMESPACE::kLaneBit32;
using ontile::HWY_NAMESPACE::mask_bits;

using DU = hn::ScalableTag<uint32_t>;
using VU = hn::Vec<DU>;
using DW = hn::ScalableTag<uint64_t>;

// The last granule of a trace that ends at `end`: a repeat entry's window (right before it)
// ends with the granule its expansion ends with.
HWY_INLINE uint64_t last_granule_before(const uint64_t* end) {
  return is_repeat_entry(end[-1]) ? end[-2] : end[-1];
}

// TraceTemplates::row_reads plus offset at out, its colour reads at color_offset (where they
// are not at the offset) and its repeat entries as they are (the vectors write up to 7 entries
// past the row).
HWY_INLINE void write_row(const TraceTemplates& t, uint64_t offset, uint64_t color_offset,
                          uint64_t* out) {
  const DW dw;
  const size_t wide = hn::Lanes(dw);
  const auto add = hn::Set(dw, offset);
  // Blocks of 8 (row_reads is padded to them), a fixed number of vectors each.
  for (int at = 0; at < t.row_count; at += 8) {
    for (size_t i = 0; i < 8; i += wide) {
      hn::StoreU(hn::Add(hn::Load(dw, t.row_reads + at + i), add), dw, out + at + i);
    }
  }
  for (int k = 0; k < t.row_colors; ++k) out[t.row_color_at[k]] = t.row_color[k] + color_offset;
  for (int r = 0; r < t.row_repeats; ++r) out[t.row_repeat_at[r]] = t.row_repeat[r];
}

HWY_INLINE hn::Mask<DU> lanes_of(DU du, uint64_t bits) {
  const VU word = hn::Set(du, static_cast<uint32_t>(bits & 0xFFFFu));
  return hn::Ne(hn::And(word, hn::Load(du, kLaneBit32)), hn::Zero(du));
}

// The kernel for planes whose colour read is at the offset (kColorAtOffset, as
// TraceTemplates::color_at_offset says) or not: one build each, no test per pair.
template <bool kColorAtOffset>
HWY_INLINE int trace_from_templates(const BatchTracePlanes& planes, const FragmentTaps& taps,
                                    const FragmentEdges& edges, int count, uint64_t active,
                                    uint64_t* out, uint64_t& last_granule) {
  const TraceTemplates& t = planes.templates;
  if (active == 0) return 0;
  const DU du;
  const hn::RebindToSigned<DU> di;
  const size_t lanes = hn::Lanes(du);
  const auto load = [di, du](const int32_t* p) { return hn::BitCast(du, hn::Load(di, p)); };
  // Per fragment: its class and its offset (y * row_granules + x >> column_shift of the
  // centre); per even fragment, the pair template of it and the next.
  alignas(64) uint32_t read_class[kBatchFragments];
  alignas(64) uint32_t pair_key[kBatchFragments];
  alignas(64) uint64_t offset[kBatchFragments];
  alignas(64) uint64_t color_offset[kBatchFragments];  // pairs without color_at_offset
  const DW dw;
  // Lanes widened to 64 bits plus add, stored at to (as many entries as the vector's lanes).
  const auto store_wide = [&](VU v, uint64_t* to) {
#if HWY_TARGET == HWY_SCALAR
    to[0] = hn::GetLane(v);
#else
    const hn::Half<DU> dh;
    const hn::Rebind<uint64_t, decltype(dh)> dw_half;
    hn::Store(hn::PromoteTo(dw_half, hn::LowerHalf(dh, v)), dw_half, to);
    hn::Store(hn::PromoteTo(dw_half, hn::UpperHalf(dh, v)), dw_half, to + hn::Lanes(dh));
#endif
  };
  const VU one = hn::Set(du, 1u);
  const VU not_bit0 = hn::Set(du, ~1u);
  const VU row_granules = hn::Set(du, t.row_granules);
  const VU depth_edge_class = hn::Set(du, 4u);
  // Without a normal plane a depth edge changes no read: one class.
  const uint64_t depth_edges = planes.has_normal ? edges.depth_edge : 0;
  VU misfit = hn::Zero(du);
  // Bit f: fragment f has its partner's offsets (and samples the colour at its centre where
  // the colour read is at the offset).
  uint64_t pairable = 0;
  for (int f = 0; f < count; f += static_cast<int>(lanes)) {
    const VU x1 = load(taps.x[1] + f), y1 = load(taps.y[1] + f);
    const auto rows_fit = hn::And(hn::Eq(load(taps.y[0] + f), hn::Sub(y1, one)),
                                  hn::Eq(load(taps.y[2] + f), hn::Add(y1, one)));
    const VU centre = hn::ShiftRightSame(x1, t.column_shift);
    const VU left = hn::Sub(centre, hn::ShiftRightSame(load(taps.x[0] + f), t.column_shift));
    const VU right = hn::Sub(hn::ShiftRightSame(load(taps.x[2] + f), t.column_shift), centre);
    // Each 0 or 1 (a column left of the centre's granule by more, or right of it, wraps high).
    const auto columns_fit = hn::Eq(hn::And(hn::Or(left, right), not_bit0), hn::Zero(du));
    // Vectors of active lanes only and without depth edges (most) need no lane masks.
    const uint64_t lane_bits = lanes >= 64 ? ~uint64_t{0} : (uint64_t{1} << lanes) - 1;
    const auto fits = hn::And(rows_fit, columns_fit);
    const bool all_on = ((active >> f) & lane_bits) == lane_bits;
    misfit = hn::Or(misfit, hn::VecFromMask(du, all_on ? hn::Not(fits)
                                                       : hn::AndNot(fits, lanes_of(du, active >> f))));
    VU cls = hn::Or(left, hn::ShiftLeft<1>(right));
    if (((depth_edges >> f) & lane_bits) != 0) {
      cls = hn::Or(cls, hn::IfThenElseZero(lanes_of(du, depth_edges >> f), depth_edge_class));
    }
    hn::Store(cls, du, read_class + f);
    const VU fragment_offset = hn::Add(hn::Mul(y1, row_granules), centre);
    store_wide(fragment_offset, offset + f);
#if HWY_TARGET != HWY_SCALAR
    if (t.pairs) {
      const VU color_x = load(taps.color_x + f), color_y = load(taps.color_y + f);
      hn::Store(hn::Or(cls, hn::ShiftLeft<3>(hn::Shuffle2301(cls))), du, pair_key + f);
      const auto one_offset = hn::Eq(fragment_offset, hn::Shuffle2301(fragment_offset));
      if (kColorAtOffset) {
        const auto at_centre = hn::And(hn::Eq(color_x, x1), hn::Eq(color_y, y1));
        pairable |= mask_bits(du, hn::And(at_centre, one_offset)) << f;
      } else {
        const VU own = hn::Add(hn::Mul(color_y, hn::Set(du, t.color_row_granules)),
                               hn::ShiftRightSame(color_x, t.color_column_shift));
        store_wide(own, color_offset + f);
        const auto one_color_offset = hn::Eq(own, hn::Shuffle2301(own));
        pairable |= mask_bits(du, hn::And(one_color_offset, one_offset)) << f;
      }
    }
#endif
  }
  if (!hn::AllTrue(du, hn::Eq(misfit, hn::Zero(du)))) return -1;
  // The first read of a fragment is a depth granule and the read before it a colour or border
  // granule (other tags: never equal) except for the batch's first, compared here.
  const int first = std::countr_zero(active);
  if (t.reads[read_class[first]][0] + offset[first] == last_granule) return -1;
  const size_t wide = hn::Lanes(dw);
  const TracePlane& c = planes.color;
  const TracePlane& b = planes.border;
  const uint64_t border_reads = planes.has_border ? active & edges.edge : 0;
  // Even fragments that start a pair: both active, pairable and without a border read.
  constexpr uint64_t kEven = 0x5555555555555555u;
  const uint64_t no_border = ~(border_reads | (border_reads >> 1));
  const uint64_t pair_starts =
      pairable & (pairable >> 1) & active & (active >> 1) & no_border & kEven;
  int written = 0;
  // Template reads [at, at + 8) plus the offset, at out + written + at.
  const auto block = [&](const uint64_t* reads, hn::Vec<DW> add, int at) {
    for (size_t i = 0; i < 8; i += wide) {
      hn::StoreU(hn::Add(hn::Load(dw, reads + at + i), add), dw, out + written + at + i);
    }
  };
  const auto one_fragment = [&](int f) {
    const uint64_t* const reads = t.reads[read_class[f]];
    const int n = t.read_count[read_class[f]];
    const auto add = hn::Set(dw, offset[f]);
    // Every class has at least 5 reads: a first block always.
    block(reads, add, 0);
    if (n > 8) {
      block(reads, add, 8);
      if (n > 16) block(reads, add, 16);
    }
    written += n;
    // The colour follows a depth or normal read (other tags): always new.
    const uint64_t color_texel = static_cast<uint64_t>(taps.color_y[f]) * c.width +
                                 static_cast<uint64_t>(taps.color_x[f]);
    const uint64_t color = (c.origin + color_texel * c.texel_bytes) >> 6;
    out[written++] = color;
    if ((border_reads >> f) & 1u) {
      const int tap = edges.nearest_tap[f];
      const uint64_t texel = static_cast<uint64_t>(taps.y[tap / kTapsPerAxis][f]) * b.width +
                             static_cast<uint64_t>(taps.x[tap % kTapsPerAxis][f]);
      const uint64_t g = (b.origin + texel * b.texel_bytes) >> 6;
      out[written] = g;
      written += g != color;
    }
  };
  // Pair template `key` at the pair's offset, at out + written; where the colour read is not
  // at the offset, color (the pair's colour granule) over the template's colour reads.
  const auto pair = [&](uint32_t key, hn::Vec<DW> add, uint64_t color) {
    const uint64_t* const reads = t.pair_reads[key];
    const int n = t.pair_count[key];
    block(reads, add, 0);  // every pair has at least 12 reads: two blocks always
    block(reads, add, 8);
    for (int at = 16; at < n; at += 8) block(reads, add, at);
    if (!kColorAtOffset) {
      out[written + t.pair_first_color[key]] = color;
      out[written + n - 1] = color;
    }
    written += n;
  };
  const uint64_t untag_color = c.first_granule();
  // The colour granule of fragment f where it is not at the offset (pairs only).
  const auto own_color = [&](int f) {
    return kColorAtOffset ? uint64_t{0} : untag_color + color_offset[f];
  };
  // Whether the quad row of fragments [first, first + 32) reads row_reads plus its offset:
  // every pair starts a pair template of row_keys, one offset per pixel row.
  const auto row_fits = [&](int first) {
    constexpr uint64_t kRowPairs = 0x55555555u;
    if (((pair_starts >> first) & kRowPairs) != kRowPairs) return false;
    const uint64_t upper = offset[first], lower = upper + t.row_granules;
    for (int q = 0; q < TraceTemplates::kRowQuads; ++q) {
      const int f = first + 4 * q;
      if (pair_key[f] != t.row_keys[q] || pair_key[f + 2] != t.row_keys[q] ||
          offset[f] != upper || offset[f + 2] != lower) {
        return false;
      }
    }
    return true;
  };
  constexpr int kQuadRowFragments = 4 * TraceTemplates::kRowQuads;
  for (int f = 0; f < count; f += 4) {
    // (Rows whose colour is at its own offset need the colour at the centres, which pairable
    // does not test there: those go to trace_regular_batch only.)
    if (kColorAtOffset && t.rows && f % kQuadRowFragments == 0 && f + kQuadRowFragments <= count &&
        row_fits(f)) {
      write_row(t, offset[f], offset[f], out + written);
      written += t.row_count;
      f += kQuadRowFragments - 4;
      continue;
    }
    // A quad whose rows are pairs of one template, the lower row's offset one row on (no
    // edge nearby): both pairs from the template's reads.
    if (((pair_starts >> f) & 5u) == 5u && pair_key[f + 2] == pair_key[f] &&
        offset[f + 2] == offset[f] + t.row_granules) {
      const auto upper = hn::Set(dw, offset[f]);
      pair(pair_key[f], upper, own_color(f));
      pair(pair_key[f], hn::Add(upper, hn::Set(dw, uint64_t{t.row_granules})), own_color(f + 2));
      continue;
    }
    for (int g = f; g < f + 4; g += 2) {
      if ((pair_starts >> g) & 1u) {
        pair(pair_key[g], hn::Set(dw, offset[g]), own_color(g));
        continue;
      }
      if ((active >> g) & 1u) one_fragment(g);
      if ((active >> (g + 1)) & 1u) one_fragment(g + 1);
    }
  }
  // Every read written is new: the last (or, after a repeat entry, its window's) is the trace's
  // last granule.
  last_granule = last_granule_before(out + written);
  return written;
}

int TraceBatchTemplateKernel(const BatchTracePlanes& planes, const FragmentTaps& taps,
                             const FragmentEdges& edges, int count, uint64_t active,
                             uint64_t* out, uint64_t& last_granule) {
  if (!planes.templates.usable) return -1;
  return planes.templates.color_at_offset
             ? trace_from_templates<true>(planes, taps, edges, count, active, out, last_granule)
             : trace_from_templates<false>(planes, taps, edges, count, active, out, last_granule);
}

void WriteRowKernel(const TraceTemplates& t, uint64_t offset, uint64_t color_offset,
                    uint64_t* out) {
  write_row(t, offset, color_offset, out);
}

// Whether every fragment of [first, first + 32) samples the colour at its centre tap.
bool ColorAtCentresKernel(const FragmentTaps& taps, int first) {
  const hn::ScalableTag<int32_t> di;
  auto same = hn::Eq(hn::Zero(di), hn::Zero(di));
  for (int f = first; f < first + 32; f += static_cast<int>(hn::Lanes(di))) {
    same = hn::And(same, hn::And(hn::Eq(hn::Load(di, taps.color_x + f), hn::Load(di, taps.x[1] + f)),
                                 hn::Eq(hn::Load(di, taps.color_y + f), hn::Load(di, taps.y[1] + f))));
  }
  return hn::AllTrue(di, same);
}

}  // namespace HWY_NAMESPACE
}  // namespace ontile::sobel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ontile::sobel {

HWY_EXPORT(TraceBatchTemplateKernel);
HWY_EXPORT(WriteRowKernel);
HWY_EXPORT(ColorAtCentresKernel);

void BatchTracePlanes::prepare_templates() {
  templates.usable = false;
  if (!tags_fit) return;
  // The first read of a fragment (depth) never meets the colour or border read before it, and
  // the colour never meets the depth or normal read before it.
  if (tag[kColor] == tag[kDepth]) return;
  if (has_normal && (tag[kNormal] == tag[kDepth] || tag[kNormal] == tag[kColor])) return;
  if (has_border && tag[kBorder] == tag[kDepth]) return;
  const uint64_t texel_bytes = depth.texel_bytes;
  if (!std::has_single_bit(texel_bytes) || texel_bytes > 64) return;
  const uint64_t row_bytes = texel_bytes * static_cast<uint64_t>(depth.width);
  if (depth.origin % 64 != 0 || row_bytes % 64 != 0 || row_bytes == 0) return;
  if (has_normal && (normal.texel_bytes != texel_bytes || normal.width != depth.width ||
                     normal.origin % 64 != 0)) {
    return;
  }
  TraceTemplates& t = templates;
  t.column_shift = 6 - std::countr_zero(texel_bytes);
  t.row_granules = static_cast<uint32_t>(row_bytes / 64);
  // Rows are whole granules (at least one), so reads of different planes (tags), rows or
  // granule columns differ and a read repeats the one before only at the same place.
  for (int cls = 0; cls < kTemplateClasses; ++cls) {
    const int dx[kTapsPerAxis] = {-(cls & 1), 0, (cls >> 1) & 1};
    int n = 0;
    int previous_plane = -1, previous_dy = 0, previous_dx = 0;
    const auto read = [&](int plane, uint64_t origin, int dy, int column) {
      if (plane == previous_plane && dy == previous_dy && column == previous_dx) return;
      t.reads[cls][n++] = (origin >> 6) + static_cast<uint64_t>(int64_t{dy}) * t.row_granules +
                          static_cast<uint64_t>(int64_t{column});
      previous_plane = plane;
      previous_dy = dy;
      previous_dx = column;
    };
    for (int k = 0; k < kTaps; ++k) {
      read(kDepth, depth.origin, k / kTapsPerAxis - 1, dx[k % kTapsPerAxis]);
    }
    if (has_normal) {
      read(kNormal, normal.origin, 0, 0);
      if ((cls & 4) == 0) {
        for (int k = 0; k < kTaps; ++k) {
          if (k != kCentreTap) read(kNormal, normal.origin, k / kTapsPerAxis - 1, dx[k % kTapsPerAxis]);
        }
      }
    }
    t.read_count[cls] = n;
    for (int i = n; i < kTemplateReads; ++i) t.reads[cls][i] = 0;
  }
  const uint64_t color_row_bytes = color.texel_bytes * static_cast<uint64_t>(color.width);
  t.pairs = color.origin % 64 == 0 && std::has_single_bit(color.texel_bytes) &&
            color.texel_bytes <= 64 && color_row_bytes % 64 == 0 && color_row_bytes != 0;
  t.color_at_offset = t.pairs && color.texel_bytes == texel_bytes && color.width == depth.width;
  t.color_column_shift = t.pairs ? 6 - std::countr_zero(color.texel_bytes) : 0;
  t.color_row_granules = static_cast<uint32_t>(color_row_bytes / 64);
  if (t.pairs) {
    for (int key = 0; key < kTemplateClasses * kTemplateClasses; ++key) {
      int n = 0;
      for (int second = 0; second < 2; ++second) {
        const int cls = second ? key / kTemplateClasses : key % kTemplateClasses;
        for (int i = 0; i < t.read_count[cls]; ++i) t.pair_reads[key][n++] = t.reads[cls][i];
        if (!second) t.pair_first_color[key] = n;
        t.pair_reads[key][n++] = color.origin >> 6;
      }
      t.pair_count[key] = n;
      for (int i = n; i < TraceTemplates::kPairReads; ++i) t.pair_reads[key][i] = 0;
    }
  }
  // Rows: 4-byte depth texels (16 per granule) and colour texels of at least 4 bytes, so that
  // a 16-pixel quad row on a granule reads whole colour granules from its first pixel's on.
  t.rows = t.pairs && texel_bytes == 4 && color.texel_bytes >= 4;
  if (t.rows) prepare_row_template(t, color);
  t.usable = true;
}

int trace_regular_batch(const BatchTracePlanes& planes, const FragmentTaps& taps,
                        const FragmentEdges& edges, uint64_t* granules, uint64_t& last_granule) {
  const TraceTemplates& t = planes.templates;
  constexpr int kQuadRowFragments = 4 * TraceTemplates::kRowQuads;
  constexpr int kGranuleTexels = 16;  // rows: 4-byte texels
  const int x = taps.x[1][0], y = taps.y[1][0];
  if (!t.usable || !t.rows || x % kGranuleTexels != 0) {
    return trace_batch(planes, taps, edges, kBatchFragments, ~uint64_t{0}, granules, last_granule);
  }
  // Fragments whose reads differ from their class without edges.
  const uint64_t edge_reads = (planes.has_normal ? edges.depth_edge : 0) |
                              (planes.has_border ? edges.edge : 0);
  int written = 0;
  for (int first = 0; first < kBatchFragments; first += kQuadRowFragments) {
    const uint64_t quad_row = ((uint64_t{1} << kQuadRowFragments) - 1) << first;
    // Pixel rows y + first / 16 and the next; the first pixel's centre granule column.
    const uint64_t offset = static_cast<uint64_t>(y + first / 16) * t.row_granules +
                            static_cast<uint64_t>(x / kGranuleTexels);
    if ((edge_reads & quad_row) == 0 && t.row_reads[0] + offset != last_granule &&
        HWY_DYNAMIC_DISPATCH(ColorAtCentresKernel)(taps, first)) {
      // The colour at the centres: pixel row y + first / 16 of the colour plane, its granule
      // column the first pixel's (the row starts on a depth granule, so on a colour one).
      const uint64_t color_offset =
          static_cast<uint64_t>(y + first / 16) * t.color_row_granules +
          static_cast<uint64_t>(x >> t.color_column_shift);
      HWY_DYNAMIC_DISPATCH(WriteRowKernel)(t, offset, color_offset, granules + written);
      last_granule = granules[written + t.row_last];
      written += t.row_count;
      continue;
    }
    written += trace_batch(planes, taps, edges, kBatchFragments, quad_row, granules + written,
                           last_granule);
  }
  return written;
}

int trace_batch_template(const BatchTracePlanes& planes, const FragmentTaps& taps,
                         const FragmentEdges& edges, int count, uint64_t active,
                         uint64_t* granules, uint64_t& last_granule) {
  return HWY_DYNAMIC_DISPATCH(TraceBatchTemplateKernel)(planes, taps, edges, count, active,
                                                        granules, last_granule);
}

}  // namespace ontile::sobel
#endif  // HWY_ONCE
