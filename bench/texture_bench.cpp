// Micro-benchmark of the texture sampler on the shading hot path: 2x2 quads sampling a mipmapped
// sRGB8 texture with trilinear filtering (the Lambert functor's base map), with and without the
// texel trace the texture-cache model replays. Reports time per quad.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "raster/texel_trace.h"
#include "raster/texture.h"

namespace ontile {
namespace {

std::shared_ptr<const Texture2D> checker_texture(int size) {
  std::vector<uint8_t> rgba(static_cast<size_t>(size) * size * 4);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      uint8_t* p = rgba.data() + (static_cast<size_t>(y) * size + x) * 4;
      p[0] = static_cast<uint8_t>(x * 7);
      p[1] = static_cast<uint8_t>(y * 13);
      p[2] = static_cast<uint8_t>((x ^ y) * 3);
      p[3] = 255;
    }
  }
  return Texture2D::from_rgba8(size, size, std::move(rgba), true, "bench");
}

// Quads walking across the texture at ~1.5 texels per pixel (LOD ~0.6: both levels read).
void BM_SampleQuadTrilinear(benchmark::State& state) {
  const auto texture = checker_texture(1024);
  SamplerDesc sampler;  // trilinear, repeat
  const bool traced = state.range(0) != 0;
  std::vector<uint64_t> granules;
  granules.reserve(1 << 20);
  constexpr int kQuads = 4096;
  constexpr float kStep = 1.5f / 1024.0f;
  glm::vec4 out[4];
  float sink = 0.0f;
  for (auto _ : state) {
    granules.clear();
    const TexelTraceScope scope(traced ? &granules : nullptr);
    for (int q = 0; q < kQuads; ++q) {
      const float u = (q % 64) * 2 * kStep, v = (q / 64) * 2 * kStep;
      const glm::vec2 uv[4] = {{u, v}, {u + kStep, v}, {u, v + kStep}, {u + kStep, v + kStep}};
      texture->sample_quad(sampler, uv, out);
      sink += out[0].x + out[3].w;
    }
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations() * kQuads);
  state.counters["ns_per_quad"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * kQuads, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_SampleQuadTrilinear)->Arg(0)->Arg(1)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace
}  // namespace ontile
