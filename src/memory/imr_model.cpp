// The IMR comparison model (see imr_model.h): replays the recorded fragment accesses in
// submission order through a render-target cache in front of external memory and counts the
// bytes each attachment moves.
//
// Rules, and why:
// - Every attachment lives in external memory, transient ones included: an IMR has no tile
//   memory to keep an attachment on chip for the whole pass.
// - Surface layout: each attachment has its own address range, base line-aligned, one after the
//   other in attachment order. Inside it, pixels are linear row-major and a pixel's samples are
//   adjacent (byte offset ((y * width + x) * samples + s) * bytes_per_pixel), the same layout
//   as tiler/surface.h. A fragment touches the lines holding the bytes of its samples.
// - Load actions: Load reads nothing up front (lines are filled on first access); Clear writes
//   the whole attachment once (width * height * samples * bytes_per_pixel bytes; fast-clear
//   metadata is not modelled) straight to memory, so the cleared lines are not in the cache;
//   DontCare costs nothing.
// - Replay order: all tiles' fragment lists are merged by triangle_ref (submission order); for
//   one triangle the tiles come in tile-index order, each with its own fragment order. This is
//   a block-rasterizing IMR walking the triangle, and it does not depend on thread count.
// - Per fragment, in pipeline order: the depth test reads the covered samples (kDepthRead),
//   the depth write writes the written samples (kDepthWritten); then for every colour output
//   of the fragment's subpass, blending reads the written samples (kColorRead) and the colour
//   write writes them (kColorWritten).
// - Cache: write-back, write-allocate with fill: a write miss reads the whole line before the
//   write. A ROP cache with per-byte valid masks could skip the fill for fully overwritten
//   lines; this model does not, so its write traffic is an upper bound for such hardware.
//   Replacement is LRU within a set; the cache starts empty each pass.
// - End of pass: the cache is flushed and every dirty line is written back, whatever the store
//   action: the hardware cannot discard dirty render-target lines, so StoreAction::DontCare
//   saves nothing on an IMR.
// - Resolve (Resolve / StoreAndResolve): a separate pass after the flush reads all samples from
//   memory (width * height * samples * bytes_per_pixel) and writes the resolved pixels
//   (width * height * bytes_per_pixel), bypassing the render-target cache; both count to the
//   attachment (the write also in bytes_resolved).
#include "memory/imr_model.h"

#include <bit>
#include <functional>
#include <queue>
#include <string>
#include <utility>

#include "memory/set_associative_cache.h"
#include "util/error.h"

namespace ontile {
namespace {

void validate_config(const RenderTargetCacheConfig& c) {
  const std::string what = "render-target cache (" + std::to_string(c.size_bytes) + " bytes, " +
                           std::to_string(c.line_bytes) + "-byte lines, " +
                           std::to_string(c.ways) + " ways): ";
  if (c.line_bytes == 0 || !std::has_single_bit(c.line_bytes)) {
    throw Error(what + "line size must be a power of two");
  }
  if (c.ways == 0) throw Error(what + "needs at least one way");
  const uint64_t set_bytes = uint64_t{c.line_bytes} * c.ways;
  if (c.size_bytes == 0 || c.size_bytes % set_bytes != 0) {
    throw Error(what + "size must be a positive multiple of line size * ways");
  }
}

// The render-target cache: the shared set-associative cache, its lines owned by attachments so
// write-backs are charged to them.
class RenderTargetCache {
 public:
  RenderTargetCache(const RenderTargetCacheConfig& config, ImrTraffic& traffic)
      : line_bytes_(config.line_bytes),
        cache_(static_cast<uint32_t>(config.size_bytes / (uint64_t{config.line_bytes} * config.ways)),
               config.ways, 0),
        traffic_(traffic) {}

  void access(uint64_t line_address, int attachment, bool write) {
    SetAssociativeCache::WriteBack evicted;
    if (cache_.access_line_write_back(line_address, static_cast<uint32_t>(attachment), write, evicted)) {
      ++traffic_.cache_hits;
      return;
    }
    ++traffic_.cache_misses;
    if (evicted.happened) traffic_.attachments[evicted.owner].bytes_written += line_bytes_;
    // Write-allocate with fill: the whole line is read, also for a write (see the rules above).
    traffic_.attachments[attachment].bytes_read += line_bytes_;
  }

  void flush() {
    cache_.flush([&](uint32_t owner) { traffic_.attachments[owner].bytes_written += line_bytes_; });
  }

 private:
  uint64_t line_bytes_;
  SetAssociativeCache cache_;
  ImrTraffic& traffic_;
};

struct AttachmentLayout {
  uint64_t base_bytes = 0;
  uint64_t sample_bytes = 0;  // bytes_per_pixel of the format
};

class FragmentReplay {
 public:
  FragmentReplay(const PassMemoryDesc& pass, const RenderTargetCacheConfig& config,
                 ImrTraffic& traffic)
      : pass_(pass), line_bytes_(config.line_bytes), cache_(config, traffic) {
    uint64_t next_base = 0;
    for (const AttachmentMemory& d : pass.attachments) {
      AttachmentLayout layout;
      layout.base_bytes = next_base;
      layout.sample_bytes = static_cast<uint64_t>(bytes_per_pixel(d.format));
      const uint64_t size = uint64_t(pass.width_px) * pass.height_px * pass.samples * layout.sample_bytes;
      next_base += (size + line_bytes_ - 1) / line_bytes_ * line_bytes_;
      layouts_.push_back(layout);
    }
  }

