// The Sobel pass's row template (TraceTemplates::rows, sobel_trace_kernel.h): the reads of an
// edge-free 16-pixel quad row, runs of equal quads folded into repeat entries, built once per
// shader from the class templates.
#include <algorithm>
#include <cstdint>

#include "shaders_cpp/toon/sobel_trace_kernel.h"

namespace ontile::sobel {
namespace {

// A run of quads equal to the one before becomes one repeat entry only from this many repeats
// on. The replay tests a repeat entry's window once (about 6 instructions per entry), against
// about 3 per entry it skips plus about 2 in the stores and the copy into the tile's trace:
// cartoon's quads repeated 5 times pay; universal's, repeated twice, measured 2.8 M
// instructions worse on the demo frame than written whole (session17-sobel.md).
constexpr int kMinRepeats = 3;

// A read of the template: its value less the row's offset, and whether it is a colour read at
// the colour plane's own offset (then its value is less the colour offset instead).
struct RowRead {
  uint64_t value = 0;
  bool own_color = false;
  bool operator==(const RowRead&) const = default;
};

}  // namespace

void prepare_row_template(TraceTemplates& t, const TracePlane& color) {
  constexpr int kQuads = TraceTemplates::kRowQuads;
  constexpr int kQuadReads = 2 * TraceTemplates::kPairReads;
  RowRead quads[kQuads][kQuadReads];
  int sizes[kQuads] = {};
  for (int q = 0; q < kQuads; ++q) {
    // Classes: bit 0 the left column, bit 1 the right one in the neighbouring granule.
    const uint32_t key = q == 0            ? 1u + kTemplateClasses * 0u
                         : q == kQuads - 1 ? 0u + kTemplateClasses * 2u
                                           : 0u;
    t.row_keys[q] = key;
    // Its upper pair, then its lower pair one row on; each fragment's reads, then its colour
    // (pixel 2 q + second of the row, in the colour granule column pixel >> shift on).
    int& size = sizes[q];
    for (int row = 0; row < 2; ++row) {
      for (int second = 0; second < 2; ++second) {
        const uint32_t cls = second ? key / kTemplateClasses : key % kTemplateClasses;
        for (int i = 0; i < t.read_count[cls]; ++i) {
          quads[q][size++] = {t.reads[cls][i] + uint64_t{t.row_granules} * row, false};
        }
        const int pixel = 2 * q + second;
        quads[q][size++] =
            t.color_at_offset
                ? RowRead{(color.origin >> 6) + uint64_t{t.row_granules} * row, false}
                : RowRead{(color.origin >> 6) + uint64_t{t.color_row_granules} * row +
                              static_cast<uint64_t>(pixel >> t.color_column_shift),
                          true};
      }
    }
  }
  int n = 0;
  t.row_repeats = 0;
  t.row_colors = 0;
  const auto append = [&](int q) {
    for (int i = 0; i < sizes[q]; ++i) {
      if (quads[q][i].own_color) {
        t.row_color_at[t.row_colors] = n;
        t.row_color[t.row_colors++] = quads[q][i].value;
        t.row_reads[n++] = 0;  // written over the sum
      } else {
        t.row_reads[n++] = quads[q][i].value;
      }
    }
    t.row_last = n - 1;
  };
  for (int q = 0; q < kQuads;) {
    int run = 1;
    while (q + run < kQuads && sizes[q + run] == sizes[q] &&
           std::equal(quads[q], quads[q] + sizes[q], quads[q + run])) {
      ++run;
    }
    // The repeat entry's window is the quad written just before it: granules only, and its
    // first read (depth) unlike its last (colour), so the expansion is the plain trace.
    const int folded = run - 1 >= kMinRepeats ? run - 1 : 0;
    for (int copy = 0; copy < run - folded; ++copy) append(q);
    if (folded > 0) {
      t.row_repeat_at[t.row_repeats] = n;
      t.row_repeat[t.row_repeats++] =
          repeat_entry(static_cast<uint32_t>(sizes[q]), static_cast<uint32_t>(folded));
      t.row_reads[n++] = 0;  // written over the sum
    }
    q += run;
  }
  t.row_count = n;
  for (int i = n; i < TraceTemplates::kRowReads; ++i) t.row_reads[i] = 0;
}

}  // namespace ontile::sobel
