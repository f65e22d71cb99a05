// The texel trace of the Sobel edge pass (sobel_edge_shader.h): per fragment, the texels that
// sampling each tap separately reads, in that order, with the address constants held in
// locals and the granules gathered in a batch-sized buffer, so a tap costs an add, a store
// and a compare, and the thread's trace is appended to once per batch.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "raster/texel_trace.h"
#include "raster/texture.h"
#include "shaders_cpp/toon/sobel_edge_kernel.h"
#include "shaders_cpp/toon/sobel_trace_kernel.h"

namespace ontile::sobel {

class TapTrace {
 public:
  // Reads per fragment: 9 depth taps, 9 normal taps, the colour and the border texel.
  static constexpr int kMaxReadsPerFragment = 2 * kTaps + 2;

  // depth is required; normal and border may be null (not sampled). Records into the thread's
  // texel trace (texel_trace.h), if one is active, when the TapTrace goes out of scope; at most
  // kBatchFragments fragments (and their border reads) may be recorded.
  TapTrace(const Texture2D::TexelView& color, const Texture2D::TexelView& depth,
           const Texture2D::TexelView* normal, const Texture2D::TexelView* border)
      : color_(color), depth_(depth), normal_(normal ? Plane(*normal) : Plane()),
        border_(border ? Plane(*border) : Plane()), has_normal_(normal != nullptr),
        sink_(texel_trace_detail::sink), last_granule_(texel_trace_detail::last_granule) {}
  ~TapTrace() {
    if (!sink_) return;
    sink_->insert(sink_->end(), granules_.data(), granules_.data() + count_);
    texel_trace_detail::last_granule = last_granule_;
  }
  TapTrace(const TapTrace&) = delete;
  TapTrace& operator=(const TapTrace&) = delete;

  // The reads of one fragment up to its colour sample: the 9 depth taps row by row, the normal
  // centre, the other 8 normal taps when all_normals, the colour texel.
  void fragment(const int tx[kTapsPerAxis], const int ty[kTapsPerAxis], int color_x,
                int color_y, bool all_normals) {
    if (!sink_) return;
    // The last granule and the count in locals, so they stay in registers across the stores.
    uint64_t last = last_granule_;
    int count = count_;
    uint64_t* const granules = granules_.data();
    const auto record = [&last, &count, granules](uint64_t byte_address) {
      append_new(byte_address, granules, count, last);
    };
    uint64_t column[kTapsPerAxis], row[kTapsPerAxis];
    for (int a = 0; a < kTapsPerAxis; ++a) {
      column[a] = depth_.column_offset(tx[a]);
      row[a] = depth_.row_address(ty[a]);
    }
    for (int b = 0; b < kTapsPerAxis; ++b) {
      for (int a = 0; a < kTapsPerAxis; ++a) record(row[b] + column[a]);
    }
    if (has_normal_) {
      for (int a = 0; a < kTapsPerAxis; ++a) {
        column[a] = normal_.column_offset(tx[a]);
        row[a] = normal_.row_address(ty[a]);
      }
      record(row[1] + column[1]);
      if (all_normals) {
        for (int b = 0; b < kTapsPerAxis; ++b) {
          for (int a = 0; a < kTapsPerAxis; ++a) {
            if (b != 1 || a != 1) record(row[b] + column[a]);
          }
        }
      }
    }
    record(color_.address(color_x, color_y));
    last_granule_ = last;
    count_ = count;
  }
  // The reads of a whole batch's fragments whose bit is set in active, borders included, in
  // the order fragment() and border() would record them (trace_batch, on SIMD lanes).
  // regular: a whole batch that find_edges_rows took (trace_regular_batch).
  void batch(const BatchTracePlanes& planes, const FragmentTaps& taps, const FragmentEdges& edges,
             int fragment_count, uint64_t active, bool regular) {
    if (!sink_) return;
    uint64_t* const out = granules_.data() + count_;
    count_ += regular && planes.templates.rows
                  ? trace_regular_batch(planes, taps, edges, out, last_granule_)
                  : trace_batch(planes, taps, edges, fragment_count, active, out, last_granule_);
  }
  // The border read of a fragment on an edge, at its nearest tap's texel.
  void border(int x, int y) {
    if (sink_) append_new(border_.address(x, y), granules_.data(), count_, last_granule_);
  }

 private:
  // Texture2D::texel_address of level 0 split into row and column terms: origin +
  // (y * width + x) * bytes = (origin + y * width * bytes) + x * bytes, exactly (integers).
  struct Plane {
    uint64_t origin = 0, row_bytes = 0, texel_bytes = 0;
    Plane() = default;
    explicit Plane(const Texture2D::TexelView& v)
        : origin(v.address),
          row_bytes(static_cast<uint64_t>(v.width) * v.memory_bytes_per_texel),
          texel_bytes(v.memory_bytes_per_texel) {}
    uint64_t row_address(int y) const { return origin + static_cast<uint64_t>(y) * row_bytes; }
    uint64_t column_offset(int x) const { return static_cast<uint64_t>(x) * texel_bytes; }
    uint64_t address(int x, int y) const { return row_address(y) + column_offset(x); }
  };

  // Consecutive reads of one 64-byte granule count once, as record_texel_address merges them
  // (texel_trace.h); branch-free: the granule is always stored, the count moves on if new.
  static void append_new(uint64_t byte_address, uint64_t* granules, int& count,
                         uint64_t& last_granule) {
    const uint64_t granule = byte_address >> 6;
    granules[count] = granule;
    count += granule != last_granule;
    last_granule = granule;
  }

  Plane color_, depth_, normal_, border_;
  bool has_normal_;
  std::vector<uint64_t>* sink_;  // the thread's trace when the TapTrace was made, or null
  uint64_t last_granule_;        // the trace's last granule, carried across the batch
  int count_ = 0;
  std::array<uint64_t, kBatchFragments * kMaxReadsPerFragment + kTraceSlack> granules_;
};

}  // namespace ontile::sobel