  void replay(const FragmentAccess& f) {
    if (f.x_px >= pass_.width_px || f.y_px >= pass_.height_px ||
        f.subpass >= pass_.subpass_color_outputs.size()) {
      throw Error("IMR model, pass '" + pass_.name + "': fragment at (" + std::to_string(f.x_px) +
                  ", " + std::to_string(f.y_px) + ") of subpass " + std::to_string(f.subpass) +
                  " lies outside the pass");
    }
    const int depth = pass_.depth_index;
    if (depth >= 0 && (f.flags & kDepthRead)) touch(depth, f, f.covered_samples, false);
    if (depth >= 0 && (f.flags & kDepthWritten)) touch(depth, f, f.written_samples, true);
    if (f.flags & kColorWritten) {
      for (int a : pass_.subpass_color_outputs[f.subpass]) {
        if (f.flags & kColorRead) touch(a, f, f.written_samples, false);
        touch(a, f, f.written_samples, true);
      }
    }
  }

  void flush() { cache_.flush(); }

 private:
  // One cache access per distinct line holding the masked samples' bytes. Samples of a pixel
  // are adjacent and visited in increasing address order, so repeats are consecutive.
  void touch(int attachment, const FragmentAccess& f, uint8_t sample_mask, bool write) {
    const AttachmentLayout& layout = layouts_[attachment];
    const uint64_t pixel = uint64_t{f.y_px} * pass_.width_px + f.x_px;
    uint64_t last_line = UINT64_MAX;
    for (int s = 0; s < pass_.samples; ++s) {
      if (!((sample_mask >> s) & 1u)) continue;
      const uint64_t begin =
          layout.base_bytes + (pixel * pass_.samples + s) * layout.sample_bytes;
      const uint64_t first = begin / line_bytes_;
      const uint64_t last = (begin + layout.sample_bytes - 1) / line_bytes_;
      for (uint64_t line = first; line <= last; ++line) {
        if (line == last_line) continue;
        cache_.access(line, attachment, write);
        last_line = line;
      }
    }
  }

  const PassMemoryDesc& pass_;
  uint64_t line_bytes_;
  std::vector<AttachmentLayout> layouts_;
  RenderTargetCache cache_;
};

// k-way merge of the tiles' fragment lists by (triangle_ref, tile index); each pop hands over
// the whole run of one triangle's fragments in one tile.
template <typename Visit>
void merge_in_submission_order(const PassMemoryDesc& pass, const std::vector<TileTrace>& traces,
                               Visit&& visit) {
  using Key = std::pair<uint32_t, size_t>;  // (triangle_ref, tile)
  std::priority_queue<Key, std::vector<Key>, std::greater<Key>> heads;
  std::vector<size_t> cursor(traces.size(), 0);
  for (size_t t = 0; t < traces.size(); ++t) {
    if (!traces[t].fragments.empty()) heads.push({traces[t].fragments.front().triangle_ref, t});
  }
  while (!heads.empty()) {
    const auto [ref, t] = heads.top();
    heads.pop();
    const std::vector<FragmentAccess>& list = traces[t].fragments;
    size_t& i = cursor[t];
    while (i < list.size() && list[i].triangle_ref == ref) visit(list[i++]);
    if (i == list.size()) continue;
    if (list[i].triangle_ref < ref) {
      throw Error("IMR model, pass '" + pass.name + "': tile " + std::to_string(t) +
                  " fragments are not in submission order (triangle " +
                  std::to_string(list[i].triangle_ref) + " after " + std::to_string(ref) + ")");
    }
    heads.push({list[i].triangle_ref, t});
  }
}

}  // namespace

ImrTraffic simulate_imr_pass(const PassMemoryDesc& pass, const std::vector<TileTrace>& traces,
                             const RenderTargetCacheConfig& config) {
  validate_config(config);
  if (pass.subpass_color_outputs.size() > 256) {
    throw Error("IMR model, pass '" + pass.name + "': " + std::to_string(pass.subpass_color_outputs.size()) +
                " subpasses (fragment records hold at most 256)");
  }
  ImrTraffic traffic;
  traffic.attachments.resize(pass.attachments.size());
  const uint64_t pixels = uint64_t(pass.width_px) * pass.height_px;

  for (size_t a = 0; a < pass.attachments.size(); ++a) {
    const AttachmentMemory& d = pass.attachments[a];
    if (d.clears) {
      traffic.attachments[a].bytes_written += pixels * pass.samples * bytes_per_pixel(d.format);
    }
  }

  FragmentReplay replay(pass, config, traffic);
  merge_in_submission_order(pass, traces, [&](const FragmentAccess& f) { replay.replay(f); });
  replay.flush();

  for (size_t a = 0; a < pass.attachments.size(); ++a) {
    const AttachmentMemory& d = pass.attachments[a];
    if (!d.resolves) continue;
    const uint64_t pixel_bytes = pixels * bytes_per_pixel(d.format);
    ImrAttachmentTraffic& t = traffic.attachments[a];
    t.bytes_read += pixel_bytes * pass.samples;
    t.bytes_written += pixel_bytes;
    t.bytes_resolved += pixel_bytes;
  }
  return traffic;
}

}  // namespace ontile
