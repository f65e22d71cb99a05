// The Sobel pass's texel trace for a whole batch on SIMD lanes (Highway, integer arithmetic
// only): the granules each fragment's per-tap sampling reads, in sampling order with
// consecutive repeats dropped, exactly as TapTrace::fragment and TapTrace::border record them.
#pragma once
#include <cstdint>
#include <initializer_list>

#include "raster/texture.h"
#include "shaders_cpp/toon/sobel_edge_kernel.h"

namespace ontile::sobel {

// Texture2D::texel_address of level 0: origin + (y * width + x) * texel_bytes.
struct TracePlane {
  uint64_t origin = 0;
  uint64_t texel_bytes = 0;
  int width = 0, height = 0;
  TracePlane() = default;
  explicit TracePlane(const Texture2D::TexelView& v)
      : origin(v.address), texel_bytes(v.memory_bytes_per_texel), width(v.width),
        height(v.height) {}
  uint64_t first_granule() const { return origin >> 6; }
  uint64_t last_granule() const;  // of the last texel's last byte
};

// Reads per fragment in sampling order: 9 depth taps, the normal centre, the other 8 normal
// taps, the colour, the border.
constexpr int kTraceSlots = 2 * kTaps + 2;

// The read patterns most fragments of a full-screen pass take, as the slots a fragment keeps
// after its first (bit s: slot s differs from the read before it; slots as in trace_batch:
// depth taps 0-8, normal centre 9, other normal taps 10-17, colour 18, border 19), with
// normals: every tap row in one granule of its plane and no edge; the left or the right
// column in the neighbouring granule; a depth edge (no normal taps besides the centre)
// without and with a border read. The 32-bit kernel writes those with gathers.
constexpr int kReadPatterns = 5;
constexpr int kMaxPatternReads = 16;
constexpr uint32_t slot_bits(std::initializer_list<int> slots) {
  uint32_t bits = 0;
  for (int s : slots) bits |= uint32_t{1} << s;
  return bits;
}
inline constexpr uint32_t kReadPatternSlots[kReadPatterns] = {
    slot_bits({3, 6, 9, 10, 13, 15, 18}),
    slot_bits({1, 3, 4, 6, 7, 9, 10, 11, 13, 14, 15, 16, 18}),
    slot_bits({2, 3, 5, 6, 8, 9, 10, 12, 13, 14, 15, 17, 18}),
    slot_bits({3, 6, 9, 18}),
    slot_bits({3, 6, 9, 18, 19})};

// Room a trace_batch output needs beyond count * kTraceSlots: the vector stores of the
// template kernel and the pattern gathers may write up to this many entries past the last read.
constexpr int kTraceSlack = 8;

// A repeat entry of a texture trace, "the `window` entries before me, `repeats` more times",
// in the format of memory/trace_repeats.h (which the shaders layer cannot include; its rules:
// window >= 2 granules right before the entry, in the same tile's trace, no repeat entry among
// them). tests/shaders/sobel_trace_kernel_test.cpp checks that the two agree.
constexpr uint64_t kRepeatEntryBit = uint64_t{1} << 63;
constexpr uint64_t repeat_entry(uint32_t window, uint32_t repeats) {
  return kRepeatEntryBit | uint64_t{window} << 32 | repeats;
}
constexpr bool is_repeat_entry(uint64_t entry) { return (entry & kRepeatEntryBit) != 0; }

// Read classes of the template kernel (trace_batch_template): bit 0, the left tap column lies
// in the granule before the centre's; bit 1, the right one in the granule after; bit 2, a depth
// edge (no normal taps besides the centre).
constexpr int kTemplateClasses = 8;
constexpr int kTemplateReads = 24;  // the most reads of a class (18), padded for vector stores

// For depth and normal planes that start on a granule, whose rows are whole granules and
// whose texels tile a granule (one texel size): the granule of texel (x, y) is origin / 64 +
// y * row_granules + (x >> column_shift), so a fragment whose tap rows are y - 1, y, y + 1 and
// whose tap columns lie in the centre's granule or its neighbours reads, up to its colour
// sample, the granules of its class's template plus y * row_granules + (x >> column_shift).
struct TraceTemplates {
  bool usable = false;  // set by BatchTracePlanes::prepare_tags
  int column_shift = 0;
  uint32_t row_granules = 0;
  // The kept reads of each class (repeats dropped) less the fragment's offset: the planes'
  // origin / 64 + dy * row_granules + dx, modulo 2^64.
  alignas(64) uint64_t reads[kTemplateClasses][kTemplateReads] = {};
  int read_count[kTemplateClasses] = {};
  // Where the colour plane lies as the depth plane does (granule-aligned, one texel size and
  // width), a fragment sampling the colour at its centre texel reads the colour granule at
  // its offset too, and the two fragments of a quad row (one offset) read, with no border
  // read, the pair template of their classes (class 0 + 8 * class 1): both fragments' reads.
  bool pairs = false;
  static constexpr int kPairReads = 40;  // 2 * (18 + 1), a multiple of 8
  alignas(64) uint64_t pair_reads[kTemplateClasses * kTemplateClasses][kPairReads] = {};
  int pair_count[kTemplateClasses * kTemplateClasses] = {};
  // Pairs also where the colour plane starts on a granule and its rows are whole granules but
  // its texels or rows differ from depth's (color_at_offset false): a fragment's colour read
  // is then the colour plane's origin / 64 plus its own colour offset, cy * color_row_granules
  // + (cx >> color_column_shift) (the two fragments of a pair share it), written over the
  // pair template's colour reads, at pair_first_color and the pair's last read.
  bool color_at_offset = false;
  int color_column_shift = 0;
  uint32_t color_row_granules = 0;
  int pair_first_color[kTemplateClasses * kTemplateClasses] = {};
  // With pairs, 4-byte depth texels (16 per granule) and colour texels of 4 bytes or more, a
  // quad row of 16 pixels that starts on a granule, samples the colour at its centres and has
  // no edge reads its quads' pairs in the classes of such a row: the left column of its first
  // pixel and the right column of its last in the neighbouring granules.
  // row_reads: all its reads (upper and lower pair of each quad) less the first pixel's offset,
  // a run of quads equal to the one before them (the middle quads read the same granules)
  // folded into a repeat entry where it is long enough to pay (prepare_row_template);
  // row_repeat_at: where the repeat entries lie, written over the vector stores' sums. Where the
  // colour is not at the offset, its reads are row_color plus the first pixel's colour offset
  // (cy * color_row_granules + (cx >> color_column_shift)), at row_color_at. row_last: where
  // the row's last granule lies.
  bool rows = false;
  static constexpr int kRowQuads = 8;
  static constexpr int kRowReads = 2 * kRowQuads * kPairReads;
  uint32_t row_keys[kRowQuads] = {};
  alignas(64) uint64_t row_reads[kRowReads] = {};
  int row_count = 0;
  int row_repeats = 0;
  int row_repeat_at[kRowQuads] = {};
  uint64_t row_repeat[kRowQuads] = {};
  int row_colors = 0;
  int row_color_at[4 * kRowQuads] = {};
  uint64_t row_color[4 * kRowQuads] = {};
  int row_last = 0;
};

// Builds TraceTemplates::row_reads and the rest of the row template from the pair templates
// (t.rows set, `color` the colour plane), sobel_trace_rows.cpp.
void prepare_row_template(TraceTemplates& t, const TracePlane& color);

// The planes a batch reads. Depth, normal and border share the depth grid's size.
struct BatchTracePlanes {
  TracePlane depth, normal, color, border;
  bool has_normal = false, has_border = false;
  // The 32-bit lane kernel's planes: a granule is origin / 64 + r with r = (origin % 64 +
  // texel offset in bytes) / 64, and the lanes hold r (below 2^26). Planes with one origin
  // (one texture) share a tag and compare their r; planes with different tags never hold the
  // same granule (disjoint ranges). Set by prepare_tags(); tags_fit is false where a plane's
  // bytes reach 2^32 or planes overlap otherwise (the 64-bit kernel runs).
  enum PlaneIndex { kDepth, kNormal, kColor, kBorder, kPlanes };
  bool tags_fit = false;
  uint32_t tag[kPlanes] = {};
  // Per slot, what turns its r back into the granule: its plane's origin / 64.
  uint64_t slot_untag[kTraceSlots] = {};
  // The same per read pattern, for each of its reads (the first, then its kept slots in order).
  alignas(64) uint64_t pattern_untag[kReadPatterns][kMaxPatternReads] = {};
  // The template kernel's tables where the planes allow it (tags_fit, depth, normal and colour
  // with different tags, depth and normal aligned as TraceTemplates says).
  TraceTemplates templates;
  void prepare_tags();  // also prepares templates (prepare_templates)
  void prepare_templates();
  // The lane kernels index texels (and float channels) with 32-bit integers: every plane must
  // hold fewer than 2^29 texels (callers fall back to TapTrace::fragment otherwise).
  static bool fits_lanes(const Texture2D::TexelView& depth, const Texture2D::TexelView& color);
};


// Writes, for each fragment f < count whose bit is set in `active` (in ascending f), the
// granules (byte address / 64) of its reads as sobel_edge_shader.h lists them: the 9 depth
// taps row by row, the normal centre (with a normal plane), the other 8 normal taps where
// depth found no edge, the colour at (color_x, color_y), the border at the nearest tap where
// there is an edge (with a border plane), each skipped when equal to the granule before it
// (`last_granule` before the first; updated). Returns how many entries it wrote to
// `granules` (room for count * kTraceSlots + kTraceSlack): granules and, from the template
// kernels, repeat entries (repeat_entry) whose windows lie in what this call wrote, so
// expand_trace_repeats of the entries gives those granules; last_granule is the last granule
// of that expansion.
int trace_batch(const BatchTracePlanes& planes, const FragmentTaps& taps,
                const FragmentEdges& edges, int count, uint64_t active, uint64_t* granules,
                uint64_t& last_granule);
// trace_batch's two kernels, the same granules: 64-bit lanes for any planes, and 32-bit lanes
// (twice the lanes) for planes whose tags fit (prepare_tags), which trace_batch takes then.
int trace_batch_64(const BatchTracePlanes& planes, const FragmentTaps& taps,
                   const FragmentEdges& edges, int count, uint64_t active, uint64_t* granules,
                   uint64_t& last_granule);
int trace_batch_32(const BatchTracePlanes& planes, const FragmentTaps& taps,
                   const FragmentEdges& edges, int count, uint64_t active, uint64_t* granules,
                   uint64_t& last_granule);
// The same granules (edge-free quad rows folded, TraceTemplates::row_reads) from the class
// templates (TraceTemplates) for batches whose active fragments all fit them (tap rows y - 1,
// y, y + 1, tap columns within a granule of the centre's) and whose first read is new; returns
// -1, writing nothing of use and leaving last_granule, for any other batch or planes without
// usable templates.
int trace_batch_template(const BatchTracePlanes& planes, const FragmentTaps& taps,
                         const FragmentEdges& edges, int count, uint64_t active,
                         uint64_t* granules, uint64_t& last_granule);
// trace_batch for a whole batch that find_edges_rows took (every fragment active, 16x4 pixels
// in quad order, taps each pixel's neighbours): a quad row that starts on a granule, samples the
// colour at its centres and has no depth edge or border read is written from the row template
// (TraceTemplates::rows) at its offset, with no per-fragment pass; other quad rows as
// trace_batch writes them.
int trace_regular_batch(const BatchTracePlanes& planes, const FragmentTaps& taps,
                        const FragmentEdges& edges, uint64_t* granules, uint64_t& last_granule);

}  // namespace ontile::sobel
