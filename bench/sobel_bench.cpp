// Micro-benchmark of the screen-space Sobel edge functor alone (no tiler): a synthetic 1280x720
// G-buffer of spheres shaded quad by quad in 16x16-pixel tiles, with and without a texel trace,
// reported as time per pixel (median of repetitions).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "memory/trace_repeats.h"
#include "raster/texel_trace.h"
#include "raster/texture.h"
#include "shaders_cpp/full_screen.h"
#include "shaders_cpp/toon/sobel_edge_shader.h"

namespace ontile {
namespace {

constexpr int kWidthPx = 1280, kHeightPx = 720, kTilePx = 16;
constexpr float kNear = 0.1f, kFar = 100.0f;

struct Sphere {
  float cx_px, cy_px, radius_px, distance;
  glm::vec4 border;
};

// Colour, depth, normal (unorm) and border textures: spheres over a background at depth 1, so
// that, as in a rendered frame, a few percent of pixels are silhouettes or creases.
struct SyntheticGBuffer {
  std::shared_ptr<const Texture2D> color, depth, normal, border;

  SyntheticGBuffer() {
    const Sphere spheres[] = {{300, 360, 200, 5.0f, {0, 0, 0, 1}},
                              {640, 300, 150, 8.0f, {0.2f, 0, 0, 1}},
                              {900, 420, 260, 6.5f, {0, 0, 0, 0}},
                              {1150, 150, 90, 3.0f, {0, 0, 0.3f, 1}}};
    const size_t texels = static_cast<size_t>(kWidthPx) * kHeightPx * 4;
    std::vector<float> c(texels), d(texels), n(texels), b(texels);
    for (int y = 0; y < kHeightPx; ++y) {
      for (int x = 0; x < kWidthPx; ++x) {
        float depth = 1.0f, z_best = 1e30f;
        glm::vec3 normal(0.0f);
        glm::vec4 border(0.0f);
        for (const Sphere& s : spheres) {
          const float dx = (x + 0.5f - s.cx_px) / s.radius_px;
          const float dy = (y + 0.5f - s.cy_px) / s.radius_px;
          const float r2 = dx * dx + dy * dy;
          if (r2 >= 1.0f) continue;
          const float nz = std::sqrt(1.0f - r2);
          const float z = s.distance - nz;  // view distance of the front surface (unit radius)
          if (z >= z_best) continue;
          z_best = z;
          depth = kFar * (z - kNear) / (z * (kFar - kNear));
          normal = {dx, -dy, nz};
          border = s.border;
        }
        const size_t i = (static_cast<size_t>(y) * kWidthPx + x) * 4;
        const glm::vec4 shade(0.2f + 0.6f * normal.z, 0.3f, 0.5f, 1.0f);
        const glm::vec4 encoded = encode_view_normal(normal, NormalEncoding::Unorm);
        for (int k = 0; k < 4; ++k) {
          c[i + k] = shade[k];
          d[i + k] = k == 0 ? depth : 0.0f;
          n[i + k] = encoded[k];
          b[i + k] = border[k];
        }
      }
    }
    color = Texture2D::from_surface_texels(kWidthPx, kHeightPx, std::move(c), 4, "color");
    depth = Texture2D::from_surface_texels(kWidthPx, kHeightPx, std::move(d), 4, "depth");
    normal = Texture2D::from_surface_texels(kWidthPx, kHeightPx, std::move(n), 4, "normal");
    border = Texture2D::from_surface_texels(kWidthPx, kHeightPx, std::move(b), 4, "border");
  }
};

const SyntheticGBuffer& gbuffer() {
  static const SyntheticGBuffer g;
  return g;
}

// Shades the whole frame tile by tile, as the tile executor does; with `traced`, each tile's
// texels go to a trace buffer that is cleared (keeping its capacity) per tile, so the number
// measures the functor and its trace records, not buffer growth.
// Counts the trace entries recorded and the granule accesses they stand for (repeat entries,
// trace_repeats.h, expanded).
void shade_frame(const SobelEdgeShader& shader, bool traced, std::vector<uint64_t>& granules,
                 uint64_t& entries_recorded, uint64_t& granules_recorded) {
  QuadFragment quad;
  quad.lane_mask = 0xF;
  QuadOutput out;
  for (int ty = 0; ty < kHeightPx; ty += kTilePx) {
    for (int tx = 0; tx < kWidthPx; tx += kTilePx) {
      granules.clear();
      const TexelTraceScope scope(traced ? &granules : nullptr);
      for (int y = ty; y < ty + kTilePx; y += 2) {
        for (int x = tx; x < tx + kTilePx; x += 2) {
          quad.x_px = x;
          quad.y_px = y;
          for (int lane = 0; lane < kQuadLanes; ++lane) {
            quad.varyings[FullScreenVertexShader::kUv][lane] = (x + (lane & 1) + 0.5f) / kWidthPx;
            quad.varyings[FullScreenVertexShader::kUv + 1][lane] =
                (y + (lane >> 1) + 0.5f) / kHeightPx;
          }
          shader.shade(quad, out);
          benchmark::DoNotOptimize(out);
        }
      }
      entries_recorded += granules.size();
      granules_recorded += traced_accesses(granules);
    }
  }
}

void BM_SobelEdgeFrame(benchmark::State& state) {
  const SyntheticGBuffer& g = gbuffer();
  SobelEdgeParams p;
  p.color = g.color.get();
  p.depth = g.depth.get();
  p.normal = g.normal.get();
  p.border = g.border.get();
  p.depth_linearization = {false, kNear, kFar};
  p.view_ray_scale = {0.7f, 0.4f};
  const SobelEdgeShader shader(p);
  const bool traced = state.range(0) != 0;
  std::vector<uint64_t> granules;
  uint64_t entries_recorded = 0, granules_recorded = 0;
  for (auto _ : state) shade_frame(shader, traced, granules, entries_recorded, granules_recorded);
  const double pixels = static_cast<double>(kWidthPx) * kHeightPx;
  const double frames = static_cast<double>(state.iterations());
  // Seconds per pixel (printed with an SI prefix: 80n = 80 ns).
  state.counters["s_per_px"] = benchmark::Counter(
      pixels * frames, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["granules_per_px"] = static_cast<double>(granules_recorded) / (pixels * frames);
  state.counters["entries_per_px"] = static_cast<double>(entries_recorded) / (pixels * frames);
}

BENCHMARK(BM_SobelEdgeFrame)->ArgName("traced")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)
    ->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace
}  // namespace ontile
