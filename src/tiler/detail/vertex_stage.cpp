// Per-draw vertex stage of binning (see vertex_stage.h).
#include "tiler/detail/vertex_stage.h"

#include <atomic>
#include <cmath>
#include <string>

#include <tbb/blocked_range.h>

#include "util/error.h"
#include "util/parallel_for.h"

namespace ontile {
namespace {

constexpr uint32_t kVertexGrain = 2048;

}  // namespace

ShadedDraw shade_draw(const DrawCall& draw, const TileGrid& grid, const GuardBand& guard,
                      GeometryCounters& counters, bool idvs) {
  ShadedDraw shaded;
  shaded.varying_count = draw.vertex_shader->varying_count();
  if (shaded.varying_count < 0 || shaded.varying_count > kMaxVaryings) {
    throw Error("vertex shader declares " + std::to_string(shaded.varying_count) +
                " varyings (at most " + std::to_string(kMaxVaryings) + ")");
  }
  const int n = shaded.varying_count;
  // Every element below is written by the loop before anything reads it.
  shaded.positions.resize(draw.vertex_count);
  shaded.varyings.resize(static_cast<size_t>(draw.vertex_count) * n);
  shaded.outcode.resize(draw.vertex_count);
  shaded.snapped.resize(draw.vertex_count);
  shaded.referenced = std::vector<std::atomic<uint8_t>>(draw.vertex_count);  // all 0
  if (idvs) shaded.varyings_written = std::vector<std::atomic<uint8_t>>(draw.vertex_count);
  std::atomic<uint64_t> sanitized{0};
  ontile::parallel_for(tbb::blocked_range<uint32_t>(0, draw.vertex_count, kVertexGrain),
                    [&](const tbb::blocked_range<uint32_t>& r) {
    float* var = shaded.varyings.data() + static_cast<size_t>(r.begin()) * n;
    draw.vertex_shader->shade(r.begin(), r.size(), shaded.positions.data() + r.begin(), var);
    // A NaN/Inf varying would poison every pixel it touches; replace it and count it.
    uint64_t bad = 0;
    for (size_t i = 0; i < r.size() * n; ++i) {
      const bool finite = std::isfinite(var[i]);
      var[i] = finite ? var[i] : 0.0f;
      bad += !finite;
    }
    if (bad) sanitized += bad;
    classify_and_snap(shaded.positions.data() + r.begin(), r.size(), guard, grid.width_px,
                      grid.height_px, grid.subpixel_bits, shaded.outcode.data() + r.begin(),
                      shaded.snapped.data() + r.begin());
  });
  counters.vertices_shaded += draw.vertex_count;
  counters.varyings_sanitized += sanitized.load();
  return shaded;
}

uint64_t count_referenced_vertices(const ShadedDraw& shaded) {
  uint64_t unique = 0;
  for (const std::atomic<uint8_t>& r : shaded.referenced) unique += r.load(std::memory_order_relaxed);
  return unique;
}

uint64_t count_varying_vertices(const ShadedDraw& shaded) {
  uint64_t written = 0;
  for (const std::atomic<uint8_t>& w : shaded.varyings_written) written += w.load(std::memory_order_relaxed);
  return written;
}

}  // namespace ontile
