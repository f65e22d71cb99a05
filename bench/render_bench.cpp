// Frame benchmarks (Google Benchmark): the generated atrium (default size and ~2M triangles)
// and ToyCar at 1920x1080 with the Lambert pipeline, at 1 and 2 threads. Reports the median
// of repeated frames, split into binning (geometry) and tile execution.
#include <benchmark/benchmark.h>

#include "util/heap_tuning.h"

#include "bench_scenes.h"
#include "pipeline_bench.h"
#include "pipelines/kit/render_frame.h"

namespace ontile {
namespace {

const Scene* atrium(double size) { return bench::generated_scene("atrium", size); }
const Scene* shared_asset(const std::string& relative) { return bench::shared_asset(relative); }

void render_benchmark(benchmark::State& state, const Scene* scene) {
  if (!scene) {
    state.SkipWithError("scene not available (../shared/assets missing?)");
    return;
  }
  RenderSettings settings;
  settings.width_px = 1920;
  settings.height_px = 1080;
  settings.context.threads = static_cast<int>(state.range(0));
  double binning_ms = 0.0, tiles_ms = 0.0;
  uint64_t bytes = 0;
  for (auto _ : state) {
    const RenderedFrame frame = render_frame(*scene, settings);
    const FrameReport& r = frame.outputs.report;
    state.SetIterationTime(r.total_ms / 1000.0);
    binning_ms = tiles_ms = 0.0;
    for (const PassReport& p : r.passes) {
      binning_ms += p.binning_ms;
      tiles_ms += p.tiles_ms;
    }
    bytes = r.bytes_read() + r.bytes_written();
  }
  state.counters["binning_ms"] = binning_ms;
  state.counters["tiles_ms"] = tiles_ms;
  state.counters["triangles"] = static_cast<double>(scene->drawn_triangle_count());
  state.counters["traffic_MiB"] = static_cast<double>(bytes) / (1024.0 * 1024.0);
}

void BM_AtriumDefault(benchmark::State& s) { render_benchmark(s, atrium(1.0)); }
void BM_Atrium2M(benchmark::State& s) { render_benchmark(s, atrium(8.0)); }
void BM_ToyCar(benchmark::State& s) { render_benchmark(s, shared_asset("ToyCar/ToyCar.gltf")); }

#define ONTILE_FRAME_BENCH(fn)                                                               \
  BENCHMARK(fn)->Arg(1)->Arg(2)->UseManualTime()->Unit(benchmark::kMillisecond)               \
      ->Iterations(1)->Repetitions(5)->ReportAggregatesOnly(true)

ONTILE_FRAME_BENCH(BM_AtriumDefault);
ONTILE_FRAME_BENCH(BM_Atrium2M);
ONTILE_FRAME_BENCH(BM_ToyCar);

}  // namespace
}  // namespace ontile

// Google Benchmark's main, with freed memory kept in the heap so every iteration runs in the
// steady state (util/heap_tuning.h), and the benchmarks registered at run time (pipeline_bench.cpp).
int main(int argc, char** argv) {
  ontile::keep_freed_memory_in_the_heap();
  ontile::register_pipeline_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
